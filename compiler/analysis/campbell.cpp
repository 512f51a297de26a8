#include "analysis/campbell.hpp"

#include "analysis/svg_plot.hpp"
#include "driver/values.hpp"
#include "text/number.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace yamsc::analysis {

namespace {

/// Shortest round-trip text of a number, no "-0".
std::string csv_number(double v) {
    if (v == 0) return "0";
    return text::shortest_printf(v, 6);
}

} // namespace

std::string campbell_csv(const std::string& name, const std::vector<CampbellRow>& rows) {
    std::size_t modes = 0;
    for (const CampbellRow& r : rows) modes = std::max(modes, r.modes.size());
    std::string out = name;
    for (std::size_t k = 1; k <= modes; ++k)
        out += ",mode" + std::to_string(k) + "_freq_hz,mode" + std::to_string(k) + "_damping_ratio";
    out += "\n";
    for (const CampbellRow& r : rows) {
        out += csv_number(r.value);
        for (std::size_t k = 0; k < modes; ++k) {
            if (k >= r.modes.size()) {
                out += ",,";
                continue;
            }
            const runtime::Mode& m = r.modes[k];
            out += "," + csv_number(m.rigid_body ? 0.0 : m.freq_hz) + "," +
                   (m.rigid_body ? std::string() : csv_number(m.damping_ratio));
        }
        out += "\n";
    }
    return out;
}

std::string campbell_svg(const std::string& title, const std::string& name,
                         const std::vector<CampbellRow>& rows) {
    std::size_t modes = 0;
    for (const CampbellRow& r : rows) modes = std::max(modes, r.modes.size());
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<double> x;
    for (const CampbellRow& r : rows) x.push_back(r.value);
    PlotPanel freq{"frequency [Hz]", {}}, damping{"damping ratio [-]", {}};
    for (std::size_t k = 0; k < modes; ++k) {
        const std::string label = "mode " + std::to_string(k + 1);
        freq.series.push_back({label, x, std::vector<double>(x.size(), nan), false});
        damping.series.push_back({label, x, std::vector<double>(x.size(), nan), false});
    }
    for (std::size_t i = 0; i < rows.size(); ++i)
        for (std::size_t k = 0; k < rows[i].modes.size(); ++k) {
            const runtime::Mode& m = rows[i].modes[k];
            // Rigid-body modes: frequency 0, no damping ratio.
            freq.series[k].y[i] = m.rigid_body ? 0.0 : m.freq_hz;
            if (!m.rigid_body) damping.series[k].y[i] = m.damping_ratio;
        }
    PlotOptions options;
    options.title = title;
    options.x_label = name;
    options.panel_height = 260;
    options.label_curve_ends = true;
    return svg_plot({freq, damping}, options);
}

} // namespace yamsc::analysis
