// Dynamic inflow on a rigid rotor against OpenFAST + AeroDyn, every DBEMT step
// of data/reference/aero/cases.txt (its README): given, the NREL 5-MW rotor at
// 12.1 rpm and 5 deg pitch in a uniform wind stepping from 11 to 13 m/s at t =
// 10 s, DBEMT_Mod 2 (dbemt2_U11to13.csv).
#include <doctest/doctest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "aerodyn_input/rotor.hpp"
#include "analysis/compare.hpp"
#include "reference_cases.hpp"
#include "run_error.hpp"
#include "yamsc/aero/dynamic_inflow.hpp"
#include "yamsc/aero/dynamic_inflow_element.hpp"
#include "yamsc/aero/rigid_rotor.hpp"

using namespace yamsc;
using namespace yamsc::aero;

namespace {

constexpr double pi = 3.14159265358979323846;
constexpr int output_nodes[9] = {3, 5, 7, 9, 11, 13, 15, 17, 18}; // BlOutNd

struct Channels {
    std::vector<double> fxh, power, ct, cp;
    std::array<std::vector<double>, 9> ax, tn;
};

// AeroDyn's rotor integrals (RtFldFxh, RtFldMxh) of the loads per length of
// every node, as RigidRotor::evaluate sums them: linear between nodes, lumped,
// about the hub.
void integrate(const RotorResult& r, const std::vector<std::vector<ElementSolution>>& loads,
               const Eigen::Vector3d& hub, const Eigen::Vector3d& axis, double& fxh, double& mxh) {
    Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
    for (std::size_t k = 0; k < r.blades.size(); ++k) {
        const auto& nodes = r.blades[k];
        for (std::size_t j = 0; j + 1 < nodes.size(); ++j) {
            const NodeResult &p = nodes[j], &q = nodes[j + 1];
            const ElementSolution &sp = loads[k][j], &sq = loads[k][j + 1];
            const double len = (q.position - p.position).norm();
            const Eigen::Vector3d fp = sp.fx * p.x - sp.fy * p.y, fq = sq.fx * q.x - sq.fy * q.y;
            const Eigen::Vector3d lp = len / 6 * (2 * fp + fq), lq = len / 6 * (fp + 2 * fq);
            force += lp + lq;
            moment += (p.position - hub).cross(lp) + (q.position - hub).cross(lq) +
                      len / 6 * (3 * sp.mz * p.z + 3 * sq.mz * q.z);
        }
    }
    fxh = force.dot(axis);
    mxh = moment.dot(axis);
}

// The rigid rotor stepped as AeroDyn steps it: at each step the steady BEM at t
// + dt gives DBEMT's input, DBEMT updates its states from t to t + dt, and the
// outputs at t + dt use the filtered inductions. Outputs every `every` steps.
Channels run(const RotorInput& input, const reference_cases::Case& reference, double dt, int steps,
             int every) {
    const DynamicInflow model = input.dynamic_inflow;
    const RotorGeometry geometry;
    RigidRotor rotor(input, geometry);
    const BemOptions opt = bem_options(input);
    const double omega = reference.rpm * pi / 30, pitch = reference.pitch_deg * pi / 180;
    const reference_cases::WindStep step = reference_cases::wind_step(reference);
    auto op = [&](int n) {
        OperatingPoint o;
        o.azimuth = omega * n * dt;
        o.rotor_speed = omega;
        o.pitch = pitch;
        o.wind_speed = step.at(n * dt); // step.wnd, given: 11 -> 13 in (10, 10.00625]
        return o;
    };
    const int nb = int(input.blades.size()), nn = int(input.blades[0].size());
    const RotorResult& first = rotor.evaluate(op(0));
    std::vector<double> rlocal;
    for (const auto& blade : first.blades)
        for (const auto& node : blade) rlocal.push_back(node.r_local);
    const Dbemt dbemt(model, input.tau1_const, dt, nb, nn, rlocal);
    DbemtInput u_t = dbemt.make_input(), u_next = dbemt.make_input();
    DbemtState x = dbemt.make_state();
    std::vector<double> a_qs(rlocal.size());
    std::vector<std::vector<ElementSolution>> loads(nb, std::vector<ElementSolution>(nn));
    // The hub and shaft axis of the rigid rotor (RigidRotor's frames).
    const double tilt = geometry.shaft_tilt;
    const Eigen::Vector3d axis(std::cos(tilt), 0, std::sin(tilt));
    const Eigen::Vector3d hub =
        Eigen::Vector3d(0, 0, geometry.tower_height + geometry.twr2shft) + geometry.overhang * axis;

    Channels c;
    // DBEMT's quasi-steady input: the inductions at the inflow angle `phi` (AeroDyn's
    // constraint state z%phi) with the inputs of r; the BEM's state becomes r's roots.
    std::vector<ElementSolution> phi(rlocal.size());
    auto sample = [&](const RotorResult& r, DbemtInput& u, bool stale_phi) {
        std::size_t e = 0;
        for (const auto& blade : r.blades)
            for (const auto& node : blade) {
                if (!stale_phi) phi[e] = node.bem;
                const InductionFactors f = quasi_steady_induction(node.input, opt, phi[e]);
                u.quasi_steady[e] = induced_velocity(f, node.vx, node.vy);
                u.rlocal[e] = node.r_local;
                a_qs[e++] = f.axial;
            }
        dbemt.set_disk_input(u, a_qs.data(), r.v_avg_xh);
    };
    auto record = [&](const RotorResult& r, const DbemtInput& u) {
        std::size_t e = 0;
        for (int k = 0; k < nb; ++k)
            for (int j = 0; j < nn; ++j, ++e) {
                const NodeResult& node = r.blades[k][j];
                const InductionFactors f =
                    filtered_induction(dbemt, u, x, e, node.input, opt, node.bem);
                loads[k][j] =
                    element_with_induction(node.input, opt, input.air_density, f, node.bem);
            }
        double fxh = 0, mxh = 0;
        integrate(r, loads, hub, axis, fxh, mxh);
        const double q = 0.5 * input.air_density * pi * r.r_max * r.r_max * r.v_avg_xh * r.v_avg_xh;
        c.fxh.push_back(fxh);
        c.power.push_back(omega * mxh);
        c.ct.push_back(fxh / q);
        c.cp.push_back(omega * mxh / (q * r.v_avg_xh));
        for (int i = 0; i < 9; ++i) {
            c.ax[i].push_back(loads[0][output_nodes[i] - 1].a);
            c.tn[i].push_back(loads[0][output_nodes[i] - 1].ap);
        }
    };

    sample(first, u_t, false);
    dbemt.initialize(u_t, x);
    record(first, u_t);
    for (int n = 0; n < steps; ++n) {
        // AeroDyn's BEMT_UpdateStates takes the inflow of both its inputs at t + dt
        // (AD_UpdateStates sets them from the inflow at the glue code's newest input
        // time), and its input at t is the induction at the inflow angle solved at the
        // last step: a change of the wind reaches DBEMT's input at t through Vx with the
        // old angle, and only the change of the angle falls within the update.
        if (op(n + 1).wind_speed != op(n).wind_speed) {
            OperatingPoint o = op(n);
            o.wind_speed = op(n + 1).wind_speed;
            sample(rotor.evaluate(o, true), u_t, true);
        }
        const RotorResult& r = rotor.evaluate(op(n + 1), true);
        sample(r, u_next, false);
        dbemt.update(u_t, u_next, x);
        if ((n + 1) % every == 0) record(r, u_next);
        std::swap(u_t, u_next);
    }
    return c;
}

void compare(const reference_cases::Case& c) {
    CAPTURE(c.file);
    const std::string deck = reference_cases::deck("dbemt_openfast_" + c.name(), c.settings);
    diag::Diagnostics diags;
    const auto input =
        aerodyn_input::read_aerodyn_rotor(deck + reference_cases::aerodyn_file, 3, diags);
    REQUIRE_MESSAGE(input.has_value(), diags.render());
    REQUIRE(int(input->dynamic_inflow) == int(c.number("DBEMT_Mod", 2)));
    const analysis::Table ref = analysis::read_table(c.path());
    auto column = [&](const std::string& name) -> const std::vector<double>& {
        const int i = ref.find(name);
        REQUIRE(i >= 0);
        return ref.data[std::size_t(i)];
    };
    // The reference's time step (README.md) and its rows.
    const double dt = 0.00625;
    const std::vector<double>& time = column("Time_[s]");
    const int every = int(std::lround((time.at(1) - time.at(0)) / dt));
    const int steps = int(std::lround(time.back() / dt));

    const auto start = std::chrono::steady_clock::now();
    const Channels y = run(*input, c, dt, steps, every);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    REQUIRE(y.fxh.size() == ref.rows());
    // The issue's bound is 2 %; these conventions each cost more than 1e-4 on some
    // channel (measured: the wind change inside the update, 1e-2 to 1e-1; DBEMT on the
    // fixed-induction tip node, 1.4e-2 on RtFldCt), so the tighter bound keeps them.
    constexpr double issue_bound = 0.02, conventions_bound = 1e-4;
    std::vector<std::pair<std::string, const std::vector<double>*>> channels = {
        {"RtFldFxh_[N]", &y.fxh},
        {"RtFldPwr_[W]", &y.power},
        {"RtFldCt_[-]", &y.ct},
        {"RtFldCp_[-]", &y.cp}};
    for (int i = 0; i < 9; ++i) {
        const std::string node = "B1N" + std::to_string(i + 1);
        channels.push_back({node + "AxInd_[-]", &y.ax[i]});
        channels.push_back({node + "TnInd_[-]", &y.tn[i]});
    }
    for (const auto& [name, value] : channels) {
        const double eps = aero_test::epsilon(*value, column(name));
        std::printf("%s %-16s eps %.2e\n", c.name().c_str(), name.c_str(), eps);
        CHECK_MESSAGE(eps < issue_bound, name);
        CHECK_MESSAGE(eps < conventions_bound, name);
    }
    std::printf("%s: %d steps of 57 elements in %.2f s\n", c.name().c_str(), steps, seconds);
}

} // namespace

TEST_CASE("dbemt: every wind step on the rigid NREL 5-MW rotor (DBEMT_Mod 2 and those held) "
          "against OpenFAST") {
    for (const reference_cases::Case& c : reference_cases::cases(reference_cases::Kind::dbemt_step))
        compare(c);
}
