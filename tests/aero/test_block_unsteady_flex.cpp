// Unsteady airfoil aerodynamics (UA_Mod 3) and dynamic inflow (DBEMT_Mod 2) inside
// `load blade_elements` on the flexible NREL 5-MW (blades and tower flexible, rotor
// speed and pitch fixed: GenDOF, DrTrDOF, YawDOF off), simulated as `yamsc sim` does
// with the deck's AeroDyn file, against OpenFAST (data/reference/aero/flex_U8.csv,
// flex_U16.csv): the means and standard deviations of the last 20 s of 80 s.
#include "analysis/commands.hpp"
#include "block_unsteady_support.hpp"

#include <chrono>
#include <cstdio>

using namespace block_unsteady;

namespace {

struct Stats {
    double mean = 0, std = 0;
};

/// Over the rows with t in (t_end - 20, t_end].
Stats last_20_s(const std::vector<double>& time, const std::vector<double>& y) {
    const double t_end = time.back();
    double s = 0, s2 = 0;
    int n = 0;
    for (std::size_t i = 0; i < time.size(); ++i)
        if (time[i] > t_end - 20 + 1e-6) {
            s += y[i];
            s2 += y[i] * y[i];
            ++n;
        }
    const double mean = s / n;
    return {mean, std::sqrt(std::max(0.0, s2 / n - mean * mean))};
}

struct Case {
    const char* reference;
    const char* wind;
    double rpm, pitch_deg;
};

void compare(const Case& c) {
    CAPTURE(c.reference);
    static const std::string deck = deck_copy("block_unsteady_flex", {});
    const std::string dir = test_support::scratch_dir("aero", "block_unsteady_flex_run");
    yamsc::driver::FromOpenFastOptions f;
    f.deck = deck + "/NREL-5MW.fst";
    f.output = dir + "/flex.mbd";
    f.dofs = {{"GenDOF", false}, {"DrTrDOF", false}, {"YawDOF", false}};
    std::ostringstream out, err;
    REQUIRE_MESSAGE(yamsc::openfast::from_openfast(f, out, err) == 0, err.str());

    yamsc::driver::SimOptions o;
    o.model = f.output;
    o.tmax = 80;
    o.dt = 0.00625;
    o.dt_out = 0.1;
    o.set = {{"Omega0", 0, c.rpm * M_PI / 30}};
    o.u = {{"pitch", 0, c.pitch_deg * M_PI / 180}};
    o.aero = deck + "/NRELOffshrBsline5MW_Onshore_AeroDyn15.dat";
    o.wind = c.wind;
    o.method = yamsc::driver::SimMethod::abm4; // ElastoDyn's Method 3
    o.channels = yamsc::driver::Channels::openfast;
    o.output = dir + "/flex.csv";
    const auto start = std::chrono::steady_clock::now();
    REQUIRE_MESSAGE(yamsc::analysis::sim(o, out, err) == 0, err.str());
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    const auto got = read_columns(o.output);
    const auto ref = read_reference(c.reference);
    for (const char* name : {"RotThrust", "RtFldPwr", "OoPDefl1", "TTDspFA", "RootMyc1"}) {
        const Stats y = last_20_s(got.at("Time"), got.at(name));
        const Stats r = last_20_s(ref.at("Time"), ref.at(name));
        std::printf("block %s %-10s mean %.6g (OpenFAST %.6g, %+.3f %%)  std %.4g (%.4g, %+.1f "
                    "%%)\n",
                    c.reference, name, y.mean, r.mean, 100 * (y.mean / r.mean - 1), y.std, r.std,
                    100 * (y.std / r.std - 1));
        CHECK_MESSAGE(std::abs(y.mean / r.mean - 1) < 0.01, name);
        CHECK_MESSAGE(std::abs(y.std / r.std - 1) < 0.05, name);
    }
    std::printf("block %s: 80 s in %.1f s\n", c.reference, seconds);
}

} // namespace

TEST_CASE("the flexible rotor with UA_Mod 3 and DBEMT_Mod 2 at 8 m/s matches OpenFAST") {
    compare({"flex_U8.csv", "8", 8.9886, 0.0});
}

TEST_CASE("the flexible rotor with UA_Mod 3 and DBEMT_Mod 2 at 16 m/s matches OpenFAST") {
    compare({"flex_U16.csv", "16", 12.1, 11.535});
}
