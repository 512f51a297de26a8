#include "analysis/hydro_potential_setup.hpp"

#include "diag/read_text.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

namespace yamsc::analysis {
namespace {

using diag::Kind;
using runtime::hydro::Mat6;

constexpr double pi = 3.14159265358979323846;
/// HydroDyn's OnePlusEps (single precision): the infinite frequency just above the highest.
constexpr double one_plus_eps = 1 + 1.1920929e-7;

/// WAMIT's nondimensionalization: L^(k + rotations among i, j), i and j 1-based.
double length_power(double ulen, int base, int i, int j = 0) {
    int k = base + (i > 3 ? 1 : 0) + (j > 3 ? 1 : 0);
    return std::pow(ulen, k);
}

diag::Location at(const std::shared_ptr<const diag::SourceFile>& f, int line, int col = 1) {
    return {f, line, col};
}

/// Periods as HydroDyn reads them: a new frequency where the period changes.
struct Period {
    double period = 0, omega = 0;
    std::size_t first = 0, end = 0; // rows [first, end)
};

template <class Row> std::vector<Period> periods(const std::vector<Row>& rows) {
    std::vector<Period> out;
    for (std::size_t k = 0; k < rows.size(); ++k) {
        if (out.empty() || rows[k].period != out.back().period)
            out.push_back({rows[k].period, 0, k, k});
        out.back().end = k + 1;
    }
    return out;
}

} // namespace

std::optional<WamitCoefficients> wamit_coefficients(const wamit::RadiationFile& radiation,
                                                    const wamit::ExcitationFile* excitation,
                                                    const wamit::HydrostaticFile& hydrostatics,
                                                    double density, double gravity, double ulen,
                                                    diag::Diagnostics& diags) {
    WamitCoefficients c;
    const double rho_g = density * gravity;
    bool ok = true;
    const auto too_many = [&](const std::shared_ptr<const diag::SourceFile>& f, int line) {
        diags.error(Kind::NotSupported, at(f, line),
                    "modes beyond 6 (more bodies or generalized modes) are not supported");
        ok = false;
    };
    for (const wamit::HydrostaticRow& r : hydrostatics.rows) {
        if (r.i > 6 || r.j > 6) {
            too_many(hydrostatics.file, r.line);
            continue;
        }
        c.hydrostatic[static_cast<std::size_t>(6 * (r.i - 1) + r.j - 1)] =
            r.restoring * rho_g * length_power(ulen, 2, r.i, r.j);
    }

    std::vector<Period> freq = periods(radiation.rows);
    bool zero = false, infinite = false;
    double highest = 0;
    for (Period& p : freq) {
        if (p.period < 0) {
            zero = true;
        } else if (p.period > 0) {
            p.omega = 2 * pi / p.period;
            highest = std::max(highest, p.omega);
        } else {
            infinite = true;
        }
    }
    if (!zero || !infinite) {
        diags.error(Kind::InvalidValue, at(radiation.file, 1),
                    "the WAMIT .1 file must hold both the zero-frequency (period < 0) and the "
                    "infinite-frequency (period 0) added mass, as HydroDyn requires");
        return std::nullopt;
    }
    for (Period& p : freq)
        if (p.period == 0) p.omega = highest * one_plus_eps;
    std::vector<std::size_t> order(freq.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return freq[a].omega < freq[b].omega; });
    for (std::size_t k : order) {
        const Period& p = freq[k];
        Mat6 a{}, b{};
        for (std::size_t r = p.first; r < p.end; ++r) {
            const wamit::RadiationRow& row = radiation.rows[r];
            if (row.i > 6 || row.j > 6) {
                too_many(radiation.file, row.line);
                continue;
            }
            const std::size_t ij = static_cast<std::size_t>(6 * (row.i - 1) + row.j - 1);
            const double scale = density * length_power(ulen, 3, row.i, row.j);
            a[ij] = row.added_mass * scale;
            if (row.damping) b[ij] = *row.damping * scale * p.omega;
        }
        c.omega.push_back(p.omega);
        c.added_mass.push_back(a);
        c.damping.push_back(b);
    }
    c.added_mass_infinite = c.added_mass.back();

    if (excitation) {
        // The .3's periods are the .1's positive ones in the same order, each with the
        // same headings as the first (WAMIT_Init's checks).
        std::vector<Period> finite;
        for (const Period& p : freq)
            if (p.period > 0) finite.push_back(p);
        const std::vector<Period> x = periods(excitation->rows);
        std::vector<double> headings;
        for (std::size_t k = 0; k < x.size() && ok; ++k) {
            const wamit::ExcitationRow& first = excitation->rows[x[k].first];
            if (k >= finite.size() || x[k].period != finite[k].period) {
                diags.error(Kind::InvalidValue, at(excitation->file, first.line),
                            "the .3 file's periods must be the .1 file's (other than zero and "
                            "infinity), in the same order: both from one WAMIT run");
                return std::nullopt;
            }
            std::vector<double> here;
            for (std::size_t r = x[k].first; r < x[k].end; ++r)
                if (here.empty() || excitation->rows[r].heading != here.back())
                    here.push_back(excitation->rows[r].heading);
            if (k == 0) {
                headings = here;
            } else if (here != headings) {
                diags.error(Kind::InvalidValue, at(excitation->file, first.line),
                            "every period of the .3 file must list the same headings");
                return std::nullopt;
            }
        }
        if (!ok) return std::nullopt;
        if (x.size() != finite.size()) {
            diags.error(Kind::InvalidValue, at(excitation->file, excitation->file->line_count()),
                        "the .3 file ends before the .1 file's last period");
            return std::nullopt;
        }
        std::vector<double> sorted = headings;
        std::sort(sorted.begin(), sorted.end());
        sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
        if (sorted.back() - sorted.front() > 360 + 1e-6) {
            diags.error(Kind::InvalidValue, at(excitation->file, 1),
                        "the .3 file's headings must span at most 360 deg");
            return std::nullopt;
        }
        runtime::hydro::ExcitationTable& t = c.excitation;
        t.omega = c.omega;
        for (double h : sorted) t.heading.push_back(h * pi / 180);
        const std::size_t nh = sorted.size();
        t.force.assign(t.omega.size() * nh * 6, 0.0);
        const auto place = [&](double omega) {
            return static_cast<std::size_t>(std::find(t.omega.begin(), t.omega.end(), omega) -
                                            t.omega.begin());
        };
        for (std::size_t k = 0; k < x.size(); ++k) {
            const std::size_t f = place(finite[k].omega);
            for (std::size_t r = x[k].first; r < x[k].end; ++r) {
                const wamit::ExcitationRow& row = excitation->rows[r];
                if (row.i > 6) {
                    too_many(excitation->file, row.line);
                    continue;
                }
                const std::size_t h = static_cast<std::size_t>(
                    std::lower_bound(sorted.begin(), sorted.end(), row.heading) - sorted.begin());
                t.force[(f * nh + h) * 6 + static_cast<std::size_t>(row.i - 1)] =
                    std::complex<double>(row.re, row.im) * rho_g * length_power(ulen, 2, row.i);
            }
        }
        // The zero frequency takes the lowest positive one's values (WAMIT_Init);
        // the infinite one stays zero.
        std::size_t lowest = 0;
        while (lowest < t.omega.size() && !(t.omega[lowest] > 0)) ++lowest;
        for (std::size_t f = 0; f < lowest && lowest < t.omega.size(); ++f)
            std::copy_n(t.force.begin() + static_cast<std::ptrdiff_t>(lowest * nh * 6), nh * 6,
                        t.force.begin() + static_cast<std::ptrdiff_t>(f * nh * 6));
    }
    if (!ok) return std::nullopt;
    return c;
}

std::optional<runtime::hydro::PotentialFlowSetup>
potential_setup(const hydrodyn::Input& input, const runtime::hydro::Water& water,
                diag::Diagnostics& diags, double time_step) {
    const int errors = diags.error_count();
    const auto refuse = [&](const char* key, const std::string& why) {
        diags.error(Kind::NotSupported, input.location(key), why);
    };
    if (input.pot_mod != hydrodyn::PotentialFlow::wamit)
        refuse("PotMod", "the potential-flow block needs PotMod 1 (WAMIT)");
    if (input.n_body != 1 || input.pot_file.size() != 1)
        refuse("NBody", "potential flow is supported for one body (NBody 1)");
    if (input.exctn_mod == 2)
        refuse("ExctnMod", "the state-space wave excitation (ExctnMod 2) is not supported; "
                           "use 1 (the DFT of the .3)");
    if (input.rdtn_mod == 2)
        refuse("RdtnMod", "the state-space radiation (RdtnMod 2) is not supported; use 1 "
                          "(convolution)");
    if (!input.ptfm_ref_zt_rot.empty() && input.ptfm_ref_zt_rot[0] != 0)
        refuse("PtfmRefztRot", "a rotated WAMIT body (PtfmRefztRot other than 0) is not "
                               "supported");
    if (!input.n_add_dof.empty() && input.n_add_dof[0] != 0)
        refuse("NAddDOF", "generalized WAMIT modes (NAddDOF) are not supported");
    if (input.exctn_disp != 0)
        diags.warning(Kind::NotSupported, input.location("ExctnDisp"),
                      "the excitation is computed at the undisplaced position (ExctnDisp 0)");
    double rdtn_dt = input.rdtn_dt;
    if (input.rdtn_mod == 1 && input.rdtn_dt_default) {
        rdtn_dt = time_step;
        if (!(time_step > 0))
            refuse("RdtnDT", "RdtnDT DEFAULT is the simulation's time step, which is not known "
                             "here: give RdtnDT");
    }
    if (diags.error_count() > errors) return std::nullopt;

    const std::filesystem::path root =
        std::filesystem::path(input.path).parent_path() / input.pot_file[0];
    const diag::Location pot_file = input.location("PotFile");
    const auto read = [&](const char* ext) {
        return diag::read_text_file(root.string() + ext, diags, pot_file);
    };
    const auto f1 = read(".1"), fh = read(".hst");
    const auto f3 = input.exctn_mod == 1 ? read(".3") : nullptr;
    if (!f1 || !fh || (input.exctn_mod == 1 && !f3)) return std::nullopt;
    const auto radiation = wamit::read_radiation(f1, diags);
    const auto hydrostatics = wamit::read_hydrostatics(fh, diags);
    std::optional<wamit::ExcitationFile> excitation;
    if (f3) excitation = wamit::read_excitation(f3, diags);
    if (!radiation || !hydrostatics || (f3 && !excitation)) return std::nullopt;
    const double ulen = input.wamit_ulen.empty() ? 1.0 : input.wamit_ulen[0];
    const auto c = wamit_coefficients(*radiation, excitation ? &*excitation : nullptr,
                                      *hydrostatics, water.density, water.gravity, ulen, diags);
    if (!c) return std::nullopt;

    runtime::hydro::PotentialFlowSetup s;
    s.added_mass_infinite = c->added_mass_infinite;
    s.hydrostatic = c->hydrostatic;
    s.displaced_volume = input.ptfm_vol0.empty() ? 0 : input.ptfm_vol0[0];
    s.cob_x = input.ptfm_cob_xt.empty() ? 0 : input.ptfm_cob_xt[0];
    s.cob_y = input.ptfm_cob_yt.empty() ? 0 : input.ptfm_cob_yt[0];
    s.reference = {input.ptfm_ref_xt.empty() ? 0 : input.ptfm_ref_xt[0],
                   input.ptfm_ref_yt.empty() ? 0 : input.ptfm_ref_yt[0],
                   input.ptfm_ref_zt.empty() ? 0 : input.ptfm_ref_zt[0]};
    if (input.rdtn_mod == 1) {
        try {
            s.radiation_kernel =
                runtime::hydro::radiation_kernel(c->omega, c->damping, rdtn_dt, input.rdtn_tmax);
            s.kernel_dt = rdtn_dt;
        } catch (const std::invalid_argument& e) {
            diags.error(Kind::InvalidValue, input.location("RdtnDT"), e.what());
            return std::nullopt;
        }
    }
    if (input.exctn_mod == 1) s.excitation = c->excitation;
    s.water = water;
    if (input.matrix_size == 6 && input.matrix_count == 1 && input.add_f0.size() == 6 &&
        input.add_c_lin.size() == 36 && input.add_b_lin.size() == 36 &&
        input.add_b_quad.size() == 36) {
        std::copy_n(input.add_f0.begin(), 6, s.additional.f0.begin());
        std::copy_n(input.add_c_lin.begin(), 36, s.additional.c_lin.begin());
        std::copy_n(input.add_b_lin.begin(), 36, s.additional.b_lin.begin());
        std::copy_n(input.add_b_quad.begin(), 36, s.additional.b_quad.begin());
    }
    return s;
}

} // namespace yamsc::analysis
