#pragma once
// A small, dependency-free SVG writer for time series: one panel per channel,
// stacked, sharing the time axis, each with its curves (simulation solid,
// reference dashed) and a legend. Deterministic text: the same data give the same
// bytes.
#include <string>
#include <vector>

namespace yamsc::analysis {

struct PlotSeries {
    std::string label;        ///< legend text
    std::vector<double> t, y; ///< equal lengths; t rising
    bool dashed = false;
};

struct PlotPanel {
    std::string y_label; ///< the channel, e.g. `Q_TFA1_[m]`
    std::vector<PlotSeries> series;
};

struct PlotOptions {
    std::string title;
    int width = 900;        ///< px
    int panel_height = 200; ///< px per panel
    std::string x_label = "Time [s]";
    /// Also write each curve's label at its last point in the first panel (many
    /// curves, few colours: a Campbell diagram); the right margin widens for them.
    bool label_curve_ends = false;
};

/// The SVG document. Non-finite values break a curve.
std::string svg_plot(const std::vector<PlotPanel>& panels, const PlotOptions& options);

/// `text` with & < > " escaped, for SVG/XML text and attribute values.
std::string xml_escape(const std::string& text);

/// Tick positions for [lo, hi]: about `target` round values (1, 2, 5 x 10^k).
std::vector<double> nice_ticks(double lo, double hi, int target = 5);

} // namespace yamsc::analysis
