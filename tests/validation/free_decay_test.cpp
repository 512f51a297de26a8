// The paper's free-decay cases (sections 4.5 and 4.6) against OpenFAST: models written
// by `yamsc from-openfast` from the reference decks, simulated with the nonlinear
// generated code and with the linear model, compared with OpenFAST's outputs.
// Targets (issue 5): mean relative error, normalised by the reference's range, under
// 1 % (nonlinear) and 1.5 % (linear) on every DOF channel, R^2 above 0.99. The numbers
// measured are much better (docs/validation.md); the tight bounds below catch a
// regression long before the targets would.
#include "analysis/svg_plot.hpp"
#include "validation_support.hpp"

#include <yamsc/atomic_file.hpp>

#include <fstream>
#include <map>
#include <regex>

using namespace validation;
using yamsc::analysis::ChannelScore;
using yamsc::analysis::Comparison;
using yamsc::analysis::Table;

namespace {

struct Bounds {
    double nonlinear, linear; // mean relative error, fraction
};

/// Compares, checks, and records the scores for the report.
Comparison check_case(const Case& c, const Table& sim, bool linear, const Bounds& measured) {
    const Table reference = yamsc::analysis::read_table(reference_csv(c));
    const Comparison cmp = yamsc::analysis::compare_tables(sim, reference);
    const std::string report = c.model + (linear ? " linear\n" : " nonlinear\n") +
                               yamsc::analysis::format_comparison(cmp, reference_csv(c));
    MESSAGE(report);
    CHECK(cmp.missing.empty());
    for (const std::string& channel : c.channels) {
        CAPTURE(channel);
        const ChannelScore* s = nullptr;
        for (const ChannelScore& x : cmp.channels)
            if (x.name == channel) s = &x;
        REQUIRE(s);
        CHECK(s->samples == static_cast<std::size_t>(c.tmax / 0.01 + 1.5));
        CHECK(s->mean_rel_error < (linear ? 0.015 : 0.01)); // the targets of issue 5
        CHECK(s->r2 > 0.99);
        // What yamsc achieves today (docs/validation.md), with a little room.
        CHECK(s->mean_rel_error < (linear ? measured.linear : measured.nonlinear));
        CHECK(s->r2 > (linear ? 0.9995 : 0.99999));
    }
    return cmp;
}

/// OpenFAST, the nonlinear and the linear simulation of each channel, one panel each.
void plot(const Case& c, const Table& nonlinear, const Table& linear) {
    const Table reference = yamsc::analysis::read_table(reference_csv(c));
    std::vector<yamsc::analysis::PlotPanel> panels;
    for (const std::string& channel : c.channels) {
        yamsc::analysis::PlotPanel p;
        p.y_label = channel;
        const int n = nonlinear.find(channel), l = linear.find(channel),
                  r = reference.find(channel);
        REQUIRE((n > 0 && l > 0 && r > 0));
        p.series.push_back({"yamsc, nonlinear", nonlinear.data[0],
                            nonlinear.data[static_cast<std::size_t>(n)], false});
        p.series.push_back(
            {"yamsc, linear", linear.data[0], linear.data[static_cast<std::size_t>(l)], false});
        p.series.push_back(
            {"OpenFAST", reference.data[0], reference.data[static_cast<std::size_t>(r)], true});
        panels.push_back(std::move(p));
        // The differences, too small to see above.
        yamsc::analysis::PlotPanel e;
        e.y_label = "yamsc - OpenFAST, " + channel;
        for (const Table* sim : {&nonlinear, &linear}) {
            const int j = sim->find(channel);
            std::vector<double> diff;
            for (std::size_t i = 0; i < reference.rows(); ++i)
                diff.push_back(yamsc::analysis::interpolate(sim->data[0],
                                                            sim->data[static_cast<std::size_t>(j)],
                                                            reference.data[0][i]) -
                               reference.data[static_cast<std::size_t>(r)][i]);
            e.series.push_back({sim == &nonlinear ? "yamsc, nonlinear" : "yamsc, linear",
                                reference.data[0], diff, false});
        }
        panels.push_back(std::move(e));
    }
    yamsc::analysis::PlotOptions o;
    o.panel_height = 150;
    o.title = "Free decay: " + c.folder + " (yamsc vs OpenFAST)";
    yamsc::runtime::write_file_atomically(work_dir + "/" + c.model + ".svg",
                                          yamsc::analysis::svg_plot(panels, o));
}

std::vector<double> frequencies(const std::string& text) {
    // "linear model about ...; modes [Hz]: 0.100658 0.799966"
    std::vector<double> f;
    const auto at = text.find("modes [Hz]:");
    REQUIRE(at != std::string::npos);
    std::istringstream in(text.substr(at + 11, text.find('\n', at) - at - 11));
    for (double v; in >> v;) f.push_back(v);
    return f;
}

} // namespace

TEST_CASE("land-based 3 DOF (tower FA1, SS1, generator azimuth at 10 rpm) agrees with OpenFAST") {
    convert(land_case);
    std::string log;
    const Table nonlinear = simulate(land_case, false);
    const Table linear = simulate(land_case, true, &log);
    check_case(land_case, nonlinear, false, {0.001, 0.003});
    check_case(land_case, linear, true, {0.001, 0.003});
    // Tower fore-aft and side-side, split by the gyroscopic coupling of the rotor.
    const std::vector<double> f = frequencies(log);
    REQUIRE(f.size() == 2);
    CHECK(f[0] == doctest::Approx(0.4550).epsilon(0.002));
    CHECK(f[1] == doctest::Approx(0.4681).epsilon(0.002));
    plot(land_case, nonlinear, linear);
}

TEST_CASE("floating 3 DOF (surge, pitch, tower FA1) agrees with OpenFAST; linear frequencies") {
    convert(floating_case);
    std::string log;
    const Table nonlinear = simulate(floating_case, false);
    const Table linear = simulate(floating_case, true, &log);
    check_case(floating_case, nonlinear, false, {0.001, 0.007});
    check_case(floating_case, linear, true, {0.001, 0.007});
    // The paper: 0.099 Hz (pitch) and 0.799 Hz (tower); OpenFAST's linearization 0.095 and
    // 0.795 Hz. yamsc: 0.1007 and 0.8000 Hz (the nonlinear time series, which matches
    // OpenFAST's to 0.02 %, has the pitch frequency of yamsc's linear model, not 0.095).
    const std::vector<double> f = frequencies(log);
    REQUIRE(f.size() == 2);
    CHECK(f[0] == doctest::Approx(0.099).epsilon(0.025));
    CHECK(f[1] == doctest::Approx(0.799).epsilon(0.002));
    CHECK(f[0] == doctest::Approx(0.1007).epsilon(0.001));
    CHECK(f[1] == doctest::Approx(0.8000).epsilon(0.001));
    plot(floating_case, nonlinear, linear);
}

TEST_CASE("land-based 16 DOF (every ElastoDyn DOF, 30 s): DOF channels against OpenFAST") {
    // The full onshore NREL 5-MW: tower 2+2 modes, yaw, generator, drivetrain, three
    // blades with flap 1, edge 1, flap 2 (issue 13), nonlinear only (the generated
    // model compiles in about a minute). Bounds: what yamsc achieves today
    // (docs/validation.md) with a little room; the target, 1 % on every
    // channel, is met (the yaw angle, 0.95 %, is the closest).
    // Also with OpenFAST's own integrator and step (ABM4, DT 0.005, rows every
    // 0.01 s): the same bounds (the library is compiled once for both runs).
    const Case& c = land_16dof_case;
    convert(c);
    for (const bool abm4 : {false, true}) {
        CAPTURE(abm4);
        const Table sim =
            abm4 ? simulate(c, false, nullptr, yamsc::driver::SimMethod::abm4, 0.005, 0.01)
                 : simulate(c, false);
        const Table reference = yamsc::analysis::read_table(reference_csv(c));
        const Comparison cmp = yamsc::analysis::compare_tables(sim, reference);
        const std::string report = c.model +
                                   (abm4 ? " nonlinear, ABM4 dt 0.005\n" : " nonlinear\n") +
                                   yamsc::analysis::format_comparison(cmp, reference_csv(c));
        MESSAGE(report);
        const std::map<std::string, double> bounds{
            // the DOFs
            {"Q_TFA1_[m]", 0.0003},
            {"Q_TSS1_[m]", 0.001},
            {"Q_TFA2_[m]", 0.004},
            {"Q_TSS2_[m]", 0.0012},
            {"NacYaw_[deg]", 0.0099},
            {"RotSpeed_[rpm]", 0.0013},
            {"Q_DrTr_[rad]", 0.0006},
            {"Q_B1F1_[m]", 0.0033},
            {"Q_B1E1_[m]", 0.0014},
            {"Q_B1F2_[m]", 0.0033},
            {"Q_B2F1_[m]", 0.003},
            {"Q_B2E1_[m]", 0.0011},
            {"Q_B2F2_[m]", 0.003},
            {"Q_B3F1_[m]", 0.0028},
            {"Q_B3E1_[m]", 0.0013},
            {"Q_B3F2_[m]", 0.003},
            // ElastoDyn's displacement channels (docs/openfast.md)
            {"TTDspFA_[m]", 0.0003},
            {"TTDspSS_[m]", 0.001},
            {"OoPDefl1_[m]", 0.0033},
            {"IPDefl1_[m]", 0.0014},
            {"OoPDefl2_[m]", 0.0032},
            {"IPDefl2_[m]", 0.001},
            {"OoPDefl3_[m]", 0.003},
            {"IPDefl3_[m]", 0.0012},
            {"TipDzc1_[m]", 0.003}};
        // ElastoDyn's load channels from the joints' reactions (measured 0.02-0.68 %);
        // the target of issue 13 for these is 2 %.
        const std::map<std::string, double> load_bounds{
            {"TwrBsMxt_[kN-m]", 0.001},  {"TwrBsMyt_[kN-m]", 0.0005},  {"TwrBsMzt_[kN-m]", 0.0017},
            {"YawBrMxp_[kN-m]", 0.0012}, {"YawBrMyp_[kN-m]", 0.004},   {"RootMxc1_[kN-m]", 0.0016},
            {"RootMyc1_[kN-m]", 0.003},  {"RootMzc1_[kN-m]", 0.009},   {"LSShftMxa_[kN-m]", 0.0006},
            {"LSSGagMya_[kN-m]", 0.003}, {"LSSGagMza_[kN-m]", 0.0025}, {"RotThrust_[kN]", 0.0015},
            {"RotTorq_[kN-m]", 0.0006}};
        auto score = [&](const std::string& channel) {
            const ChannelScore* s = nullptr;
            for (const ChannelScore& x : cmp.channels)
                if (x.name == channel) s = &x;
            REQUIRE(s);
            CHECK(s->samples == static_cast<std::size_t>(c.tmax / 0.01 + 1.5));
            return s->mean_rel_error;
        };
        for (const auto& [channel, bound] : bounds) {
            CAPTURE(channel);
            const double error = score(channel);
            CHECK(error < bound);
            CHECK(error < 0.01); // the target of issue 13
        }
        for (const auto& [channel, bound] : load_bounds) {
            CAPTURE(channel);
            const double error = score(channel);
            CHECK(error < bound);
            CHECK(error < 0.02); // the target of issue 13 for loads
        }
        // R^2 (target 0.99): the drivetrain chain, which the Coriolis forces of the blades'
        // radial shortening brought from 0.985 to 0.9999 (docs/validation.md), and the rest.
        const std::map<std::string, double> r2_bounds{
            {"Q_DrTr_[rad]", 0.9999},    {"QD_DrTr_[rad/s]", 0.9998},  {"LSShftMxa_[kN-m]", 0.9999},
            {"RotSpeed_[rpm]", 0.99995}, {"QD_GeAz_[rad/s]", 0.99995}, {"Q_B1E1_[m]", 0.9999},
            {"NacYaw_[deg]", 0.998},     {"RootMzc1_[kN-m]", 0.993}};
        for (const auto& [channel, bound] : r2_bounds) {
            CAPTURE(channel);
            const ChannelScore* s = nullptr;
            for (const ChannelScore& x : cmp.channels)
                if (x.name == channel) s = &x;
            REQUIRE(s);
            CHECK(s->r2 > bound);
        }
        // ElastoDyn's initial blade deflection: OoPDefl = 2 m on the twisted blade.
        const int f1 = sim.find("Q_B1F1_[m]"), e1 = sim.find("Q_B1E1_[m]");
        REQUIRE((f1 > 0 && e1 > 0));
        CHECK(sim.data[static_cast<std::size_t>(f1)][0] ==
              doctest::Approx(1.9752467222).epsilon(1e-9));
        CHECK(sim.data[static_cast<std::size_t>(e1)][0] ==
              doctest::Approx(0.25352369297).epsilon(1e-9));
    }
}

TEST_CASE("parked 15 DOF: the linear model has OpenFAST's linearization frequencies") {
    // OpenFAST v5's linearization of the 16-DOF deck with the rotor parked and the
    // generator locked (tests/data/reference/linearization/parked_modes.csv), about
    // the undeflected state; `yamsc lin` about the same point.
    const Case parked{
        "linearization/decks/A_parked", "land_parked", 0, {}, "NREL5MW_Onshore_FreeDecay.fst"};
    convert(parked);
    yamsc::driver::LinOptions o;
    o.model = model_path(parked);
    std::ostringstream out, err;
    REQUIRE(yamsc::analysis::lin(o, out, err) == 0);
    std::vector<double> f;
    std::istringstream lines(out.str());
    for (std::string line; std::getline(lines, line);) {
        std::istringstream row(line);
        int mode = 0;
        double hz = 0;
        if (row >> mode >> hz) f.push_back(hz);
    }
    MESSAGE(out.str());
    const std::vector<double> openfast{0.001889, 0.313956, 0.324409, 0.620993, 0.666692,
                                       0.699050, 0.960129, 1.083600, 1.160541, 1.911082,
                                       2.007350, 2.538394, 2.916144, 2.954968, 3.687862};
    REQUIRE(f.size() == openfast.size());
    CHECK(f[0] < 0.002); // free yaw: a near-zero root
    for (std::size_t i = 1; i < f.size(); ++i) {
        CAPTURE(i);
        CHECK(f[i] == doctest::Approx(openfast[i]).epsilon(2e-4)); // measured: <= 1e-4
    }
}
