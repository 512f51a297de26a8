#pragma once
// Tables of numbers with named columns, as time series are written: CSV (`,` or `;`)
// or whitespace/tab separated, with a row of column names (`Time_[s]` or `Time`,
// optionally followed by a row of units in parentheses, as in OpenFAST `.out` files:
// names become `NAME_[unit]`). Lines before the names (an OpenFAST header) are
// skipped. Column 0 must be time, strictly rising; every row holds one number per
// column (Fortran `D` exponents accepted, no NaN or infinity).
#include <string>
#include <vector>

namespace yamsc::table {

struct Table {
    std::vector<std::string> columns;
    std::vector<std::vector<double>> data; // data[column][row]
};

/// Throws diag::UserError with the file and line on bad input.
Table read_table(const std::string& path);

/// An OpenFAST binary file when the name ends in `.outb` (openfast_binary.hpp),
/// else a text table as read_table reads it.
Table read_time_series(const std::string& path);

} // namespace yamsc::table
