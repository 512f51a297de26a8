// The OC3-Hywind spar's RAO (models/oc3_spar_hydrodyn.mbd with the strip-theory HydroDyn file and
// MAP++'s lines): peaks at the linear model's frequencies.
#include "analysis/commands.hpp"
#include "analysis/load_blocks.hpp"
#include "analysis/loaded_model.hpp"
#include "analysis/wave_response.hpp"
#include "codegen/routines.hpp"

#include <yamsc/modal.hpp>
#include <yamsc/trim.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <sstream>

using namespace yamsc;

namespace {

struct Spar {
    std::optional<analysis::Loaded> loaded;
    analysis::BlockOptions blocks;
    std::vector<double> q, u, hz; // the trimmed point and lin's frequencies there
};

Spar& spar() {
    static Spar s = [] {
        Spar r;
        std::ostringstream err;
        auto l = analysis::load(std::string(YAMSC_SOURCE_DIR) + "/models/oc3_spar_hydrodyn.mbd", {},
                                "", false, err, {}, codegen::abi_routines());
        REQUIRE_MESSAGE(l, err.str());
        r.loaded.emplace(std::move(*l));
        r.blocks.mooring = std::string(YAMSC_TEST_DATA_DIR) + "/mooring/oc3_hywind.map";
        r.blocks.hydro = std::string(YAMSC_TEST_DATA_DIR) + "/hydro/oc3_spar_strip.dat";
        const runtime::ModelView v = analysis::with_load_blocks(*r.loaded, r.blocks);
        r.u.assign(static_cast<std::size_t>(v.nu), 0.0);
        const std::vector<double> zero(static_cast<std::size_t>(v.nq), 0.0);
        const runtime::TrimResult t =
            runtime::trim(v, zero, zero, r.u, std::vector<bool>(zero.size(), false));
        REQUIRE(t.converged);
        r.q = t.q;
        std::vector<double> x(t.q);
        x.insert(x.end(), zero.begin(), zero.end());
        for (const runtime::Mode& m :
             runtime::modal_analysis(runtime::state_matrix_from_view(v, x, r.u), v.nq))
            r.hz.push_back(m.freq_hz);
        return r;
    }();
    return s;
}

/// The frequency [Hz] of the largest |X_dof| on the response's grid.
double peak(const analysis::WaveResponse& r, std::size_t dof) {
    double best = -1, at = 0;
    for (std::size_t k = 0; k < r.omega.size(); ++k)
        if (std::abs(r.motion[k][dof]) > best) best = std::abs(r.motion[k][dof]), at = r.omega[k];
    return at / (2 * M_PI);
}

std::vector<double> grid(double lo_hz, double hi_hz, double step_hz) {
    std::vector<double> w;
    for (double f = lo_hz; f <= hi_hz; f += step_hz) w.push_back(2 * M_PI * f);
    return w;
}

} // namespace

TEST_CASE("the OC3 spar's heave and pitch RAOs peak at lin's frequencies") {
    Spar& s = spar();
    REQUIRE(s.hz.size() == 6);
    for (double f : s.hz) MESSAGE("mode " << f << " Hz");
    // Without drag and radiation damping nothing damps heave and pitch: their
    // peaks sit on the grid point nearest the modes' frequencies (surge and
    // pitch couple through the lines and the mass, the mode is the coupled one).
    analysis::WaveResponseRequest r;
    const double step = 2e-5;
    r.omega = grid(s.hz[2] - 50 * step, s.hz[2] + 50 * step, step);
    const analysis::WaveResponse heave = analysis::wave_response(*s.loaded, s.blocks, s.q, s.u, r);
    CHECK(std::abs(peak(heave, 2) - s.hz[2]) <= 0.51 * step);
    // Roll's mode is 1e-5 Hz below pitch's (the three lines' asymmetry): a grid
    // ten times finer tells them apart.
    const double fine = step / 10;
    r.omega = grid(s.hz[4] - 50 * fine, s.hz[4] + 50 * fine, fine);
    const analysis::WaveResponse pitch = analysis::wave_response(*s.loaded, s.blocks, s.q, s.u, r);
    CHECK(std::abs(peak(pitch, 4) - s.hz[4]) <= 0.51 * fine);
    // Head seas (direction 0): no sway, roll or yaw.
    for (std::size_t dof : {1u, 3u, 5u})
        CHECK(std::abs(pitch.motion[10][dof]) < 1e-9 * std::abs(pitch.motion[10][4]));
}

TEST_CASE("the OC3 spar in long waves: the heave excitation is rho g A_wp per metre") {
    // Under a wave much longer than the draft the pressure is the hydrostatic one of
    // the elevation, so the excitation on the hull is what the restoring of the same
    // rise of the water gives: rho g pi 3.25^2 per metre (strip theory's keel and
    // taper pressures together), the heave RAO K33_hydro / K33 with the lines'
    // heave stiffness in K33.
    // At 0.002 rad/s (k h = 0.011 in 320 m) the keel's pressure is below the
    // surface's by 1 - cosh(k (h - 120)) / cosh(k h) = 4e-5; at 0.01 rad/s it would be
    // 1e-3, the 0.2 % the keel's 69 m^2 then take off the excitation.
    Spar& s = spar();
    analysis::WaveResponseRequest r;
    r.omega = {0.002};
    const analysis::WaveResponse x = analysis::wave_response(*s.loaded, s.blocks, s.q, s.u, r);
    const double c33 = 1025 * 9.80665 * M_PI * 3.25 * 3.25;
    MESSAGE("F " << x.force[0][0] << " " << x.force[0][2] << " " << x.force[0][4] << ", X "
                 << x.motion[0][0] << " " << x.motion[0][2] << " " << x.motion[0][4]);
    CHECK(x.force[0][2].real() == doctest::Approx(c33).epsilon(2e-4));
    CHECK(std::abs(x.force[0][2].imag()) < 1e-4 * c33);
    // The RAO: the hull's restoring over the hull's and the lines' (K33 = 3.46e5 N/m).
    const double k33 = x.linear.K0[2 * 6 + 2];
    CHECK(k33 > c33 * 1.02);
    CHECK(std::abs(x.motion[0][2]) == doctest::Approx(c33 / k33).epsilon(1e-3));
}

TEST_CASE(
    "yamsc lin --rao: the CSV's spectra are |X|^2 S, the table's deviations their integrals") {
    driver::LinOptions o;
    o.model = std::string(YAMSC_SOURCE_DIR) + "/models/oc3_spar_hydrodyn.mbd";
    o.mooring = std::string(YAMSC_TEST_DATA_DIR) + "/mooring/oc3_hywind.map";
    o.hydro = std::string(YAMSC_TEST_DATA_DIR) + "/hydro/oc3_spar_strip.dat";
    o.sea_state = std::string(YAMSC_TEST_DATA_DIR) + "/hydro/oc3_sea_state.dat";
    o.trim = true;
    o.rao = std::string(YAMSC_TEST_BINARY_DIR) + "/oc3_spar_rao.csv";
    for (int k = 1; k <= 40; ++k) o.rao_frequencies.push_back(0.005 * k);
    std::ostringstream out, err;
    REQUIRE(analysis::lin(o, out, err) == 0);
    std::ifstream in(o.rao);
    std::string header, line;
    std::getline(in, header);
    CHECK(header.rfind("frequency_hz,omega_rad_s,wave_spectrum_m2s_rad,surge_abs,", 0) == 0);
    // Columns: f, w, S, then |X| and phase per DOF (heave's |X| is column 7), then
    // the spectra (heave's is column 17).
    std::vector<std::vector<double>> rows;
    while (std::getline(in, line)) {
        std::vector<double> row;
        std::stringstream s(line);
        for (std::string cell; std::getline(s, cell, ',');) row.push_back(std::stod(cell));
        REQUIRE(row.size() == 21);
        rows.push_back(row);
    }
    REQUIRE(rows.size() == 40);
    double variance = 0;
    for (std::size_t k = 0; k < rows.size(); ++k) {
        CHECK(rows[k][17] == doctest::Approx(rows[k][7] * rows[k][7] * rows[k][2]).epsilon(1e-7));
        if (k > 0)
            variance += 0.5 * (rows[k][1] - rows[k - 1][1]) * (rows[k][17] + rows[k - 1][17]);
    }
    // The table's heave row: name, max |X|, its frequency, standard deviation.
    const std::string table = out.str();
    const std::size_t at = table.find("\nheave ");
    REQUIRE(at != std::string::npos);
    std::stringstream heave(table.substr(at + 1));
    std::string name;
    double peak = 0, where = 0, deviation = 0;
    heave >> name >> peak >> where >> deviation;
    CHECK(deviation == doctest::Approx(std::sqrt(variance)).epsilon(1e-4));
    CHECK(deviation > 0.01);
}
