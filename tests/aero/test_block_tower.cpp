// The tower inside `load blade_elements` on the NREL 5-MW structure
// from-openfast writes (its flexible tower bound to the block's `tower` role),
// with the deck's tower table as the AeroDyn reader reads it: the tower's
// potential flow through the model's kinematics against OpenFAST's disk-averaged
// wind (every tower run of data/reference/aero/cases.txt less its flexible run:
// twr_U8 - flex_U8 given), and the drag set on the tower against its closed form.
#include "analysis/load_blocks.hpp"
#include "analysis/loaded_model.hpp"
#include "openfast/from_openfast.hpp"
#include "reference_cases.hpp"
#include "test_files.hpp"
#include "tower_reference.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>

namespace {

const std::string aerodyn_file = reference_cases::aerodyn_file;

/// The deck as it is (TwrPotent 0, TwrAero False), copied once.
const std::string& plain_deck() {
    static const std::string dir = reference_cases::deck("block_tower_plain", {});
    return dir;
}

/// The deck's model (flexible tower and blades) from-openfast writes, loaded
/// once: the AeroDyn file is the blocks' option, not the model's.
const yamsc::analysis::Loaded& five_mw() {
    static const std::optional<yamsc::analysis::Loaded> loaded = [] {
        const std::string dir = test_support::scratch_dir("aero", "block_tower_model");
        yamsc::driver::FromOpenFastOptions o;
        o.deck = plain_deck() + "/NREL-5MW.fst";
        o.output = dir + "/full.mbd";
        std::ostringstream out, err;
        REQUIRE_MESSAGE(yamsc::openfast::from_openfast(o, out, err) == 0, err.str());
        REQUIRE(test_support::read_file(o.output).find("    tower = tower\n") != std::string::npos);
        auto l =
            yamsc::analysis::load(o.output, {}, "", false, err, {}, yamsc::codegen::abi_routines());
        REQUIRE_MESSAGE(l, err.str());
        return l;
    }();
    return *loaded;
}

std::size_t index_of(const std::vector<std::string>& names, const std::string& name) {
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return i;
    FAIL("no channel " << name);
    return 0;
}

/// The disk-averaged wind the tower run's AeroDyn entries change, at its mean
/// deflections (its last 20 s: tower and blades), in the block; OpenFAST's
/// change (tower run less its flexible run) and the spread of its 10-s halves.
struct WindChange {
    double block = 0, reference = 0, spread = 0;
};
WindChange wind_change(const reference_cases::Case& c) {
    CAPTURE(c.file);
    const reference_cases::Case base = reference_cases::base_run(c);
    const yamsc::analysis::Loaded& l = five_mw();
    const std::string plain = reference_cases::deck("block_tower_" + base.name(), base.settings);
    const std::string tower = reference_cases::deck("block_tower_" + c.name(), c.settings);
    yamsc::analysis::BlockOptions without, with;
    without.aero = plain + aerodyn_file;
    with.aero = tower + aerodyn_file;
    const yamsc::runtime::ModelView v0 = yamsc::analysis::with_load_blocks(l, without);
    const yamsc::runtime::ModelView v1 = yamsc::analysis::with_load_blocks(l, with);
    REQUIRE(v0.nu == v1.nu);

    const double from = reference_cases::last_20_s(c);
    const yamsc::table::Table flex = yamsc::table::read_table(base.path());
    const yamsc::table::Table twr = yamsc::table::read_table(c.path());
    auto mean = [&](const char* column) {
        return tower_reference::statistics(twr, column, from).mean;
    };
    std::vector<double> q(static_cast<std::size_t>(v0.nq), 0.0),
        qd = q, u(static_cast<std::size_t>(v0.nu), 0.0), y0(static_cast<std::size_t>(v0.ny)),
        y1(static_cast<std::size_t>(v1.ny));
    q[index_of(v0.dof_names, "q_fa1")] = mean("Q_TFA1_[m]");
    q[index_of(v0.dof_names, "q_ss1")] = mean("Q_TSS1_[m]");
    for (int k = 1; k <= 3; ++k) {
        const std::string b = "q_b" + std::to_string(k) + "_";
        q[index_of(v0.dof_names, b + "flap1")] = mean("Q_B1F1_[m]");
        q[index_of(v0.dof_names, b + "edge1")] = mean("Q_B1E1_[m]");
        q[index_of(v0.dof_names, b + "flap2")] = mean("Q_B1F2_[m]");
    }
    const double omega = c.rpm * M_PI / 30;
    qd[index_of(v0.dof_names, "psi")] = omega;
    u[index_of(v0.input_names, "V_wind")] = c.wind;
    u[index_of(v0.input_names, "pitch")] = c.pitch_deg * M_PI / 180;
    const std::size_t psi = index_of(v0.dof_names, "psi");
    const std::size_t wind_avg = index_of(v0.output_names, "RtVAvgxh");

    // The rotor turned through a third of a revolution (the three blades pass
    // the tower once each), 1 deg apart.
    const int steps = 120;
    WindChange w;
    for (int k = 0; k < steps; ++k) {
        q[psi] = k * M_PI / 180;
        v0.outputs(0.0, q.data(), qd.data(), u.data(), y0.data());
        v1.outputs(0.0, q.data(), qd.data(), u.data(), y1.data());
        w.block += (y1[wind_avg] - y0[wind_avg]) / steps;
    }
    // OpenFAST's change over the last 20 s, known to within the spread of its
    // two 10-s halves (test_tower_influence.cpp: rows every 0.1 s sample the
    // 0.3-s dips unevenly).
    w.reference = tower_reference::effect(flex, twr, from).rotor_wind_change;
    w.spread =
        tower_reference::change_spread(flex, twr, "RtVAvgxh_[m/s]", {from, from + 10, from + 21});
    MESSAGE("RtVAvgxh change: block " << w.block << " m/s, OpenFAST " << w.reference << " +- "
                                      << w.spread);
    return w;
}

} // namespace

TEST_CASE("the blade-element block's tower: OpenFAST's disk-averaged wind change and the drag") {
    for (const reference_cases::Case& c : reference_cases::cases(reference_cases::Kind::tower)) {
        const WindChange w = wind_change(c);
        CHECK(std::abs(w.block - w.reference) < w.spread);
        // twr_U8's: the tower functions' own figure on the rotor's geometry with
        // quadratic deflections (test_tower_influence.cpp), -0.04117 m/s.
        if (c.file == "twr_U8.csv") CHECK(w.block == doctest::Approx(-0.04117).epsilon(0.01));
    }
}

TEST_CASE("the blade-element block's tower drag reaches the tower as its distributed load") {
    // Only the drag (TwrAero), on the undeflected turbine in 8 m/s: the tower's
    // mesh inputs (force and moment at its base in its axes) carry the total of
    // the drag per length, linear between AeroDyn's tower nodes, and its moment
    // about the base; 16.85 kN and 683.2 kN m (test_tower_drag.cpp).
    const std::string drag = reference_cases::deck("block_tower_drag", {{"TwrAero", "True"}});
    const yamsc::analysis::Loaded& l = five_mw();
    yamsc::analysis::BlockOptions options;
    options.aero = drag + aerodyn_file;
    const yamsc::runtime::ModelView& v = l.view;
    const yamsc::runtime::LoadBlocks blocks = yamsc::analysis::load_blocks(l, v, l.params, options);
    REQUIRE(blocks.size() == 1);
    const yamsc::runtime::LoadBlock& block = *blocks.front();
    const yamsc::runtime::BlockPorts& ports = block.ports();

    std::vector<double> q(static_cast<std::size_t>(v.nq), 0.0),
        qd = q, u(static_cast<std::size_t>(v.nu), 0.0), y(static_cast<std::size_t>(v.ny));
    qd[index_of(v.dof_names, "psi")] = 8.988566 * M_PI / 30;
    u[index_of(v.input_names, "V_wind")] = 8.0;
    v.outputs(0.0, q.data(), qd.data(), u.data(), y.data());
    std::vector<double> r;
    for (int o : ports.outputs_read) r.push_back(y[static_cast<std::size_t>(o)]);
    for (int i : ports.inputs_read) r.push_back(i < 0 ? 0.0 : u[static_cast<std::size_t>(i)]);
    std::vector<double> loads(ports.loads.size()), out(block.output_names().size());
    block.evaluate(0.0, nullptr, r.data(), loads.data(), nullptr, out.data());

    // The tower's inputs: the last of the block's loads, force and moment first.
    std::size_t first = 0;
    while (first < ports.loads.size() &&
           v.input_names[static_cast<std::size_t>(ports.loads[first])].rfind("aero.tower.", 0) != 0)
        ++first;
    REQUIRE(ports.loads.size() - first == 6 + 4); // the tower's four modes
    const double* tower = loads.data() + first;

    // The closed form: 1/2 rho Cd D U^2 per length at each node, linear between.
    const std::vector<yamsc::aero::TowerNode> table = tower_reference::five_mw_tower_table();
    double force = 0, moment = 0;
    auto f = [&](const yamsc::aero::TowerNode& n) { return 0.5 * 1.225 * n.cd * n.diameter * 64; };
    for (std::size_t j = 0; j + 1 < table.size(); ++j) {
        const double z1 = table[j].elevation, z2 = table[j + 1].elevation, len = z2 - z1;
        force += len / 2 * (f(table[j]) + f(table[j + 1]));
        moment += len / 6 * ((2 * z1 + z2) * f(table[j]) + (z1 + 2 * z2) * f(table[j + 1]));
    }
    CHECK(force == doctest::Approx(16850).epsilon(1e-3));
    CHECK(moment == doctest::Approx(683.2e3).epsilon(1e-3));
    CHECK(tower[0] == doctest::Approx(force).epsilon(1e-9));
    CHECK(std::abs(tower[1]) < 1e-9 * force);
    CHECK(std::abs(tower[2]) < 1e-9 * force);
    CHECK(std::abs(tower[3]) < 1e-9 * moment);
    CHECK(tower[4] == doctest::Approx(moment).epsilon(1e-9));
    CHECK(std::abs(tower[5]) < 1e-9 * moment);
    // The first fore-aft mode takes work from it (its shape is 1 at the top):
    // a fraction of the force, the drag being highest where the shape is small.
    const std::size_t fa1 = first + 6;
    CHECK(v.input_names[static_cast<std::size_t>(ports.loads[fa1])].find("fa1") !=
          std::string::npos);
    CHECK(tower[6] > 0.2 * force);
    CHECK(tower[6] < force);
}

TEST_CASE("the blade-element block stops at a tower strike, as AeroDyn does") {
    // Blade 1 pointing down, bent downwind by its first flap mode (1 at the
    // tip) until a node reaches the tower's surface: AeroDyn's "Tower strike".
    const yamsc::analysis::Loaded& l = five_mw();
    const std::string tower = reference_cases::deck("block_tower_strike", {{"TwrPotent", "1"}});
    yamsc::analysis::BlockOptions options;
    options.aero = tower + aerodyn_file;
    const yamsc::runtime::ModelView v = yamsc::analysis::with_load_blocks(l, options);
    std::vector<double> q(static_cast<std::size_t>(v.nq), 0.0),
        qd = q, u(static_cast<std::size_t>(v.nu), 0.0), y(static_cast<std::size_t>(v.ny));
    q[index_of(v.dof_names, "psi")] = M_PI;
    u[index_of(v.input_names, "V_wind")] = 8.0;
    const std::size_t flap = index_of(v.dof_names, "q_b1_flap1");
    auto strikes = [&](double tip) {
        q[flap] = tip;
        try {
            v.outputs(0.0, q.data(), qd.data(), u.data(), y.data());
        } catch (const std::invalid_argument& e) {
            CHECK(std::string(e.what()).find("tower strike") != std::string::npos);
            return true;
        }
        return false;
    };
    CHECK_FALSE(strikes(3.0));
    bool struck = false;
    for (double tip = 3.0; tip < 20 && !struck; tip += 0.25) struck = strikes(tip);
    CHECK(struck);
}
