#include "analysis/linear_report.hpp"

#include "driver/json.hpp"

#include <cmath>
#include <cstdio>

namespace yamsc::analysis {

std::vector<std::vector<double>> matrix_rows(const std::vector<double>& m, int nrow, int ncol) {
    std::vector<std::vector<double>> out(static_cast<std::size_t>(nrow));
    for (int i = 0; i < nrow; ++i)
        for (int j = 0; j < ncol; ++j)
            out[static_cast<std::size_t>(i)].push_back(m[static_cast<std::size_t>(i * ncol + j)]);
    return out;
}

std::string format_mode_table(const std::vector<std::string>& dofs,
                              const std::vector<runtime::Mode>& modes) {
    std::string out = "mode  frequency [Hz]  damping ratio  shape (largest DOF)\n";
    char line[160];
    for (std::size_t i = 0; i < modes.size(); ++i) {
        const auto& m = modes[i];
        std::size_t big = 0;
        for (std::size_t k = 0; k < m.shape.size(); ++k)
            if (std::abs(m.shape[k]) > std::abs(m.shape[big])) big = k;
        std::string dof = m.shape.empty() ? "" : dofs[big];
        if (m.rigid_body)
            std::snprintf(line, sizeof line, "%4zu  %14s  %13s  %s (rigid-body mode)\n", i + 1, "0",
                          "-", dof.c_str());
        else
            std::snprintf(line, sizeof line, "%4zu  %14.6g  %13.4g  %s%s\n", i + 1, m.freq_hz,
                          std::fabs(m.damping_ratio) < 1e-12 ? 0.0 : m.damping_ratio, dof.c_str(),
                          m.real ? " (non-oscillating)" : "");
        out += line;
    }
    return out;
}

std::string modes_json(const std::vector<runtime::Mode>& modes) {
    namespace json = driver::json;
    std::string out = "[";
    for (std::size_t i = 0; i < modes.size(); ++i) {
        const auto& m = modes[i];
        out += std::string(i ? "," : "") + "{\"freq_hz\":" + json::number(m.freq_hz) +
               ",\"damping_ratio\":" + json::number(m.damping_ratio) +
               ",\"rigid_body\":" + (m.rigid_body ? "true" : "false") + "}";
    }
    return out + "]";
}

} // namespace yamsc::analysis
