#pragma once
// Inputs given to simulate() as a table: rows of time and the nu input values,
// interpolated linearly in time and held beyond the first and last rows. Runs
// without the GIL (the table is copied once).
#include <yamsc/integration.hpp>

#include <vector>

namespace yamsc::python {

/// `rows` x (1 + nu) values, row-major, times increasing. Throws
/// std::invalid_argument for a wrong width, no rows or times not increasing.
runtime::InputFunction table_input(std::vector<double> table, int rows, int nu);

} // namespace yamsc::python
