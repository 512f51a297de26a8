// Unsteady airfoil aerodynamics (UA_Mod 3) and dynamic inflow (DBEMT_Mod 2) inside
// `load blade_elements` on the flexible NREL 5-MW (blades and tower flexible, rotor
// speed and pitch fixed: GenDOF, DrTrDOF, YawDOF off), simulated as `yamsc sim` does
// with the deck's AeroDyn file, against OpenFAST (every flexible run of
// data/reference/aero/cases.txt: flex_U8.csv, flex_U16.csv): the means and standard
// deviations of the last 20 s of 80 s.
#include "analysis/commands.hpp"
#include "block_unsteady_support.hpp"
#include "reference_cases.hpp"

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

using reference_cases::Case;

using Columns = std::map<std::string, std::vector<double>>;

/// The run of `c` (once per test process): from undeflected blades and tower, as
/// the reference, the blades pitched in the structure (ElastoDyn's BlPitch) and in
/// the block (the pitch input), as long as the reference (80 s given) and with its
/// rows (every 0.1 s), with ElastoDyn's ABM4.
const Columns& run(const Case& c) {
    static std::map<std::string, Columns> runs;
    if (runs.count(c.file)) return runs[c.file];
    reference_cases::Settings settings = c.settings;
    for (const char* b : {"BlPitch(1)", "BlPitch(2)", "BlPitch(3)"})
        settings.emplace_back(b, std::to_string(c.pitch_deg));
    const std::string deck = reference_cases::deck("block_unsteady_" + c.name(), settings);
    yamsc::driver::FromOpenFastOptions f;
    f.deck = deck + "/NREL-5MW.fst";
    f.output = deck + "/flex.mbd";
    f.dofs = {{"GenDOF", false}, {"DrTrDOF", false}, {"YawDOF", false}};
    std::ostringstream out, err;
    REQUIRE_MESSAGE(yamsc::openfast::from_openfast(f, out, err) == 0, err.str());

    yamsc::driver::SimOptions o;
    o.model = f.output;
    const std::vector<double> time = reference_cases::column(c.path(), "Time");
    o.tmax = time.back();
    o.dt = 0.00625;
    o.dt_out = time.at(1) - time.at(0);
    o.set = {{"Omega0", 0, c.rpm * M_PI / 30}};
    o.u = {{"pitch", 0, c.pitch_deg * M_PI / 180}};
    for (const char* q : {"q_fa1", "q_ss1", "q_b1_flap1", "q_b1_edge1", "q_b2_flap1", "q_b2_edge1",
                          "q_b3_flap1", "q_b3_edge1"})
        o.ic.push_back({q, 0, 0.0}); // the deck's initial deflections: the reference starts at 0
    o.aero = deck + "/NRELOffshrBsline5MW_Onshore_AeroDyn15.dat";
    o.wind = std::to_string(c.wind);
    o.method = yamsc::driver::SimMethod::abm4; // ElastoDyn's Method 3
    o.channels = yamsc::driver::Channels::openfast;
    o.output = deck + "/flex.csv";
    const auto start = std::chrono::steady_clock::now();
    REQUIRE_MESSAGE(yamsc::analysis::sim(o, out, err) == 0, err.str());
    std::printf("block %s: %.0f s in %.1f s\n", c.file.c_str(), o.tmax,
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    return runs[c.file] = read_columns(o.output);
}

/// Means within 1 % and standard deviations within 5 % of the reference's.
void compare(const Case& c, const std::vector<std::string>& means,
             const std::vector<std::string>& stds) {
    CAPTURE(c.file);
    const Columns& got = run(c);
    const auto ref = read_columns(c.path());
    for (const std::string& name : means) {
        const Stats y = last_20_s(got.at("Time"), got.at(name));
        const Stats r = last_20_s(ref.at("Time"), ref.at(name));
        std::printf("block %s %-10s mean %.6g (OpenFAST %.6g, %+.3f %%)  std %.4g (%.4g, %+.1f "
                    "%%)\n",
                    c.file.c_str(), name.c_str(), y.mean, r.mean, 100 * (y.mean / r.mean - 1),
                    y.std, r.std, 100 * (y.std / r.std - 1));
        CHECK_MESSAGE(std::abs(y.mean / r.mean - 1) < 0.01, name);
        if (std::find(stds.begin(), stds.end(), name) != stds.end())
            CHECK_MESSAGE(std::abs(y.std / r.std - 1) < 0.05, name);
    }
}

// The rotor's aerodynamics: with UA_Mod 3 the thick inboard airfoils' Cl (B1N3, B1N5:
// AeroDyn's nodes 7 and 11, DU40 and DU35) as OpenFAST's; quasi-steady they were
// 9-12 % high (RtFldCp +5.6 % at 8 m/s).
const std::vector<std::string> aero_means = {"RtFldPwr", "RtFldFxh", "RtFldCp", "RtFldCt",
                                             "B1N2Cl",   "B1N3Cl",   "B1N4Cl",  "B1N5Cl"};
const std::vector<std::string> aero_stds = {"RtFldCp", "RtFldCt"};
// The structure's response: thrust, power, tip deflection, tower top and root
// moment, the tolerances.
const std::vector<std::string> structure = {"RotThrust", "RtFldPwr", "OoPDefl1", "TTDspFA",
                                            "RootMyc1"};

} // namespace

TEST_CASE("the flexible rotor's aerodynamics with UA_Mod 3 and DBEMT_Mod 2 match OpenFAST") {
    for (const Case& c : reference_cases::cases(reference_cases::Kind::flexible))
        compare(c, aero_means, aero_stds);
}

TEST_CASE("the flexible rotor's structural response matches OpenFAST") {
    for (const Case& c : reference_cases::cases(reference_cases::Kind::flexible))
        compare(c, structure, structure);
}
