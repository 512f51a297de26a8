#include "analysis/rotor_campbell.hpp"

#include "analysis/svg_plot.hpp"
#include "analysis/trim_point.hpp"
#include "driver/bindings.hpp"

#include <yamsc/atomic_file.hpp>

#include <algorithm>
#include <ostream>

#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

namespace yamsc::driver {

namespace {

std::string csv_field(const std::string& s) {
    if (s.find_first_of(",\"") == std::string::npos) return s;
    std::string out = "\"";
    for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

} // namespace

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
                               const std::vector<RotorCampbellRow>& rows, bool rotor_speed) {
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
                damping.series[c].y[k] = m.mode.damping_ratio;
            }
        }
    if (rotor_speed)
        for (int p : {1, 3, 6}) {
            PlotSeries line{std::to_string(p) + "P", x, {}, true};
            for (double omega : x) line.y.push_back(p * omega / (2 * M_PI));
            freq.series.push_back(std::move(line));
        }
    PlotOptions options;
    options.title = title;
    options.x_label = name + (rotor_speed ? " [rad/s]" : "");
    options.panel_height = 320;
    options.label_curve_ends = true;
    return svg_plot({freq, damping}, options);
}

int rotor_campbell(const Loaded& l, const LinOptions& o, std::ostream& out) {
    const Sweep& sweep = *o.sweep;
    const std::vector<std::string>& dofs = l.view.dof_names;
    const bool rate = !sweep.name.empty() && sweep.name.back() == '\'';
    const std::string base = rate ? sweep.name.substr(0, sweep.name.size() - 1) : sweep.name;
    const auto dof = std::find(dofs.begin(), dofs.end(), base);
    const int param = rate ? -1 : l.library->param_index(sweep.name);
    if (rate && dof == dofs.end())
        throw UserError("--sweep: unknown DOF '" + base + "'" + diag::did_you_mean(base, dofs));
    if (!rate && param < 0)
        throw UserError("--sweep: unknown parameter '" + sweep.name + "'" +
                        diag::did_you_mean(sweep.name, l.library->param_names()) +
                        " (a rotor speed is swept as a rate: psi'=FROM:STEP:TO)");
    std::vector<RotorCampbellRow> rows;
    for (double value : sweep.values) {
        std::vector<double> params = l.params;
        if (param >= 0) params[static_cast<std::size_t>(param)] = value;
        const runtime::ModelView view = l.library->view(params);
        std::vector<double> q, qd, u;
        operating_point(l, params, o.at, o.u, q, qd, u);
        if (rate) qd[static_cast<std::size_t>(dof - dofs.begin())] = value;
        if (o.trim) {
            const runtime::TrimResult trimmed = trim_point(view, q, qd, u, o.hold, o.adjust);
            q = trimmed.q;
            u = trimmed.u;
        }
        const RotorModesRequest r = rotor_request(
            view, q, qd, u, rate && o.azimuth.empty() ? base : o.azimuth, o.hold, o.azimuths);
        rows.push_back({value, rotor_modes(view, r)});
    }
    const std::string csv = rotor_campbell_csv(sweep.name, rows);
    if (o.output.empty()) {
        out << csv;
    } else {
        runtime::write_file_atomically(o.output, csv);
        out << "wrote " << rows.size() << " rotor speeds' modes to " << o.output << "\n";
    }
    if (!o.plot.empty()) {
        const std::string title = l.front.model->name + ": MBC3 modes against " + sweep.name;
        runtime::write_file_atomically(o.plot, rotor_campbell_svg(title, sweep.name, rows, rate));
        out << "wrote " << o.plot << "\n";
    }
    return 0;
}

} // namespace yamsc::driver
