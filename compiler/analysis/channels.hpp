#pragma once
// Columns of a simulation as a table, and the OpenFAST naming of its channels.
//
// A model marks which of its quantities are OpenFAST channels by declaring
// outputs named as the channels, in OpenFAST's sign convention and units
// (`output Q_TSS1 = -q_ss1`, `output PtfmPitch = pitch * 180 / pi`): this is what
// `yamsc from-openfast` writes. `--channels openfast` then writes `Time_[s]` and
// one column `NAME_[unit]` per such output, the unit from OpenFAST's channel list
// (docs/openfast.md), with the azimuth wrapped to [0, 360) deg as OpenFAST does.
#include <yamsc/simulation.hpp>

#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace yamsc::analysis {

/// Named columns of equal length; column 0 is time.
struct Table {
    std::vector<std::string> columns;
    std::vector<std::vector<double>> data; // data[column][row]

    std::size_t rows() const { return data.empty() ? 0 : data.front().size(); }
    /// Index of the column named `name`, or -1.
    int find(std::string_view name) const;
};

/// Every column of a run as `yamsc sim` writes it: time, DOFs, rates, outputs.
Table table_of(const runtime::SimulationResult& result);

/// A text field of a CSV row: as it is, or quoted (RFC 4180) when it holds a
/// comma, a quote or a line break.
std::string csv_field(const std::string& s);

/// An OpenFAST output channel that a model can provide.
struct OpenFastChannel {
    const char* name;
    const char* unit;
    bool wrap_360; // an angle OpenFAST reports modulo 360 deg
};

/// The channel named `name` (case-sensitive, as OpenFAST writes it), or null.
const OpenFastChannel* openfast_channel(std::string_view name);
/// All channels yamsc knows, for documentation and messages.
const std::vector<OpenFastChannel>& openfast_channels();
/// Those of them AeroDyn writes (aerodyn_channels.cpp).
const std::vector<OpenFastChannel>& aerodyn_channels();

/// An output named as an OpenFAST channel: `NAME_[unit]`, its index among the
/// outputs, and whether it is an angle OpenFAST writes in [0, 360).
struct OpenFastColumn {
    std::string name;
    std::size_t output = 0;
    bool wrap_360 = false;
};

/// The outputs named as OpenFAST channels, in the result's order. Throws
/// UserError when the model has none (it was not made for OpenFAST).
std::vector<OpenFastColumn> openfast_columns(const runtime::SimulationResult& result,
                                             int first_output_column);

/// `Time_[s]` and the outputs named as OpenFAST channels (openfast_columns).
Table openfast_table(const runtime::SimulationResult& result, int first_output_column);

/// The same columns written straight from the result as CSV (atomically), with
/// no table in between: the same bytes as write_table_csv(openfast_table(..)).
void write_openfast_csv(const runtime::SimulationResult& result, int first_output_column,
                        const std::string& path);

/// The columns with these names (or base names before `_[`); all when `names` is
/// empty. Throws UserError naming an unknown channel.
Table select_columns(const Table& table, const std::vector<std::string>& names);

/// The name without its unit suffix: `Q_TFA1_[m]` -> `Q_TFA1`.
std::string base_name(const std::string& column);

void write_table_csv(const Table& table, std::ostream& out);
/// Writes atomically; throws std::runtime_error on failure.
void write_table_csv(const Table& table, const std::string& path);

} // namespace yamsc::analysis
