// SVG line plots of time series (see svg_plot.hpp).
#include "analysis/svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace yamsc::analysis {

namespace {

const char* const colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e"};
const char* const reference_colour = "#222222";

std::string num(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.2f", v);
    return buffer;
}

std::string tick_label(double v, double step) {
    if (std::abs(v) < 1e-12 * std::max(1.0, step)) v = 0; // no "-0"
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", v);
    return buffer;
}

struct Range {
    double lo = INFINITY, hi = -INFINITY;
    void add(double v) {
        if (!std::isfinite(v)) return;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    bool valid() const { return lo <= hi; }
    /// Widened so that a constant signal or a span of zero still has an axis.
    Range padded(double fraction) const {
        Range r = *this;
        if (!valid()) return {0, 1};
        double span = hi - lo;
        if (span <= 1e-12 * std::max(1.0, std::abs(hi))) span = std::max(1.0, std::abs(hi)) * 0.1;
        r.lo -= fraction * span;
        r.hi += fraction * span;
        return r;
    }
};

} // namespace

std::string xml_escape(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '&')
            out += "&amp;";
        else if (c == '<')
            out += "&lt;";
        else if (c == '>')
            out += "&gt;";
        else if (c == '"')
            out += "&quot;";
        else
            out += c;
    }
    return out;
}

std::vector<double> nice_ticks(double lo, double hi, int target) {
    std::vector<double> ticks;
    if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi) || target < 1) return ticks;
    const double raw = (hi - lo) / target;
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    double step = magnitude;
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * magnitude >= raw) {
            step = m * magnitude;
            break;
        }
    for (double v = std::ceil(lo / step) * step; v <= hi + 1e-9 * step; v += step)
        ticks.push_back(v);
    return ticks;
}

std::string svg_plot(const std::vector<PlotPanel>& panels, const PlotOptions& options) {
    // Title, then the legend of the curves (the panels share their labels), in as
    // many rows as its entries need.
    const double left = 90, right = options.label_curve_ends ? 150 : 20, gap = 30, bottom = 45;
    const double w = options.width, plot_w = w - left - right, panel_h = options.panel_height;
    auto legend_width = [](const PlotSeries& s) {
        return 34 + 7.0 * static_cast<double>(s.label.size()) + 30;
    };
    int legend_rows = 1;
    if (!panels.empty()) {
        double lx = left;
        for (const PlotSeries& s : panels.front().series) {
            if (lx > left && lx + legend_width(s) - 30 > w - 20) {
                ++legend_rows;
                lx = left;
            }
            lx += legend_width(s);
        }
    }
    const double top = (options.title.empty() ? 45 : 70) + 18.0 * (legend_rows - 1);
    const double h = top + static_cast<double>(panels.size()) * (panel_h + gap) - gap + bottom;
    Range time;
    for (const PlotPanel& p : panels)
        for (const PlotSeries& s : p.series)
            for (double t : s.t) time.add(t);
    if (!time.valid() || time.hi <= time.lo) time = Range{0, 1};
    const std::vector<double> t_ticks = nice_ticks(time.lo, time.hi, 8);
    const double t_step = t_ticks.size() > 1 ? t_ticks[1] - t_ticks[0] : 1;
    auto x_of = [&](double t) { return left + (t - time.lo) / (time.hi - time.lo) * plot_w; };

    std::ostringstream out;
    out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(w) << "\" height=\""
        << num(h) << "\" viewBox=\"0 0 " << num(w) << ' ' << num(h)
        << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
    out << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    if (!options.title.empty())
        out << "<text x=\"" << num(w / 2) << "\" y=\"25\" text-anchor=\"middle\" "
            << "font-size=\"15\">" << xml_escape(options.title) << "</text>\n";
    if (!panels.empty()) {
        double lx = left;
        double ly = top - 14 - 18.0 * (legend_rows - 1);
        std::size_t solid = 0;
        for (const PlotSeries& s : panels.front().series) {
            const char* colour = s.dashed ? reference_colour : colours[solid++ % 5];
            if (lx > left && lx + legend_width(s) - 30 > w - 20) {
                ly += 18;
                lx = left;
            }
            out << "<line x1=\"" << num(lx) << "\" y1=\"" << num(ly - 4) << "\" x2=\""
                << num(lx + 28) << "\" y2=\"" << num(ly - 4) << "\" stroke=\"" << colour
                << "\" stroke-width=\"2\"" << (s.dashed ? " stroke-dasharray=\"6 4\"" : "")
                << "/>\n";
            out << "<text x=\"" << num(lx + 34) << "\" y=\"" << num(ly) << "\">"
                << xml_escape(s.label) << "</text>\n";
            lx += legend_width(s);
        }
    }
    for (std::size_t k = 0; k < panels.size(); ++k) {
        const PlotPanel& panel = panels[k];
        const double y0 = top + static_cast<double>(k) * (panel_h + gap);
        Range values;
        for (const PlotSeries& s : panel.series)
            for (double v : s.y) values.add(v);
        const Range yr = values.padded(0.05);
        const std::vector<double> y_ticks = nice_ticks(yr.lo, yr.hi, 5);
        const double y_step = y_ticks.size() > 1 ? y_ticks[1] - y_ticks[0] : 1;
        auto y_of = [&](double v) {
            return y0 + panel_h - (v - yr.lo) / (yr.hi - yr.lo) * panel_h;
        };
        out << "<g>\n";
        // Grid and tick labels.
        for (double t : t_ticks)
            out << "<line x1=\"" << num(x_of(t)) << "\" y1=\"" << num(y0) << "\" x2=\""
                << num(x_of(t)) << "\" y2=\"" << num(y0 + panel_h) << "\" stroke=\"#e0e0e0\"/>\n";
        for (double v : y_ticks) {
            out << "<line x1=\"" << num(left) << "\" y1=\"" << num(y_of(v)) << "\" x2=\""
                << num(left + plot_w) << "\" y2=\"" << num(y_of(v)) << "\" stroke=\"#e0e0e0\"/>\n";
            out << "<text x=\"" << num(left - 6) << "\" y=\"" << num(y_of(v) + 4)
                << "\" text-anchor=\"end\">" << tick_label(v, y_step) << "</text>\n";
        }
        out << "<rect x=\"" << num(left) << "\" y=\"" << num(y0) << "\" width=\"" << num(plot_w)
            << "\" height=\"" << num(panel_h) << "\" fill=\"none\" stroke=\"#444444\"/>\n";
        out << "<text transform=\"translate(" << num(18) << ' ' << num(y0 + panel_h / 2)
            << ") rotate(-90)\" text-anchor=\"middle\">" << xml_escape(panel.y_label)
            << "</text>\n";
        if (k + 1 == panels.size()) {
            for (double t : t_ticks)
                out << "<text x=\"" << num(x_of(t)) << "\" y=\"" << num(y0 + panel_h + 16)
                    << "\" text-anchor=\"middle\">" << tick_label(t, t_step) << "</text>\n";
            out << "<text x=\"" << num(left + plot_w / 2) << "\" y=\"" << num(y0 + panel_h + 36)
                << "\" text-anchor=\"middle\">" << xml_escape(options.x_label) << "</text>\n";
        }
        // Curves, clipped to the panel.
        out << "<clipPath id=\"clip" << k << "\"><rect x=\"" << num(left) << "\" y=\"" << num(y0)
            << "\" width=\"" << num(plot_w) << "\" height=\"" << num(panel_h)
            << "\"/></clipPath>\n";
        std::size_t solid = 0;
        for (const PlotSeries& s : panel.series) {
            const char* colour = s.dashed ? reference_colour : colours[solid++ % 5];
            std::string points;
            auto flush = [&] {
                if (points.empty()) return;
                out << "<polyline clip-path=\"url(#clip" << k << ")\" fill=\"none\" stroke=\""
                    << colour << "\" stroke-width=\"" << (s.dashed ? "1.6" : "1.4") << "\""
                    << (s.dashed ? " stroke-dasharray=\"6 4\"" : "") << " points=\"" << points
                    << "\"/>\n";
                points.clear();
            };
            std::size_t last = s.t.size();
            for (std::size_t i = 0; i < s.t.size() && i < s.y.size(); ++i) {
                if (!std::isfinite(s.t[i]) || !std::isfinite(s.y[i])) {
                    flush();
                    continue;
                }
                points += (points.empty() ? "" : " ") + num(x_of(s.t[i])) + "," + num(y_of(s.y[i]));
                last = i;
            }
            flush();
            const bool inside = last < s.t.size() && s.y[last] >= yr.lo && s.y[last] <= yr.hi;
            if (options.label_curve_ends && k == 0 && inside)
                out << "<text x=\"" << num(x_of(s.t[last]) + 4) << "\" y=\""
                    << num(y_of(s.y[last]) + 3) << "\" font-size=\"10\" fill=\"" << colour << "\">"
                    << xml_escape(s.label) << "</text>\n";
        }
        out << "</g>\n";
    }
    out << "</svg>\n";
    return out.str();
}

} // namespace yamsc::analysis
