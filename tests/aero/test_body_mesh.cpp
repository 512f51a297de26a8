// A load block's mesh (compiler/model/mesh_channels.hpp, yamsc/body_mesh.hpp)
// against Kane's equations themselves: the motion of a point of a flexible
// blade computed from the mesh channels equals the generated kinematics of a
// body jointed to that node, and a force and moment set there through the mesh
// give the same generalized forces as the same load on that body.
#include "analysis/body_points.hpp"
#include "analysis/loaded_model.hpp"
#include "loaded_channels.hpp"
#include "model/mesh_channels.hpp"
#include "test_files.hpp"

#include <doctest/doctest.h>

#include <sstream>

namespace {

using yamsc::runtime::ModelView;

const std::string blade_file =
    std::string(YAMSC_TEST_DATA_DIR) + "/reference/operating/deck/NRELOffshrBsline5MW_Blade.dat";

std::string structure() {
    return "input V_wind\n"
           "dof x, psi, qf1, qe1, qf2\n"
           "rigid carrier { mass = 1000 }\n"
           "joint ground -> carrier { translate x x }\n"
           "rigid hub { mass = 100; inertia = (50, 30, 30) }\n"
           "joint carrier -> hub { at (0, 0, 90); rotate y 0.1; rotate x psi }\n"
           "flexible blade1 {\n"
           "    beam \"" +
           blade_file +
           "\" elastodyn_blade {\n"
           "        length = 61.5\n"
           "        modes = (flap1 -> qf1, edge1 -> qe1, flap2 -> qf2)\n"
           "        elements = 17\n"
           "    }\n"
           "}\n"
           "joint hub -> blade1 { rotate y -0.05; rotate z -0.2; at (0, 0, 1.5) }\n";
}

std::string write(const std::string& name, const std::string& text) {
    static const std::string dir = test_support::scratch_dir("aero", "body_mesh");
    const std::string path = dir + "/" + name;
    test_support::write_file(path, text);
    return path;
}

} // namespace

using aero_test::index_of;

TEST_CASE("a point load through a body's mesh equals the load on a body jointed to its node") {
    const int node = 12; // a SID node of the blade (ElastoDyn's element centres are 2..18)
    const auto a =
        aero_test::load_model(write("mesh_a.mbd", "model mesh_a\n" + structure() +
                                                      "load blade_elements aero { wind = V_wind; "
                                                      "hub = hub; blade1 = blade1 }\n"));
    std::string probe = "rigid probe { mass = 0 }\n"
                        "joint blade1.node(" +
                        std::to_string(node) +
                        ") -> probe { }\n"
                        "input fx, fy, fz, mx, my, mz\n"
                        "force on probe in ground = (fx, fy, fz)\n"
                        "torque on probe in ground = (mx, my, mz)\n";
    for (const char* fn : {"position", "velocity", "angular_velocity"})
        for (const char* c : {"x", "y", "z"})
            probe += std::string("output ") + fn + "_" + c + " = " + fn + "(probe)." + c + "\n";
    const auto b =
        aero_test::load_model(write("mesh_b.mbd", "model mesh_b\n" + structure() + probe));

    const ModelView& va = a.view;
    const ModelView& vb = b.view;
    REQUIRE(va.nq == 5);
    REQUIRE(vb.nq == 5);
    const double t = 0.7;
    const std::vector<double> q{0.3, 1.1, 2.5, -0.8, 0.4}, qd{0.2, 1.2, -1.5, 0.9, 2.1};

    // The frame and modes from the mesh channels.
    std::vector<double> ua(static_cast<std::size_t>(va.nu), 0.0),
        ya(static_cast<std::size_t>(va.ny));
    va.outputs(t, q.data(), qd.data(), ua.data(), ya.data());
    const auto& model = *a.front.model;
    const auto& decl = model.loads.at(0);
    const int blade_role = static_cast<int>(yamsc::model::BladeElementsRole::blade1);
    const auto out_names = yamsc::model::mesh_output_names(model, decl, blade_role);
    auto y = [&](int k) {
        return ya[static_cast<std::size_t>(
            index_of(va.output_names, out_names[static_cast<std::size_t>(k)]))];
    };
    yamsc::runtime::BodyFrame frame;
    frame.r = {y(0), y(1), y(2)};
    frame.v = {y(3), y(4), y(5)};
    frame.w = {y(6), y(7), y(8)};
    for (int axis = 0; axis < 3; ++axis)
        for (int c = 0; c < 3; ++c) frame.R(c, axis) = y(9 + 3 * axis + c);
    for (int k = 0; k < 3; ++k) {
        frame.q.push_back(y(18 + k));
        frame.qd.push_back(y(21 + k));
    }
    const auto& blade = model.bodies[static_cast<std::size_t>(model.body_index("blade1"))];
    const auto points = yamsc::analysis::body_points(blade);
    const auto& sid_nodes = blade.flex->sid->nodes;
    std::size_t at = 0;
    while (at < sid_nodes.size() && sid_nodes[at].id != node) ++at;
    REQUIRE(at < sid_nodes.size());
    const yamsc::runtime::PointMotion m = yamsc::runtime::point_motion(frame, points[at]);

    // The jointed body's kinematics, generated.
    std::vector<double> ub(static_cast<std::size_t>(vb.nu), 0.0),
        yb(static_cast<std::size_t>(vb.ny));
    vb.outputs(t, q.data(), qd.data(), ub.data(), yb.data());
    auto yb_named = [&](const std::string& n) {
        return yb[static_cast<std::size_t>(index_of(vb.output_names, n))];
    };
    const char* xyz[] = {"x", "y", "z"};
    for (int c = 0; c < 3; ++c) {
        CHECK(m.r[c] ==
              doctest::Approx(yb_named(std::string("position_") + xyz[c])).epsilon(1e-12));
        CHECK(m.v[c] ==
              doctest::Approx(yb_named(std::string("velocity_") + xyz[c])).epsilon(1e-12));
        CHECK(m.w[c] ==
              doctest::Approx(yb_named(std::string("angular_velocity_") + xyz[c])).epsilon(1e-12));
    }

    // The same force and moment: through the mesh, and on the jointed body.
    const Eigen::Vector3d f{1.5e4, -3.2e4, 0.7e4}, mo{2.0e3, 5.0e3, -4.0e3};
    yamsc::runtime::BodyLoad load;
    yamsc::runtime::add_point_load(frame, points[at], f, mo, load);
    const auto in_names = yamsc::model::mesh_input_names(model, decl, blade_role);
    for (int c = 0; c < 3; ++c) {
        ua[static_cast<std::size_t>(
            index_of(va.input_names, in_names[static_cast<std::size_t>(c)]))] = load.force[c];
        ua[static_cast<std::size_t>(
            index_of(va.input_names, in_names[static_cast<std::size_t>(3 + c)]))] = load.moment[c];
    }
    for (std::size_t k = 0; k < 3; ++k)
        ua[static_cast<std::size_t>(index_of(va.input_names, in_names[6 + k]))] = load.modal[k];
    const char* loads[] = {"fx", "fy", "fz", "mx", "my", "mz"};
    for (int c = 0; c < 3; ++c) {
        ub[static_cast<std::size_t>(index_of(vb.input_names, loads[c]))] = f[c];
        ub[static_cast<std::size_t>(index_of(vb.input_names, loads[3 + c]))] = mo[c];
    }
    std::vector<double> Fa(5), Fb(5), F0(5);
    const std::vector<double> u0(static_cast<std::size_t>(va.nu), 0.0);
    va.forcing(t, q.data(), qd.data(), ua.data(), Fa.data());
    va.forcing(t, q.data(), qd.data(), u0.data(), F0.data());
    vb.forcing(t, q.data(), qd.data(), ub.data(), Fb.data());
    for (std::size_t i = 0; i < 5; ++i) {
        CAPTURE(i);
        CHECK(Fa[i] - F0[i] != doctest::Approx(0)); // the load reaches every DOF
        CHECK(Fa[i] == doctest::Approx(Fb[i]).epsilon(1e-11));
    }
}
