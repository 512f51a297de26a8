#include "analysis/campbell.hpp"

#include "analysis/svg_plot.hpp"
#include "driver/values.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace yamsc::analysis {

namespace {

/// Shortest round-trip text of a number, no "-0".
std::string csv_number(double v) {
    if (v == 0) return "0";
    char buffer[40];
    for (int digits = 6; digits <= 17; ++digits) {
        std::snprintf(buffer, sizeof buffer, "%.*g", digits, v);
        if (std::strtod(buffer, nullptr) == v) break;
    }
    return buffer;
}

std::string fixed(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.1f", v);
    return buffer;
}

/// About `target` round tick values (1, 2, 5 x 10^k) covering [lo, hi].
std::vector<double> ticks(double lo, double hi, int target) {
    if (!(hi > lo)) hi = lo + 1;
    const double raw = (hi - lo) / target;
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    double step = magnitude;
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * magnitude >= raw) {
            step = m * magnitude;
            break;
        }
    std::vector<double> out;
    for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + 1e-9 * step; t += step)
        out.push_back(std::fabs(t) < 1e-12 * step ? 0.0 : t);
    return out;
}

const char* const colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd",
                               "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};

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
    const int width = 900, panel = 260, left = 80, right = 150, top = 40, gap = 50;
    const int plot_w = width - left - right, height = top + 2 * panel + gap + 50;
    std::size_t modes = 0;
    double x_lo = INFINITY, x_hi = -INFINITY;
    for (const CampbellRow& r : rows) {
        modes = std::max(modes, r.modes.size());
        x_lo = std::min(x_lo, r.value);
        x_hi = std::max(x_hi, r.value);
    }
    if (!(x_hi > x_lo)) x_hi = x_lo + 1;
    std::string out = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(width) +
                      "\" height=\"" + std::to_string(height) +
                      "\" font-family=\"sans-serif\" font-size=\"12\">\n"
                      "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
                      "<text x=\"" +
                      std::to_string(width / 2) + "\" y=\"22\" text-anchor=\"middle\" " +
                      "font-size=\"15\">" + xml_escape(title) + "</text>\n";
    auto x_of = [&](double x) { return left + (x - x_lo) / (x_hi - x_lo) * plot_w; };
    for (int p = 0; p < 2; ++p) {
        const int y0 = top + p * (panel + gap);
        // The values of this panel: frequency or damping ratio (rigid-body modes
        // have no damping).
        auto value = [&](const runtime::Mode& m, bool& ok) {
            ok = p == 0 || !m.rigid_body;
            return p == 0 ? (m.rigid_body ? 0.0 : m.freq_hz) : m.damping_ratio;
        };
        double y_lo = INFINITY, y_hi = -INFINITY;
        for (const CampbellRow& r : rows)
            for (const runtime::Mode& m : r.modes) {
                bool ok = false;
                const double v = value(m, ok);
                if (!ok || !std::isfinite(v)) continue;
                y_lo = std::min(y_lo, v);
                y_hi = std::max(y_hi, v);
            }
        if (!(y_lo <= y_hi)) y_lo = 0, y_hi = 1;
        if (p == 0) y_lo = std::min(y_lo, 0.0);
        if (y_hi - y_lo < 1e-12 * std::max(1.0, std::fabs(y_hi))) y_hi = y_lo + 1;
        const std::vector<double> y_ticks = ticks(y_lo, y_hi, 5);
        y_lo = std::min(y_lo, y_ticks.front());
        y_hi = std::max(y_hi, y_ticks.back());
        auto y_of = [&](double y) { return y0 + panel - (y - y_lo) / (y_hi - y_lo) * panel; };
        out += "<rect x=\"" + std::to_string(left) + "\" y=\"" + std::to_string(y0) +
               "\" width=\"" + std::to_string(plot_w) + "\" height=\"" + std::to_string(panel) +
               "\" fill=\"none\" stroke=\"#444\"/>\n";
        for (double t : y_ticks) {
            char label[32];
            std::snprintf(label, sizeof label, "%g", t);
            out += "<line x1=\"" + std::to_string(left) + "\" x2=\"" +
                   std::to_string(left + plot_w) + "\" y1=\"" + fixed(y_of(t)) + "\" y2=\"" +
                   fixed(y_of(t)) + "\" stroke=\"#ddd\"/>\n<text x=\"" + std::to_string(left - 6) +
                   "\" y=\"" + fixed(y_of(t) + 4) + "\" text-anchor=\"end\">" + label + "</text>\n";
        }
        for (double t : ticks(x_lo, x_hi, 8)) {
            char label[32];
            std::snprintf(label, sizeof label, "%g", t);
            out += "<line x1=\"" + fixed(x_of(t)) + "\" x2=\"" + fixed(x_of(t)) + "\" y1=\"" +
                   std::to_string(y0) + "\" y2=\"" + std::to_string(y0 + panel) +
                   "\" stroke=\"#eee\"/>\n<text x=\"" + fixed(x_of(t)) + "\" y=\"" +
                   std::to_string(y0 + panel + 16) + "\" text-anchor=\"middle\">" + label +
                   "</text>\n";
        }
        out += "<text x=\"20\" y=\"" + std::to_string(y0 + panel / 2) +
               "\" transform=\"rotate(-90 20 " + std::to_string(y0 + panel / 2) +
               ")\" text-anchor=\"middle\">" + (p == 0 ? "frequency [Hz]" : "damping ratio [-]") +
               "</text>\n";
        for (std::size_t k = 0; k < modes; ++k) {
            std::string points;
            for (const CampbellRow& r : rows) {
                if (k >= r.modes.size()) continue;
                bool ok = false;
                const double v = value(r.modes[k], ok);
                if (!ok || !std::isfinite(v)) continue;
                points += (points.empty() ? "" : " ") + fixed(x_of(r.value)) + "," + fixed(y_of(v));
            }
            const char* colour = colours[k % (sizeof colours / sizeof colours[0])];
            out += "<polyline fill=\"none\" stroke=\"" + std::string(colour) +
                   "\" stroke-width=\"1.5\" points=\"" + points + "\"/>\n";
            if (p == 0)
                out += "<text x=\"" + std::to_string(left + plot_w + 10) + "\" y=\"" +
                       std::to_string(y0 + 16 + 16 * static_cast<int>(k)) + "\" fill=\"" + colour +
                       "\">mode " + std::to_string(k + 1) + "</text>\n";
        }
    }
    out += "<text x=\"" + std::to_string(left + plot_w / 2) + "\" y=\"" +
           std::to_string(height - 10) + "\" text-anchor=\"middle\">" + xml_escape(name) +
           "</text>\n";
    return out + "</svg>\n";
}

} // namespace yamsc::analysis
