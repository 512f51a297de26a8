#include "analysis/rao_report.hpp"

#include "analysis/load_blocks.hpp"
#include "analysis/sea_state_setup.hpp"
#include "analysis/svg_plot.hpp"
#include "analysis/wave_response.hpp"
#include "diag/errors.hpp"
#include "seastate/seastate_input.hpp"

#include <yamsc/atomic_file.hpp>

#include <cmath>
#include <cstdio>
#include <optional>
#include <ostream>
#include <sstream>

namespace yamsc::analysis {

namespace {

struct Sea {
    double hs = 0, tp = 0, gamma = 0, direction = 0;
    bool irregular = false;
};

/// The SeaState file's heading and, for a JONSWAP sea, its Hs, Tp and gamma.
std::optional<Sea> sea_of(const std::string& file, std::ostream& err) {
    if (file.empty()) return std::nullopt;
    diag::Diagnostics d;
    const std::optional<seastate::Input> in = seastate::read_seastate_input(file, d);
    if (!in || d.has_errors()) throw diag::UserError(d.render());
    const runtime::hydro::WaveSettings w = wave_settings(*in, runtime::hydro::Water{}, d);
    if (d.has_errors()) throw diag::UserError(d.render());
    if (!d.all().empty()) err << d.render();
    Sea s;
    s.direction = w.direction;
    s.irregular = w.kind == runtime::hydro::WaveKind::irregular;
    s.hs = w.height;
    s.tp = w.period;
    if (s.irregular)
        s.gamma = w.peak_shape.value_or(runtime::hydro::default_peak_shape(s.hs, s.tp));
    else
        err << "yamsc: warning: " << file
            << " is not an irregular sea (WaveMod 2): RAOs only, no response spectra\n";
    return s;
}

std::string number(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.9g", v);
    return b;
}

} // namespace

int rao_report(const Loaded& l, const driver::LinOptions& o, const std::vector<double>& q,
               const std::vector<double>& u, std::ostream& out, std::ostream& err) {
    const std::optional<Sea> sea = sea_of(o.sea_state, err);
    WaveResponseRequest r;
    for (double f : o.rao_frequencies) r.omega.push_back(2 * M_PI * f);
    if (sea) r.direction = sea->direction;
    BlockOptions b = linear_block_options(o);
    const WaveResponse x = wave_response(l, b, q, u, r);
    const std::vector<std::string>& dofs = l.view.dof_names;
    const std::size_t nq = dofs.size(), nf = r.omega.size();
    const bool spectra = sea && sea->irregular;
    std::vector<double> s(nf, 0.0);
    if (spectra)
        for (std::size_t k = 0; k < nf; ++k)
            s[k] = runtime::hydro::jonswap(r.omega[k], sea->hs, sea->tp, sea->gamma);
    const runtime::SeaResponse response = runtime::sea_response(r.omega, x.motion, s);

    std::ostringstream csv;
    csv << "frequency_hz,omega_rad_s";
    if (spectra) csv << ",wave_spectrum_m2s_rad";
    for (const std::string& d : dofs) csv << "," << d << "_abs," << d << "_phase_deg";
    if (spectra)
        for (const std::string& d : dofs) csv << "," << d << "_spectrum";
    csv << "\n";
    for (std::size_t k = 0; k < nf; ++k) {
        csv << number(o.rao_frequencies[k]) << "," << number(r.omega[k]);
        if (spectra) csv << "," << number(s[k]);
        for (std::size_t j = 0; j < nq; ++j)
            csv << "," << number(std::abs(x.motion[k][j])) << ","
                << number(std::arg(x.motion[k][j]) * 180 / M_PI);
        if (spectra)
            for (std::size_t j = 0; j < nq; ++j) csv << "," << number(response.spectra[k][j]);
        csv << "\n";
    }
    runtime::write_file_atomically(o.rao, csv.str());

    out << "RAO per metre of wave amplitude, " << nf << " frequencies "
        << number(o.rao_frequencies.front()) << " to " << number(o.rao_frequencies.back())
        << " Hz, heading " << number(r.direction * 180 / M_PI) << " deg";
    if (spectra)
        out << "; JONSWAP Hs " << number(sea->hs) << " m, Tp " << number(sea->tp) << " s, gamma "
            << number(sea->gamma);
    out << "\n";
    out << "dof        max |X|      at [Hz]" << (spectra ? "    std dev" : "") << "\n";
    for (std::size_t j = 0; j < nq; ++j) {
        std::size_t at = 0;
        for (std::size_t k = 1; k < nf; ++k)
            if (std::abs(x.motion[k][j]) > std::abs(x.motion[at][j])) at = k;
        char line[160];
        std::snprintf(line, sizeof line, "%-10s %-12.5g %-10.5g", dofs[j].c_str(),
                      std::abs(x.motion[at][j]), o.rao_frequencies[at]);
        out << line;
        if (spectra) {
            std::snprintf(line, sizeof line, " %.5g", response.standard_deviation[j]);
            out << line;
        }
        out << "\n";
    }
    out << "wrote " << nf << " rows to " << o.rao << "\n";

    if (!o.plot.empty()) {
        std::vector<PlotPanel> panels;
        for (std::size_t j = 0; j < nq; ++j) {
            PlotSeries series{"|X| " + dofs[j], o.rao_frequencies, {}};
            for (std::size_t k = 0; k < nf; ++k) series.y.push_back(std::abs(x.motion[k][j]));
            panels.push_back({"|" + dofs[j] + "| per m", {series}});
        }
        PlotOptions p;
        p.title = l.front.model->name + ": response amplitude operators";
        p.x_label = "Wave frequency [Hz]";
        runtime::write_file_atomically(o.plot, svg_plot(panels, p));
        out << "wrote " << o.plot << "\n";
    }
    return 0;
}

} // namespace yamsc::analysis
