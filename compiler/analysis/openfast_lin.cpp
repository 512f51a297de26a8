#include "analysis/openfast_lin.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace yamsc::analysis {

namespace {

/// Width of a number (ES24.16E3) and the column of the tables' flags: OpenFAST
/// tabs to 14 + 3 * width + 7, room for the three values of an orientation.
constexpr int width = 24;
constexpr int flag_column = 14 + 3 * width + 7; // 1-based, as Fortran's T edit

std::string right(const std::string& s, std::size_t w) {
    return s.size() >= w ? s : std::string(w - s.size(), ' ') + s;
}

/// Pads `line` with blanks so that the next character lands in 1-based `column`.
void tab_to(std::string& line, int column) {
    const auto at = static_cast<std::size_t>(column - 1);
    if (line.size() < at) line.append(at - line.size(), ' ');
}

/// A header value: '(3x,A,1x,...)' with the label padded to 32 characters.
std::string header_line(const std::string& label, const std::string& value) {
    std::string line = "   " + label;
    line.append(label.size() < 32 ? 32 - label.size() : 0, ' ');
    return line + " " + value + "\n";
}

std::string table(const std::vector<LinChannel>& rows, const std::string& row_col) {
    std::string head = "   " + right(row_col, 10) + " Operating Point";
    tab_to(head, flag_column);
    std::string rule = "   ---------- ---------------";
    tab_to(rule, flag_column);
    std::string out = head + "Rotating Frame? Derivative Order Description\n" + rule +
                      "--------------- ---------------- -----------\n";
    char index[32], order[32];
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const LinChannel& c = rows[i];
        std::snprintf(index, sizeof index, "%8zu", i + 1);
        std::snprintf(order, sizeof order, "%8d", c.derivative_order);
        std::string line = std::string("   ") + index + "   " + fortran_es(c.op);
        tab_to(line, flag_column);
        line += std::string(7, ' ') + (c.rotating ? "T" : "F") + std::string(8, ' ') + order +
                std::string(9, ' ') + c.description + "\n";
        out += line;
    }
    return out + "\n";
}

void matrix(std::string& out, const char* name, const LinMatrix& m, std::size_t rows,
            std::size_t cols) {
    if (rows == 0 || cols == 0) return; // OpenFAST writes no empty matrix
    if (static_cast<std::size_t>(m.rows) != rows || static_cast<std::size_t>(m.cols) != cols ||
        m.data.size() != rows * cols)
        throw std::invalid_argument(std::string("lin file: matrix ") + name +
                                    " does not match the tables");
    out += std::string(name) + ": " + std::to_string(rows) + " x " + std::to_string(cols) + "\n";
    for (std::size_t i = 0; i < rows; ++i) {
        std::string line = "  ";
        for (std::size_t j = 0; j < cols; ++j) line += " " + fortran_es(m.data[i * cols + j]);
        out += line + "\n";
    }
}

} // namespace

std::string fortran_es(double v) {
    if (std::isnan(v)) return right("NaN", width);
    if (std::isinf(v)) return right(v > 0 ? "Infinity" : "-Infinity", width);
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.16E", v);
    std::string s = buf;
    const auto e = s.find('E');
    const int exponent = std::atoi(s.c_str() + e + 1);
    std::snprintf(buf, sizeof buf, "E%c%03d", exponent < 0 ? '-' : '+', std::abs(exponent));
    return right(s.substr(0, e) + buf, width);
}

std::string format_lin_file(const LinFile& f) {
    std::string out = "\nLinearized model: " + f.origin + "\n";
    out += " " + f.linked + "\n\n";
    out += "Description from the FAST input file: " + f.description + "\n\n";
    out += "Simulation information:\n";
    out += header_line("Simulation time:", fortran_es(f.time) + " s");
    out += header_line("Rotor Speed:", fortran_es(f.rotor_speed) + " rad/s");
    out += header_line("Azimuth:", fortran_es(f.azimuth) + " rad");
    out += header_line("Wind Speed:", fortran_es(f.wind_speed) + " m/s");
    char n[32];
    auto count = [&](const char* label, std::size_t v) {
        std::snprintf(n, sizeof n, "%5zu", v);
        out += header_line(label, n);
    };
    count("Number of continuous states:", f.x.size());
    count("Number of discrete states:", 0);
    count("Number of constraint states:", 0);
    count("Number of inputs:", f.u.size());
    count("Number of outputs:", f.y.size());
    out += header_line("Jacobians included in this file?", "   No");
    out += "\n";
    if (f.xdot.size() != f.x.size())
        throw std::invalid_argument("lin file: x and its derivative differ in size");
    if (!f.x.empty()) {
        out += "Order of continuous states:\n" + table(f.x, "Row/Column");
        out += "Order of continuous state derivatives:\n" + table(f.xdot, "Row/Column");
    }
    if (!f.u.empty()) out += "Order of inputs:\n" + table(f.u, "Column  ");
    if (!f.y.empty()) out += "Order of outputs:\n" + table(f.y, "Row  ");
    out += "\nLinearized state matrices:\n\n";
    matrix(out, "A", f.A, f.x.size(), f.x.size());
    matrix(out, "B", f.B, f.x.size(), f.u.size());
    matrix(out, "C", f.C, f.y.size(), f.x.size());
    matrix(out, "D", f.D, f.y.size(), f.u.size());
    return out;
}

} // namespace yamsc::analysis
