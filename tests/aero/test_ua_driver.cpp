// UA_Mod 3 and 6 against OpenFAST's unsteady-aerodynamics driver on the DU25 airfoil
// pitching 8 +- 8 deg at 1 Hz (chord 3 m, 60 m/s): Cl, Cd and Cm within 2 % of their
// range over the run.
#include "ua_reference.hpp"
#include "yamsc/aero/unsteady_airfoil.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

using namespace yamsc::aero;
using namespace ua_reference;

namespace {

struct Series {
    std::vector<double> cl, cd, cm;
};

// Largest |error| over the run relative to the reference's range.
double error_of_range(const std::vector<double>& ours, const std::vector<double>& ref) {
    const auto [lo, hi] = std::minmax_element(ref.begin(), ref.end());
    double e = 0;
    for (std::size_t i = 0; i < ref.size(); ++i) e = std::max(e, std::abs(ours.at(i) - ref[i]));
    return e / (*hi - *lo);
}

void check(const Series& s, const Csv& ref) {
    const double ecl = error_of_range(s.cl, ref["Cl_[-]"]);
    const double ecd = error_of_range(s.cd, ref["Cd_[-]"]);
    const double ecm = error_of_range(s.cm, ref["Cm_[-]"]);
    MESSAGE("max error / range: Cl " << ecl << ", Cd " << ecd << ", Cm " << ecm);
    CHECK(ecl < 0.02);
    CHECK(ecd < 0.02);
    CHECK(ecm < 0.02);
}

Airfoil du25(UnsteadyModel model) {
    return read_airfoil(data("reference/operating/deck/Airfoils/DU25_A17.dat"), model);
}

UnsteadySettings settings(UnsteadyModel model) {
    UnsteadySettings s; // the driver's: SpdSound 335 m/s, FLookup, d_34_to_ac 0.5, ABM4
    s.model = model;
    return s;
}

} // namespace

TEST_CASE("UA_Mod 3 (Minnema/Pierce) follows OpenFAST's driver on the pitching DU25") {
    const Driver d;
    const Csv ref = read_csv(data("reference/aero/ua3_DU25_m8_a8_f1.csv"));
    const UnsteadyAirfoil af(du25(UnsteadyModel::minnema_pierce));
    const UnsteadySettings s = settings(UnsteadyModel::minnema_pierce);
    MinnemaPierceState x;
    Series out;
    std::vector<double> fpp, cn_v, tau_v, alpha_filt;
    for (int n = 1; n <= d.steps(); ++n) {
        const UnsteadyInput u = driver_input(d, n);
        const UnsteadyOutput y0 = evaluate(af, s, d.chord, d.dt(), u, x);
        const UnsteadyOutput y = step(af, s, d.chord, d.dt(), u, x);
        CHECK(y0.cl == y.cl); // evaluate gives step's outputs without the update
        out.cl.push_back(y.cl);
        out.cd.push_back(y.cd);
        out.cm.push_back(y.cm);
        fpp.push_back(y.fprimeprime);
        cn_v.push_back(y.cn_v);
        tau_v.push_back(y.tau_V);
        alpha_filt.push_back(y.alpha_filt / deg);
    }
    REQUIRE(ref["Cl_[-]"].size() == out.cl.size());
    check(out, ref);
    // The internal states behind them: separation point, vortex lift and its time, and
    // the filtered angle of attack.
    CHECK(error_of_range(fpp, ref["fprimeprime_[-]"]) < 1e-4);
    CHECK(error_of_range(cn_v, ref["Cn_v_[-]"]) < 1e-4);
    CHECK(error_of_range(tau_v, ref["Tau_V_[-]"]) < 1e-4);
    CHECK(error_of_range(alpha_filt, ref["ALPHA_filt_[deg]"]) < 1e-4);
}

TEST_CASE("UA_Mod 6 (Oye) follows OpenFAST's driver on the pitching DU25") {
    const Driver d;
    const Csv ref = read_csv(data("reference/aero/ua6_DU25_m8_a8_f1.csv"));
    const UnsteadyAirfoil af(du25(UnsteadyModel::oye));
    const UnsteadySettings s = settings(UnsteadyModel::oye);
    OyeState x;
    x.n = 1; // the driver counts its steps from 1
    Series out;
    double ex4 = 0;
    for (int n = 1; n <= d.steps(); ++n) {
        const UnsteadyInput u = driver_input(d, n);
        const UnsteadyOutput y = evaluate(af, s, d.chord, u, x);
        out.cl.push_back(y.cl);
        out.cd.push_back(y.cd);
        out.cm.push_back(y.cm);
        ex4 = std::max(ex4, std::abs(y.x4 - ref["x4_[-]"].at(n - 1)));
        step(af, s, d.chord, d.dt(), u, driver_input(d, n + 1), x);
    }
    MESSAGE("max |x4 error| " << ex4);
    CHECK(ex4 < 1e-3);
    check(out, ref);
}

TEST_CASE("AirfoilInfo's defaults of the attached range give the driver's Cl slope") {
    // The DU25 file omits C_lalpha, alphaUpper and alphaLower: AirfoilInfo fits them.
    // Oye's fully attached Cl, (alpha_E - alpha0) C_lalpha, in the driver's output
    // gives the slope it used.
    const Csv ref = read_csv(data("reference/aero/ua6_DU25_m8_a8_f1.csv"));
    const Airfoil af = du25(UnsteadyModel::oye);
    const auto& k = *af.tables.front().unsteady;
    const double alpha_e = ref["alphaE_[deg]"].at(0) * deg;
    CHECK(k.C_lalpha ==
          doctest::Approx(ref["cl_fa_[-]"].at(0) / (alpha_e - k.alpha0)).epsilon(1e-4));
    CHECK(k.alphaLower < k.alpha0);
    CHECK(k.alphaUpper > k.alpha0);
    MESSAGE("DU25 defaults: C_lalpha " << k.C_lalpha << " /rad, alphaLower " << k.alphaLower / deg
                                       << " deg, alphaUpper " << k.alphaUpper / deg << " deg");
}
