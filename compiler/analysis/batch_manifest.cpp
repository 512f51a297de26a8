#include "analysis/batch_manifest.hpp"

#include "diag/diagnostics.hpp"
#include "diag/errors.hpp"
#include "driver/values.hpp"

#include <yamsc/wind.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace yamsc::analysis {

using driver::Assignment;
using driver::parse_assignments;
using driver::parse_value;
using driver::SimMethod;

namespace {

const std::vector<std::string> plain_columns{"id",         "model",
                                             "tmax",       "dt",
                                             "method",     "rtol",
                                             "atol",       "set",
                                             "ic",         "u",
                                             "wind",       "aero",
                                             "dt_out",     "channels",
                                             "controller", "controller_input",
                                             "coupling",   "interp_order",
                                             "time_limit", "mooring",
                                             "hydro",      "sea_state"};
const std::vector<std::string> required_columns{"id", "model", "tmax", "dt"};
const std::vector<std::string> prefixes{"set:", "ic:", "u:"};

bool is_blank(char c) {
    return c == ' ' || c == '\t' || c == '\r';
}

/// Splits one line into fields (RFC 4180 quoting within the line). `error`
/// is set on an open quote or text after a closing quote.
std::vector<ManifestField> split_line(const std::string& line, int line_no, std::string& error) {
    std::vector<ManifestField> fields;
    std::size_t i = 0;
    while (true) {
        ManifestField f;
        f.line = line_no;
        while (i < line.size() && is_blank(line[i])) ++i;
        f.col = static_cast<int>(i) + 1;
        if (i < line.size() && line[i] == '"') {
            ++i;
            f.col = static_cast<int>(i) + 1;
            bool closed = false;
            while (i < line.size()) {
                if (line[i] == '"') {
                    if (i + 1 < line.size() && line[i + 1] == '"') {
                        f.text += '"';
                        i += 2;
                        continue;
                    }
                    closed = true;
                    ++i;
                    break;
                }
                f.text += line[i++];
            }
            if (!closed) {
                error = "col " + std::to_string(f.col - 1) + ": the quoted field is not closed";
                return fields;
            }
            while (i < line.size() && is_blank(line[i])) ++i;
            if (i < line.size() && line[i] != ',') {
                error = "col " + std::to_string(i + 1) + ": text after a closing quote";
                return fields;
            }
        } else {
            const std::size_t comma = std::min(line.find(',', i), line.size());
            f.text = line.substr(i, comma - i);
            while (!f.text.empty() && is_blank(f.text.back())) f.text.pop_back();
            i = comma;
        }
        fields.push_back(f);
        if (i >= line.size()) break;
        ++i; // the comma
    }
    return fields;
}

bool known_column(const std::string& name) {
    if (std::find(plain_columns.begin(), plain_columns.end(), name) != plain_columns.end())
        return true;
    for (const std::string& p : prefixes)
        if (name.size() > p.size() && name.compare(0, p.size(), p) == 0) return true;
    return false;
}

bool valid_id(const std::string& id) {
    if (id.empty() || id.size() > 128 || id[0] == '.' || id[0] == '-') return false;
    return std::all_of(id.begin(), id.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.' ||
               c == '+';
    });
}

std::string resolved(const Manifest& m, const std::string& path) {
    return path.empty() || path[0] == '/' || m.folder.empty() ? path : m.folder + "/" + path;
}

bool readable(const std::string& path) {
    return ::access(path.c_str(), R_OK) == 0;
}

/// The name as assigned (with its primes), e.g. psi'.
std::string channel(const Assignment& a) {
    return a.name + std::string(static_cast<std::size_t>(a.primes), '\'');
}

/// The checks `yamsc sim` makes of its options together (cli/commands/sim.cpp),
/// located at the row or the field concerned.
void check_combination(const BatchCase& c) {
    const driver::SimOptions& o = c.sim;
    if (!o.controller_input.empty() && o.controller.empty())
        throw CaseError(c.row_at, "controller_input needs controller");
    if (!o.controller.empty() && o.method == SimMethod::cvode)
        throw CaseError(c.row_at, "controller runs with rk4 or abm4");
    if (o.coupling == driver::SimCoupling::loose && o.method == SimMethod::cvode)
        throw CaseError(c.coupling_at, "coupling loose steps with rk4 or abm4 (cvode couples "
                                       "tightly)");
    if (!c.interp_order_at.empty() && o.coupling != driver::SimCoupling::loose)
        throw CaseError(c.interp_order_at, "interp_order needs coupling loose");
    if (o.dt_out != 0) {
        // As runtime::output_stride checks it.
        const double steps = o.dt_out / o.dt;
        if (!(o.dt_out > 0) || std::round(steps) < 1 ||
            std::fabs(steps - std::round(steps)) > 1e-9 * std::round(steps))
            throw CaseError(c.dt_out_at, "dt_out must be a positive multiple of dt");
    }
}

} // namespace

std::string Manifest::where(int line, int col) const {
    return path + ":" + std::to_string(line) + ":" + std::to_string(col);
}

const ManifestField* Manifest::field(const ManifestRow& row, const std::string& column) const {
    for (std::size_t i = 0; i < columns.size() && i < row.fields.size(); ++i)
        if (columns[i] == column) return &row.fields[i];
    return nullptr;
}

Manifest read_manifest(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw diag::UserError("cannot read the manifest '" + path + "'");
    Manifest m;
    m.path = path;
    const auto slash = path.find_last_of('/');
    m.folder = slash == std::string::npos ? "" : path.substr(0, slash == 0 ? 1 : slash);
    std::string line;
    int line_no = 0;
    bool header = true;
    while (std::getline(in, line)) {
        ++line_no;
        const std::size_t first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#') continue; // blank or comment
        std::string error;
        std::vector<ManifestField> fields = split_line(line, line_no, error);
        if (header) {
            if (!error.empty())
                throw diag::UserError(m.where(line_no, 1) + ": error: the header: " + error);
            for (const ManifestField& f : fields) {
                if (!known_column(f.text))
                    throw diag::UserError(m.where(line_no, f.col) + ": error: unknown column '" +
                                          f.text + "'" + diag::did_you_mean(f.text, plain_columns) +
                                          " (columns: id, model, tmax, dt, method, rtol, atol, "
                                          "set, ic, u, wind, aero, dt_out, channels, "
                                          "controller, controller_input, coupling, "
                                          "interp_order, time_limit, mooring, hydro, "
                                          "sea_state, set:NAME, ic:NAME, u:NAME)");
                if (std::find(m.columns.begin(), m.columns.end(), f.text) != m.columns.end())
                    throw diag::UserError(m.where(line_no, f.col) + ": error: column '" + f.text +
                                          "' is given twice");
                m.columns.push_back(f.text);
            }
            for (const std::string& c : required_columns)
                if (std::find(m.columns.begin(), m.columns.end(), c) == m.columns.end())
                    throw diag::UserError(m.where(line_no, 1) +
                                          ": error: the manifest has no column '" + c +
                                          "' (required: id, model, tmax, dt)");
            header = false;
            continue;
        }
        ManifestRow row;
        row.index = static_cast<int>(m.rows.size());
        row.line = line_no;
        row.fields = std::move(fields);
        if (!error.empty()) {
            const int col = std::stoi(error.substr(4));
            row.error = m.where(line_no, col) + ": error:" + error.substr(error.find(':') + 1);
        } else if (row.fields.size() != m.columns.size()) {
            row.error = m.where(line_no, 1) + ": error: " + std::to_string(row.fields.size()) +
                        " fields, the header has " + std::to_string(m.columns.size());
        }
        m.rows.push_back(std::move(row));
    }
    if (header) throw diag::UserError(path + ": error: the manifest has no header row");
    return m;
}

BatchCase case_of(const Manifest& m, const ManifestRow& row) {
    if (!row.error.empty()) throw std::runtime_error(row.error);
    BatchCase c;
    c.row_at = m.where(row.line, 1);
    auto at = [&](const ManifestField& f, std::size_t offset = 0) {
        return m.where(f.line, f.col + static_cast<int>(offset));
    };
    auto number = [&](const ManifestField& f, const std::string& what) {
        try {
            return parse_value(f.text, what);
        } catch (const std::exception& e) {
            throw CaseError(at(f), e.what());
        }
    };
    // name=value lists: each name located at its place in the field.
    auto assignments = [&](const ManifestField& f, const std::string& what,
                           std::vector<Assignment>& to, std::map<std::string, std::string>& where) {
        std::vector<Assignment> given;
        try {
            given = parse_assignments(f.text, what);
        } catch (const std::exception& e) {
            throw CaseError(at(f), e.what());
        }
        std::size_t from = 0;
        for (const Assignment& a : given) {
            const std::size_t pos = f.text.find(a.name, from);
            where[channel(a)] = at(f, pos == std::string::npos ? 0 : pos);
            if (pos != std::string::npos) from = pos + a.name.size();
            to.push_back(a);
        }
    };
    for (std::size_t i = 0; i < m.columns.size(); ++i) {
        const std::string& column = m.columns[i];
        const ManifestField& f = row.fields[i];
        // The time limit decides whether a case may finish, not what it computes.
        if (!f.text.empty() && column != "time_limit") c.text += column + "=" + f.text + "\n";
        if (column == "id") {
            if (!valid_id(f.text))
                throw CaseError(at(f), "the id '" + f.text +
                                           "' is not a file name: use letters, digits, _ - . + "
                                           "(not first: . -)");
            if (f.text == "summary" || f.text.rfind("summary-", 0) == 0)
                throw CaseError(at(f), "the id '" + f.text +
                                           "' would name the summary's file (summary.csv, "
                                           "summary-k-of-N.csv)");
            c.id = f.text;
        } else if (column == "model") {
            if (f.text.empty()) throw CaseError(at(f), "no model given");
            c.sim.model = resolved(m, f.text);
            c.model_at = at(f);
            if (!readable(c.sim.model))
                throw CaseError(at(f), "cannot read the model '" + c.sim.model + "'");
        } else if (column == "tmax" || column == "dt") {
            const double v = number(f, column);
            if (!(v > 0)) throw CaseError(at(f), column + " must be positive");
            (column == "tmax" ? c.sim.tmax : c.sim.dt) = v;
        } else if (column == "rtol" || column == "atol") {
            if (!f.text.empty()) (column == "rtol" ? c.sim.rtol : c.sim.atol) = number(f, column);
        } else if (column == "method") {
            if (f.text == "cvode")
                c.sim.method = SimMethod::cvode;
            else if (f.text == "abm4")
                c.sim.method = SimMethod::abm4;
            else if (!f.text.empty() && f.text != "rk4")
                throw CaseError(at(f), "method must be rk4, abm4 or cvode, not '" + f.text + "'");
        } else if (column == "aero") {
            if (!f.text.empty()) {
                c.sim.aero = resolved(m, f.text);
                if (!readable(c.sim.aero))
                    throw CaseError(at(f), "cannot read the rotor table '" + c.sim.aero + "'");
                c.files.push_back(c.sim.aero);
            }
        } else if (column == "mooring" || column == "hydro" || column == "sea_state") {
            // The platform's files (--mooring, --hydro, --sea-state).
            if (!f.text.empty()) {
                std::string& file = column == "mooring" ? c.sim.mooring
                                    : column == "hydro" ? c.sim.hydro
                                                        : c.sim.sea_state;
                file = resolved(m, f.text);
                if (!readable(file))
                    throw CaseError(at(f), "cannot read the " + column + " file '" + file + "'");
                c.files.push_back(file);
            }
        } else if (column == "controller" || column == "controller_input") {
            if (!f.text.empty()) {
                // A path, never a bare name: dlopen would search the library path for one.
                std::string path = resolved(m, f.text);
                if (path.find('/') == std::string::npos) path = "./" + path;
                if (!readable(path))
                    throw CaseError(at(f), "cannot read the " +
                                               std::string(column == "controller"
                                                               ? "controller library"
                                                               : "controller's input file") +
                                               " '" + path + "'");
                (column == "controller" ? c.sim.controller : c.sim.controller_input) = path;
                c.files.push_back(path);
            }
        } else if (column == "dt_out") {
            if (!f.text.empty()) {
                c.sim.dt_out = number(f, column);
                c.dt_out_at = at(f);
            }
        } else if (column == "time_limit") {
            if (!f.text.empty()) {
                c.time_limit = number(f, column);
                if (!(c.time_limit > 0)) throw CaseError(at(f), "time_limit must be positive [s]");
            }
        } else if (column == "channels") {
            if (f.text == "openfast")
                c.sim.channels = driver::Channels::openfast;
            else if (!f.text.empty() && f.text != "all")
                throw CaseError(at(f), "channels must be all or openfast, not '" + f.text + "'");
        } else if (column == "coupling") {
            c.coupling_at = at(f);
            if (f.text == "loose")
                c.sim.coupling = driver::SimCoupling::loose;
            else if (!f.text.empty() && f.text != "tight")
                throw CaseError(at(f), "coupling must be tight or loose, not '" + f.text + "'");
        } else if (column == "interp_order") {
            if (!f.text.empty()) {
                const double v = number(f, column);
                if (v != 0 && v != 1 && v != 2)
                    throw CaseError(at(f), "interp_order must be 0, 1 or 2");
                c.sim.interp_order = static_cast<int>(v);
                c.interp_order_at = at(f);
            }
        } else if (column == "wind") {
            c.sim.wind = f.text;
            bool number_or_step = f.text.rfind("step:", 0) == 0;
            try {
                if (!number_or_step && !f.text.empty()) parse_value(f.text, "wind");
                number_or_step = true;
            } catch (const std::exception&) {
            }
            if (!number_or_step) {
                c.sim.wind = resolved(m, f.text);
                if (!readable(c.sim.wind))
                    throw CaseError(at(f), "cannot read the wind file '" + c.sim.wind + "'");
                c.files.push_back(c.sim.wind);
                // An InflowWind file's uniform wind file is an input too (a bad
                // file is the case's error when it runs).
                try {
                    const std::vector<std::string> read = runtime::open_wind(c.sim.wind).files;
                    c.files.insert(c.files.end(), read.begin() + 1, read.end());
                } catch (const std::exception&) {
                }
            }
        } else if (f.text.empty()) {
            continue; // an optional value not given for this case
        } else if (column == "set") {
            assignments(f, "set", c.sim.set, c.set_at);
        } else if (column == "ic") {
            assignments(f, "ic", c.sim.ic, c.ic_at);
        } else if (column == "u") {
            assignments(f, "u", c.sim.u, c.u_at);
        } else { // set:NAME, ic:NAME, u:NAME: one value
            const std::string kind = column.substr(0, column.find(':'));
            const std::string name = column.substr(kind.size() + 1);
            std::vector<Assignment>& to = kind == "set"  ? c.sim.set
                                          : kind == "ic" ? c.sim.ic
                                                         : c.sim.u;
            std::map<std::string, std::string>& where = kind == "set"  ? c.set_at
                                                        : kind == "ic" ? c.ic_at
                                                                       : c.u_at;
            std::vector<Assignment> one;
            try {
                one = parse_assignments(name + "=" + f.text, column);
            } catch (const std::exception& e) {
                throw CaseError(at(f), e.what());
            }
            where[channel(one.front())] = at(f);
            to.push_back(one.front());
        }
    }
    check_combination(c);
    return c;
}

} // namespace yamsc::analysis
