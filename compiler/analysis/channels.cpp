// OpenFAST channel names and units, and tables of simulation columns.
#include "analysis/channels.hpp"

#include "diag/diagnostics.hpp"
#include "driver/bindings.hpp"

#include <yamsc/atomic_file.hpp>
#include <yamsc/csv.hpp>

#include <algorithm>
#include <cmath>

namespace yamsc::analysis {

using diag::UserError;

int Table::find(std::string_view name) const {
    for (std::size_t i = 0; i < columns.size(); ++i)
        if (columns[i] == name) return static_cast<int>(i);
    return -1;
}

std::string csv_field(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string out = "\"";
    for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

Table table_of(const runtime::SimulationResult& result) {
    Table t;
    t.columns = result.columns;
    t.data.assign(result.column_count(), std::vector<double>(result.rows()));
    for (std::size_t row = 0; row < result.rows(); ++row)
        for (std::size_t j = 0; j < result.column_count(); ++j)
            t.data[j][row] = result.value(row, j);
    return t;
}

const std::vector<OpenFastChannel>& openfast_channels() {
    // ElastoDyn's DOF, displacement and load channels and ServoDyn's generator channels
    // (OpenFAST's OutListParameters), in their units.
    static const std::vector<OpenFastChannel> channels{
        {"PtfmSurge", "m", false},
        {"PtfmSway", "m", false},
        {"PtfmHeave", "m", false},
        {"PtfmRoll", "deg", false},
        {"PtfmPitch", "deg", false},
        {"PtfmYaw", "deg", false},
        {"PtfmTVxi", "m/s", false},
        {"PtfmTVyi", "m/s", false},
        {"PtfmTVzi", "m/s", false},
        {"PtfmRVxi", "deg/s", false},
        {"PtfmRVyi", "deg/s", false},
        {"PtfmRVzi", "deg/s", false},
        {"Q_TFA1", "m", false},
        {"Q_TSS1", "m", false},
        {"Q_TFA2", "m", false},
        {"Q_TSS2", "m", false},
        {"QD_TFA1", "m/s", false},
        {"QD_TSS1", "m/s", false},
        {"QD_TFA2", "m/s", false},
        {"QD_TSS2", "m/s", false},
        {"Q_Yaw", "rad", false},
        {"QD_Yaw", "rad/s", false},
        {"NacYaw", "deg", false},
        {"YawPzn", "deg", false},
        {"Q_GeAz", "rad", false},
        {"QD_GeAz", "rad/s", false},
        {"Q_DrTr", "rad", false},
        {"QD_DrTr", "rad/s", false},
        {"Azimuth", "deg", true},
        {"RotSpeed", "rpm", false},
        {"GenSpeed", "rpm", false},
        {"Q_BF1", "m", false},
        {"Q_BF2", "m", false},
        {"Q_BE1", "m", false},
        {"Q_B1F1", "m", false},
        {"Q_B1F2", "m", false},
        {"Q_B1E1", "m", false},
        {"Q_B2F1", "m", false},
        {"Q_B2F2", "m", false},
        {"Q_B2E1", "m", false},
        {"Q_B3F1", "m", false},
        {"Q_B3F2", "m", false},
        {"Q_B3E1", "m", false},
        {"QD_B1F1", "m/s", false},
        {"QD_B1F2", "m/s", false},
        {"QD_B1E1", "m/s", false},
        {"QD_B2F1", "m/s", false},
        {"QD_B2F2", "m/s", false},
        {"QD_B2E1", "m/s", false},
        {"QD_B3F1", "m/s", false},
        {"QD_B3F2", "m/s", false},
        {"QD_B3E1", "m/s", false},
        {"BldPitch1", "deg", false},
        {"BldPitch2", "deg", false},
        {"BldPitch3", "deg", false},
        {"BlPitch1", "deg", false}, // ElastoDyn's aliases of BldPitch1 ..
        {"BlPitch2", "deg", false},
        {"BlPitch3", "deg", false},
        {"TTDspFA", "m", false},
        {"TTDspSS", "m", false},
        {"OoPDefl1", "m", false},
        {"OoPDefl2", "m", false},
        {"OoPDefl3", "m", false},
        {"IPDefl1", "m", false},
        {"IPDefl2", "m", false},
        {"IPDefl3", "m", false},
        {"TipDzc1", "m", false},
        {"TipDzc2", "m", false},
        {"TipDzc3", "m", false},
        // ElastoDyn's load channels (models written by `yamsc from-openfast` have them).
        {"TwrBsMxt", "kN-m", false},
        {"TwrBsMyt", "kN-m", false},
        {"TwrBsMzt", "kN-m", false},
        {"YawBrMxp", "kN-m", false},
        {"YawBrMyp", "kN-m", false},
        {"RootMxc1", "kN-m", false},
        {"RootMyc1", "kN-m", false},
        {"RootMzc1", "kN-m", false},
        {"RootMxb1", "kN-m", false},
        {"RootMyb1", "kN-m", false},
        {"LSShftMxa", "kN-m", false},
        {"LSSGagMya", "kN-m", false},
        {"LSSGagMza", "kN-m", false},
        {"RotThrust", "kN", false},
        {"RotTorq", "kN-m", false},
        // ServoDyn's generator channels: GenTq the generator torque, GenPwr the
        // electrical power (GenTq GenSpeed GenEff while generating).
        {"GenTq", "kN-m", false},
        {"GenPwr", "kW", false}};
    return channels;
}

const OpenFastChannel* openfast_channel(std::string_view name) {
    for (const OpenFastChannel& c : openfast_channels())
        if (name == c.name) return &c;
    for (const OpenFastChannel& c : aerodyn_channels())
        if (name == c.name) return &c;
    return nullptr;
}

std::vector<OpenFastColumn> openfast_columns(const runtime::SimulationResult& result,
                                             int first_output_column) {
    std::vector<OpenFastColumn> out;
    const auto first = static_cast<std::size_t>(first_output_column);
    for (std::size_t j = first; j < result.columns.size(); ++j)
        if (const OpenFastChannel* c = openfast_channel(result.columns[j]))
            out.push_back({std::string(c->name) + "_[" + c->unit + "]", j - first, c->wrap_360});
    if (out.empty())
        throw UserError("--channels openfast: the model has no output named as an OpenFAST "
                        "channel (Q_TFA1, PtfmPitch, Azimuth, ...; models written by `yamsc "
                        "from-openfast` have them)");
    return out;
}

namespace {

double openfast_value(const OpenFastColumn& c, const double* outputs) {
    double v = outputs[c.output];
    if (c.wrap_360) {
        v = std::fmod(v, 360.0);
        if (v < 0) v += 360.0;
    }
    return v;
}

} // namespace

Table openfast_table(const runtime::SimulationResult& result, int first_output_column) {
    const std::vector<OpenFastColumn> columns = openfast_columns(result, first_output_column);
    Table t;
    t.columns.push_back("Time_[s]");
    t.data.push_back(result.time);
    for (const OpenFastColumn& c : columns) {
        t.columns.push_back(c.name);
        std::vector<double> values(result.rows());
        for (std::size_t row = 0; row < result.rows(); ++row)
            values[row] = openfast_value(c, result.output_row(row));
        t.data.push_back(std::move(values));
    }
    return t;
}

void write_openfast_csv(const runtime::SimulationResult& result, int first_output_column,
                        const std::string& path) {
    const std::vector<OpenFastColumn> columns = openfast_columns(result, first_output_column);
    runtime::write_file_atomically(path, [&](std::ostream& out) {
        out << "Time_[s]";
        for (const OpenFastColumn& c : columns) out << ',' << c.name;
        out << '\n';
        // Row by row from the stored arrays: no table of the columns in between.
        runtime::CsvBuffer text(out);
        for (std::size_t row = 0; row < result.rows(); ++row) {
            text.value(result.time[row]);
            const double* outputs = result.output_row(row);
            for (const OpenFastColumn& c : columns) text.value(openfast_value(c, outputs), ',');
            text.end_line();
        }
    });
}

std::string base_name(const std::string& column) {
    const auto cut = column.find("_[");
    return cut == std::string::npos ? column : column.substr(0, cut);
}

Table select_columns(const Table& table, const std::vector<std::string>& names) {
    if (names.empty()) return table;
    Table t;
    t.columns.push_back(table.columns.front());
    t.data.push_back(table.data.front());
    for (const std::string& name : names) {
        int found = table.find(name);
        for (std::size_t j = 1; found < 0 && j < table.columns.size(); ++j)
            if (base_name(table.columns[j]) == name) found = static_cast<int>(j);
        if (found < 1) {
            std::vector<std::string> candidates;
            for (std::size_t j = 1; j < table.columns.size(); ++j)
                candidates.push_back(base_name(table.columns[j]));
            throw UserError("unknown channel '" + name + "'" +
                            diag::did_you_mean(name, candidates));
        }
        t.columns.push_back(table.columns[static_cast<std::size_t>(found)]);
        t.data.push_back(table.data[static_cast<std::size_t>(found)]);
    }
    return t;
}

void write_table_csv(const Table& table, std::ostream& out) {
    for (std::size_t j = 0; j < table.columns.size(); ++j)
        out << (j ? "," : "") << table.columns[j];
    out << '\n';
    runtime::CsvBuffer text(out);
    for (std::size_t row = 0; row < table.rows(); ++row) {
        for (std::size_t j = 0; j < table.columns.size(); ++j)
            text.value(table.data[j][row], j ? ',' : 0);
        text.end_line();
    }
}

void write_table_csv(const Table& table, const std::string& path) {
    runtime::write_file_atomically(path, [&](std::ostream& out) { write_table_csv(table, out); });
}

} // namespace yamsc::analysis
