// `load blade_elements` on the NREL 5-MW structure from-openfast writes, its
// blades undeflected: the rotor of AeroDyn's BEM through the blades' meshes,
// against OpenFAST + AeroDyn's rigid rotor (the rigid runs of
// data/reference/aero/cases.txt: every ElastoDyn DOF off, quasi-steady BEM) and against the rigid
// rotor of yamsc/aero/rigid_rotor.hpp, which places the nodes from the geometry alone.
#include "analysis/load_blocks.hpp"
#include "analysis/loaded_model.hpp"
#include "loaded_channels.hpp"
#include "openfast/from_openfast.hpp"
#include "reference_cases.hpp"
#include "test_files.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

namespace {

const std::string data_dir = YAMSC_TEST_DATA_DIR;

/// The deck copied, with AeroDyn's node outputs at the reference's nodes.
std::string deck_copy() {
    static const std::string dir = reference_cases::deck("blade_elements_deck", {});
    return dir;
}

/// The full deck's model: from-openfast declares the blade-element rotor.
std::string model_with_blade_elements() {
    const std::string dir = test_support::scratch_dir("aero", "blade_elements_model");
    yamsc::driver::FromOpenFastOptions o;
    o.deck = deck_copy() + "/NREL-5MW.fst";
    o.output = dir + "/full.mbd";
    std::ostringstream out, err;
    REQUIRE_MESSAGE(yamsc::openfast::from_openfast(o, out, err) == 0, err.str());
    REQUIRE(test_support::read_file(o.output).find("load blade_elements aero {") !=
            std::string::npos);
    return o.output;
}

using Row = std::map<std::string, double>;

std::vector<Row> read_reference(const std::string& name) {
    std::istringstream in(test_support::read_file(data_dir + "/reference/aero/" + name));
    std::string line;
    std::getline(in, line);
    std::vector<std::string> header;
    {
        std::istringstream h(line);
        std::string c;
        while (std::getline(h, c, ',')) header.push_back(c.substr(0, c.find("_[")));
    }
    std::vector<Row> rows;
    while (std::getline(in, line)) {
        std::istringstream l(line);
        std::string c;
        Row r;
        for (std::size_t i = 0; std::getline(l, c, ','); ++i) r[header.at(i)] = std::stod(c);
        rows.push_back(std::move(r));
    }
    return rows;
}

} // namespace

using aero_test::index_of;

TEST_CASE("the blade-element rotor on undeflected blades matches OpenFAST's rigid rotor") {
    const std::string path = model_with_blade_elements();
    auto l = std::make_optional(aero_test::load_model(path));

    for (const reference_cases::Case& c : reference_cases::cases(reference_cases::Kind::rigid)) {
        CAPTURE(c.file);
        // The run's AeroDyn entries (quasi-steady BEM) in the block; the
        // structure is the deck's, its motion the run's.
        yamsc::analysis::BlockOptions blocks;
        reference_cases::Settings settings = c.settings;
        settings.emplace_back("HWindSpeed", std::to_string(c.wind));
        const std::string deck = reference_cases::deck("blade_elements_" + c.name(), settings);
        blocks.aero = deck + reference_cases::aerodyn_file;
        blocks.wind = deck + "/NRELOffshrBsline5MW_InflowWind.dat"; // its direction too
        const yamsc::runtime::ModelView v = yamsc::analysis::with_load_blocks(*l, blocks);
        const std::vector<Row> rows = read_reference(c.file);
        for (std::size_t r = 0; r < rows.size(); r += 20) {
            const Row& ref = rows[r];
            CAPTURE(ref.at("Time"));
            std::vector<double> q(static_cast<std::size_t>(v.nq), 0.0),
                qd = q, u(static_cast<std::size_t>(v.nu), 0.0), y(static_cast<std::size_t>(v.ny));
            q[static_cast<std::size_t>(index_of(v.dof_names, "psi"))] =
                ref.at("Azimuth") * M_PI / 180;
            qd[static_cast<std::size_t>(index_of(v.dof_names, "psi"))] =
                ref.at("RotSpeed") * M_PI / 30;
            u[static_cast<std::size_t>(index_of(v.input_names, "V_wind"))] = c.wind;
            u[static_cast<std::size_t>(index_of(v.input_names, "pitch"))] =
                ref.at("BlPitch1") * M_PI / 180;
            v.outputs(0.0, q.data(), qd.data(), u.data(), y.data());
            auto out = [&](const std::string& n) {
                return y[static_cast<std::size_t>(index_of(v.output_names, n))];
            };
            CHECK(out("RtFldCp") == doctest::Approx(ref.at("RtFldCp")).epsilon(0.005));
            CHECK(out("RtFldCt") == doctest::Approx(ref.at("RtFldCt")).epsilon(0.005));
            CHECK(out("RtSkew") == doctest::Approx(ref.at("RtSkew")).epsilon(1e-3));
            double fmax = 0;
            for (int j = 1; j <= 9; ++j)
                for (const char* f : {"Fx", "Fy"})
                    fmax = std::max(fmax, std::abs(ref.at("B1N" + std::to_string(j) + f)));
            for (int j = 1; j <= 9; ++j) {
                const std::string n = "B1N" + std::to_string(j);
                CAPTURE(n);
                CHECK(std::abs(out(n + "Alpha") - ref.at(n + "Alpha")) < 0.1);
                CHECK(std::abs(out(n + "Fx") - ref.at(n + "Fx")) < 0.01 * fmax);
                CHECK(std::abs(out(n + "Fy") - ref.at(n + "Fy")) < 0.01 * fmax);
            }
        }
    }
}

TEST_CASE("blade elements linearized with a frozen wake: the aerodynamic damping matrix by central "
          "differences, independent of the step") {
    const std::string path = model_with_blade_elements();
    std::ostringstream err;
    auto l = yamsc::analysis::load(path, {}, "", false, err, {}, yamsc::codegen::abi_routines());
    REQUIRE_MESSAGE(l, err.str());
    const yamsc::runtime::ModelView& base = l->view;
    const auto n = static_cast<std::size_t>(base.nq);
    // 16 m/s at 12.1 rpm and 12 degrees of pitch, blade 1 at 30 degrees.
    std::vector<double> q(n, 0.0), qd(n, 0.0), u(static_cast<std::size_t>(base.nu), 0.0);
    q[static_cast<std::size_t>(index_of(base.dof_names, "psi"))] = 30 * M_PI / 180;
    qd[static_cast<std::size_t>(index_of(base.dof_names, "psi"))] = 12.1 * M_PI / 30;
    u[static_cast<std::size_t>(index_of(base.input_names, "V_wind"))] = 16;
    u[static_cast<std::size_t>(index_of(base.input_names, "pitch"))] = 12 * M_PI / 180;

    // dF/dq' of the closed model less the structure's own: the rotor's damping.
    auto aero_damping = [&](bool frozen, double step) {
        yamsc::analysis::BlockOptions o;
        o.aero = deck_copy() + "/NRELOffshrBsline5MW_Onshore_AeroDyn15.dat";
        o.frozen_wake = frozen;
        o.difference_step = step;
        const yamsc::runtime::ModelView v = yamsc::analysis::with_load_blocks(*l, o);
        std::vector<double> dq(n * n), dqd(n * n), du(n * static_cast<std::size_t>(v.nu)),
            dqd0(n * n);
        v.jacobians(0.0, q.data(), qd.data(), u.data(), dq.data(), dqd.data(), du.data());
        std::vector<double> ue = u; // the structure's at the same effective loads is linear in them
        base.jacobians(0.0, q.data(), qd.data(), ue.data(), dq.data(), dqd0.data(), du.data());
        for (std::size_t i = 0; i < n * n; ++i) dqd[i] -= dqd0[i];
        return dqd;
    };
    auto largest = [](const std::vector<double>& a) {
        double m = 0;
        for (double x : a) m = std::max(m, std::abs(x));
        return m;
    };
    auto difference = [&](const std::vector<double>& a, const std::vector<double>& b) {
        std::vector<double> d(a.size());
        for (std::size_t i = 0; i < a.size(); ++i) d[i] = a[i] - b[i];
        return largest(d) / largest(a);
    };
    const std::vector<double> c5 = aero_damping(true, 1e-5), c6 = aero_damping(true, 1e-6),
                              c7 = aero_damping(true, 1e-7);
    const double d56 = difference(c6, c5), d67 = difference(c6, c7);
    // The quasi-steady BEM, solved again at each perturbed point, against the frozen wake.
    const double quasi_steady = difference(c6, aero_damping(false, 1e-6));
    MESSAGE("aerodynamic damping matrix, frozen wake: largest entry "
            << largest(c6)
            << "; relative change 1e-5 vs "
               "1e-6 step "
            << d56 << ", 1e-6 vs 1e-7 " << d67 << "; quasi-steady vs frozen " << quasi_steady);
    // The tower's fore-aft damping is the rotor's thrust slope: positive, large.
    const auto fa = static_cast<std::size_t>(index_of(base.dof_names, "q_fa1"));
    CHECK(-c6[fa * n + fa] > 1e5);
    CHECK(d56 < 1e-7); // measured 1.1e-10
    CHECK(d67 < 1e-7); // measured 1.7e-9
    // The frozen wake is not the quasi-steady rotor: its loads answer the motion more.
    CHECK(quasi_steady > 0.05);
}
