// UA_Mod 3 and 6 against OpenFAST's unsteady-aerodynamics driver, every driver run of
// data/reference/aero/cases.txt with its .dvr (the given ones: the DU25 airfoil
// pitching 8 +- 8 deg at 1 Hz, chord 3 m, 60 m/s): Cl, Cd and Cm within 2 % of their
// range over the run.
#include "reference_cases.hpp"
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

UnsteadySettings settings(const Driver& d) {
    UnsteadySettings s; // ABM4 for UA_Mod 6, as the driver integrates
    s.model = d.model;
    s.f_lookup = d.f_lookup;
    s.speed_of_sound = d.speed_of_sound;
    s.d_34_to_ac = d.d_34_to_ac;
    return s;
}

void minnema_pierce(const Driver& d, const Csv& ref) {
    const UnsteadyAirfoil af(
        read_airfoil(data("reference/operating/deck/" + d.airfoil), UnsteadyModel::minnema_pierce));
    const UnsteadySettings s = settings(d);
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

void oye(const Driver& d, const Csv& ref) {
    const UnsteadyAirfoil af(
        read_airfoil(data("reference/operating/deck/" + d.airfoil), UnsteadyModel::oye));
    const UnsteadySettings s = settings(d);
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
    REQUIRE(ref["Cl_[-]"].size() == out.cl.size());
    MESSAGE("max |x4 error| " << ex4);
    CHECK(ex4 < 1e-3);
    check(out, ref);
}

/// Every driver run of `model` in the manifest (a run of another UAMod fails: not modelled).
int run_all(UnsteadyModel model) {
    int runs = 0;
    for (const reference_cases::Case& c :
         reference_cases::cases(reference_cases::Kind::ua_driver)) {
        CAPTURE(c.file);
        const Driver d = read_driver(reference_cases::aero_dir + c.name() + ".dvr");
        REQUIRE_MESSAGE((d.model == UnsteadyModel::minnema_pierce || d.model == UnsteadyModel::oye),
                        "UAMod " << static_cast<int>(d.model) << " is not modelled");
        if (d.model != model) continue;
        const Csv ref = read_csv(c.path());
        if (model == UnsteadyModel::oye)
            oye(d, ref);
        else
            minnema_pierce(d, ref);
        ++runs;
    }
    return runs;
}

} // namespace

TEST_CASE("UA_Mod 3 (Minnema/Pierce) follows OpenFAST's driver on every pitching airfoil run") {
    CHECK(run_all(UnsteadyModel::minnema_pierce) >= 1);
}

TEST_CASE("UA_Mod 6 (Oye) follows OpenFAST's driver on every pitching airfoil run") {
    CHECK(run_all(UnsteadyModel::oye) >= 1);
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
