#include "analysis/rotor_campbell.hpp"

#include "analysis/channels.hpp"
#include "analysis/svg_plot.hpp"
#include "analysis/sweep_point.hpp"
#include "driver/bindings.hpp"

#include <yamsc/atomic_file.hpp>

#include <algorithm>
#include <ostream>

#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

namespace yamsc::analysis {

using driver::LinOptions;
using driver::Sweep;

std::string rotor_campbell_csv(const std::string& name, const std::vector<RotorCampbellRow>& rows) {
    std::string out = csv_field(name) + ",mode,label,freq_hz,damping_ratio,share\n";
    char line[256];
    for (const RotorCampbellRow& r : rows)
        for (std::size_t i = 0; i < r.modes.size(); ++i) {
            const RotorMode& m = r.modes[i];
            std::snprintf(line, sizeof line, "%.12g,%zu,%s,%.9g,%.6g,%.4f\n", r.value, i + 1,
                          csv_field(m.label).c_str(), m.mode.rigid_body ? 0.0 : m.mode.freq_hz,
                          m.mode.rigid_body ? std::nan("") : m.mode.damping_ratio, m.participation);
            out += line;
        }
    return out;
}

std::string rotor_campbell_svg(const std::string& title, const std::string& name,
                               const std::vector<RotorCampbellRow>& rows,
                               const std::vector<double>& rotor_speed, bool swept_rotor_speed) {
    // One curve per label, NaN where the label is absent (the curve breaks).
    std::vector<std::string> labels;
    std::map<std::string, std::size_t> index;
    for (const RotorCampbellRow& r : rows)
        for (const RotorMode& m : r.modes)
            if (!m.mode.rigid_body && !index.count(m.label)) {
                index[m.label] = labels.size();
                labels.push_back(m.label);
            }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    PlotPanel freq{"frequency [Hz]", {}}, damping{"damping ratio [-]", {}};
    std::vector<double> x;
    for (const RotorCampbellRow& r : rows) x.push_back(r.value);
    for (const std::string& l : labels) {
        freq.series.push_back({l, x, std::vector<double>(x.size(), nan), false});
        damping.series.push_back({l, x, std::vector<double>(x.size(), nan), false});
    }
    for (std::size_t k = 0; k < rows.size(); ++k)
        for (const RotorMode& m : rows[k].modes) {
            if (m.mode.rigid_body) continue;
            const std::size_t c = index.at(m.label);
            // Two modes with one label at a value (a coupled pair): the first.
            if (std::isnan(freq.series[c].y[k])) {
                freq.series[c].y[k] = m.mode.freq_hz;
                // A real pole (a rotor's speed regulation) has damping ratio 1
                // by definition: left out of the panel, whose scale it would take.
                if (!m.mode.real) damping.series[c].y[k] = m.mode.damping_ratio;
            }
        }
    if (rotor_speed.size() == x.size())
        for (int p : {1, 3, 6}) {
            PlotSeries line{std::to_string(p) + "P", x, {}, true};
            for (double omega : rotor_speed) line.y.push_back(p * std::fabs(omega) / (2 * M_PI));
            freq.series.push_back(std::move(line));
        }
    PlotOptions options;
    options.title = title;
    options.x_label = name + (swept_rotor_speed ? " [rad/s]" : "");
    options.panel_height = 320;
    options.label_curve_ends = true;
    return svg_plot({freq, damping}, options);
}

int rotor_campbell(const Loaded& l, const LinOptions& o, std::ostream& out) {
    const Sweep& sweep = *o.sweep;
    const SweepPoints points(l, o);
    const std::string& rate = points.rate_of();
    std::vector<RotorCampbellRow> rows;
    std::vector<double> rotor_speed;
    for (double value : sweep.values) {
        const SweepPoint p = points.at(value);
        const RotorModesRequest r = rotor_request(
            p.view, p.q, p.qd, p.u, o.azimuth.empty() ? rate : o.azimuth, o.hold, o.azimuths);
        rotor_speed.push_back(p.qd[static_cast<std::size_t>(r.azimuth_dof)]);
        rows.push_back({value, rotor_modes(p.view, r)});
    }
    const std::string csv = rotor_campbell_csv(sweep.name, rows);
    if (o.output.empty()) {
        out << csv;
    } else {
        runtime::write_file_atomically(o.output, csv);
        out << "wrote " << rows.size() << " values' modes (" << sweep.name << ") to " << o.output
            << "\n";
    }
    if (!o.plot.empty()) {
        const std::string title = l.front.model->name + ": MBC3 modes against " + sweep.name;
        runtime::write_file_atomically(
            o.plot, rotor_campbell_svg(title, sweep.name, rows, rotor_speed, !rate.empty()));
        out << "wrote " << o.plot << "\n";
    }
    return 0;
}

} // namespace yamsc::analysis
