// Models without DOFs (their motion all prescribed by functions of t): every target
// compiles, the generated code builds with the strict flags, `sim` evaluates the
// outputs over time (reaction loads from the prescribed accelerations against
// Newton's closed forms), `eval` gives the empty equations, `lin` and `trim` refuse
// with a located error; and an OpenFAST deck with every ElastoDyn DOF off runs.
#include "json_values.hpp"
#include "test_files.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using test_support::exit_status;
using test_support::json_array;
using test_support::read_file;
using test_support::scratch_dir;
using test_support::write_file;

namespace {

const std::string yamsc = YAMSC_EXE;

/// A point mass on a massless arm, turned about the vertical with a constant
/// angular acceleration: psi = Omega t + A t^2 / 2.
const char* const arm_model = R"(model arm "A point mass turned at a prescribed azimuth"
param m = 2        # mass [kg]
param r = 0.5      # arm length [m]
param Omega = 3    # speed at t = 0 [rad/s]
param A = 0.4      # angular acceleration [rad/s^2]
param g = 9.81     # [m/s^2]
gravity (0, 0, -g)
rigid arm { mass = m; com = (r, 0, 0); inertia = (0.1, 0.2, 0.3) }
joint ground -> arm { rotate z Omega * t + A * t^2 / 2 }
point tip on arm at (r, 0, 0)
output psi = Omega * t + A * t^2 / 2             # [rad]
output x_tip = position(tip).x                   # [m]
output v_tip = velocity(tip).y in arm            # [m/s]
output Fx = reaction_force(arm).x in arm         # [N]
output Fy = reaction_force(arm).y in arm         # [N]
output Fz = reaction_force(arm).z in arm         # [N]
output My = reaction_moment(arm).y in arm        # [N m]
output Mz = reaction_moment(arm).z in arm        # [N m]
)";

struct Csv {
    std::vector<std::string> columns;
    std::vector<std::vector<double>> rows;
    double at(std::size_t row, const std::string& name) const {
        for (std::size_t i = 0; i < columns.size(); ++i)
            if (columns[i] == name) return rows.at(row).at(i);
        FAIL("no column " << name);
        return 0;
    }
};

Csv read_csv(const std::string& path) {
    std::istringstream in(read_file(path));
    Csv csv;
    std::string line, cell;
    REQUIRE(std::getline(in, line));
    std::istringstream header(line);
    while (std::getline(header, cell, ',')) csv.columns.push_back(cell);
    while (std::getline(in, line)) {
        std::istringstream row(line);
        std::vector<double> values;
        while (std::getline(row, cell, ',')) values.push_back(std::stod(cell));
        REQUIRE(values.size() == csv.columns.size());
        csv.rows.push_back(values);
    }
    return csv;
}

} // namespace

TEST_CASE("no DOF: sim evaluates the outputs over time; reactions are m a - m g of the "
          "prescribed motion") {
    const std::string dir = scratch_dir("cli", "no_dof_arm");
    const std::string model = dir + "/arm.mbd";
    write_file(model, arm_model);
    const double m = 2, r = 0.5, Omega = 3, A = 0.4, g = 9.81;
    std::map<std::string, std::string> files;
    for (const char* method : {"rk4", "abm4", "cvode"}) {
        CAPTURE(method);
        const std::string csv = dir + "/" + method + ".csv";
        REQUIRE(exit_status(yamsc + " sim " + model + " --tmax 2 --dt 0.25 --method " + method +
                            " -o " + csv + " > /dev/null 2>&1") == 0);
        files[method] = read_file(csv);
    }
    // Nothing is integrated: every method writes the same rows.
    CHECK(files["abm4"] == files["rk4"]);
    CHECK(files["cvode"] == files["rk4"]);
    const Csv csv = read_csv(dir + "/rk4.csv");
    CHECK(csv.columns ==
          std::vector<std::string>{"time", "psi", "x_tip", "v_tip", "Fx", "Fy", "Fz", "My", "Mz"});
    REQUIRE(csv.rows.size() == 9);
    // The CSV's numbers have 10 significant digits.
    for (std::size_t k = 0; k < csv.rows.size(); ++k) {
        const double t = 0.25 * static_cast<double>(k);
        CAPTURE(t);
        const double psi = Omega * t + A * t * t / 2, w = Omega + A * t;
        CHECK(csv.at(k, "time") == doctest::Approx(t).epsilon(1e-9));
        CHECK(csv.at(k, "psi") == doctest::Approx(psi).epsilon(1e-9));
        CHECK(csv.at(k, "x_tip") == doctest::Approx(r * std::cos(psi)).scale(r).epsilon(1e-9));
        CHECK(csv.at(k, "v_tip") == doctest::Approx(w * r).epsilon(1e-9));
        // Newton on the mass: m (-w^2 r, A r, 0) = R + m (0, 0, -g) in the arm's axes.
        CHECK(csv.at(k, "Fx") == doctest::Approx(-m * w * w * r).epsilon(1e-9));
        CHECK(csv.at(k, "Fy") == doctest::Approx(m * A * r).epsilon(1e-9));
        CHECK(csv.at(k, "Fz") == doctest::Approx(m * g).epsilon(1e-9));
        // About the joint: r x (m a - m g) + the inertia's J_z A.
        CHECK(csv.at(k, "My") == doctest::Approx(-m * g * r).epsilon(1e-9));
        CHECK(csv.at(k, "Mz") == doctest::Approx(m * A * r * r + 0.3 * A).epsilon(1e-9));
    }
}

TEST_CASE("no DOF: eval gives empty equations and the outputs at --t") {
    const std::string dir = scratch_dir("cli", "no_dof_eval");
    const std::string model = dir + "/arm.mbd";
    write_file(model, arm_model);
    const std::string out = dir + "/eval.json";
    for (const char* compiled : {"", " --compiled"}) {
        CAPTURE(compiled);
        REQUIRE(exit_status(yamsc + " eval " + model + " --t 1.5 --json" + compiled + " > " + out +
                            " 2>/dev/null") == 0);
        const std::string json = read_file(out);
        CHECK(json.find("\"nq\":0") != std::string::npos);
        CHECK(json_array(json, "F").empty());
        const std::vector<double> y = json_array(json, "y");
        REQUIRE(y.size() == 8);
        const double w = 3 + 0.4 * 1.5;
        CHECK(y[3] == doctest::Approx(-2 * w * w * 0.5).epsilon(1e-13));
    }
}

TEST_CASE("no DOF: lin and trim say there is nothing to do, at the model line") {
    const std::string dir = scratch_dir("cli", "no_dof_lin");
    const std::string model = dir + "/arm.mbd";
    write_file(model, arm_model);
    for (const char* command : {"lin", "trim"}) {
        CAPTURE(command);
        const std::string err = dir + "/" + command + ".err";
        CHECK(exit_status(yamsc + " " + command + " " + model + " > /dev/null 2> " + err) == 1);
        const std::string text = read_file(err);
        CHECK(text.find(model + ":1:7: error: `yamsc " + command + "`: the model has no DOF") !=
              std::string::npos);
    }
}

TEST_CASE("no DOF: the C++, C and LaTeX targets, the code built with the strict flags") {
    const std::string dir = scratch_dir("cli", "no_dof_targets");
    const std::string model = dir + "/arm.mbd";
    write_file(model, arm_model);
    REQUIRE(exit_status(yamsc + " " + model + " -o " + dir + "/arm.cpp --header " + dir +
                        "/arm.hpp") == 0);
    REQUIRE(exit_status(yamsc + " " + model + " -o " + dir + "/arm.c --header " + dir + "/arm.h") ==
            0);
    REQUIRE(exit_status(yamsc + " " + model + " -o " + dir + "/arm.tex") == 0);
    // No Jacobian to form column by column: a usage error.
    CHECK(exit_status(yamsc + " " + model + " -o " + dir + "/tangent.cpp --jacobians tangent 2> " +
                      dir + "/tangent.err") == 2);
    CHECK(read_file(dir + "/tangent.err").find("a model without DOFs") != std::string::npos);
    CHECK(read_file(dir + "/arm.tex").find("\\begin{document}") != std::string::npos);
    CHECK(exit_status(std::string(YAMSC_CXX_COMPILER) +
                      " -std=c++17 -pedantic -Wall -Wextra -Werror -Wshadow -O1 -c " + dir +
                      "/arm.cpp -o " + dir + "/arm_cpp.o") == 0);
    CHECK(exit_status(std::string(YAMSC_C_COMPILER) +
                      " -std=c99 -pedantic -Wall -Wextra -Werror -Wshadow -O1 -c " + dir +
                      "/arm.c -o " + dir + "/arm_c.o") == 0);
}

namespace {

/// The value of `param NAME = value` in a model text.
double param(const std::string& text, const std::string& name) {
    const std::string key = "\nparam " + name + " = ";
    const auto at = text.find(key);
    REQUIRE_MESSAGE(at != std::string::npos, name);
    return std::stod(text.substr(at + key.size()));
}

/// Simulates a model written by from-openfast with every DOF off for 3 s and checks
/// the rotor's azimuth and speed as ElastoDyn's with GenDOF off (the azimuth advances
/// at RotSpeed from Azimuth) and blade 1's root moments against Newton over the rigid
/// blade: its weight and the centripetal acceleration of its coned points.
void check_rigid_rotor(const std::string& model, double azimuth_deg, double rpm) {
    const std::string text = read_file(model);
    CHECK(text.find("\ndof ") == std::string::npos);
    const std::string csv_path = model + ".csv";
    REQUIRE(exit_status(yamsc + " sim " + model + " --tmax 3 --dt 0.05 --dt-out 0.25 -o " +
                        csv_path + " > /dev/null 2>&1") == 0);
    const Csv csv = read_csv(csv_path);
    REQUIRE(csv.rows.size() == 13);
    const double pi = 3.14159265358979323846, omega = rpm * pi / 30;
    // The blade's first and second moments about its root, the cone, the shaft tilt.
    const double mb = param(text, "BldMass1"), cb = param(text, "BldCM1");
    const double s1 = mb * cb, s2 = param(text, "BldIner1") + mb * cb * cb;
    const double h = param(text, "HubRad"), beta = param(text, "PreCone1") * pi / 180;
    const double tilt = -param(text, "ShftTilt") * pi / 180, g = param(text, "Gravity");
    for (std::size_t k = 0; k < csv.rows.size(); ++k) {
        const double t = csv.at(k, "time");
        CAPTURE(t);
        const double psi = azimuth_deg * pi / 180 + omega * t;
        // The CSV's numbers have 10 significant digits.
        CHECK(csv.at(k, "Azimuth") == doctest::Approx(psi * 180 / pi).epsilon(1e-9));
        CHECK(csv.at(k, "RotSpeed") == doctest::Approx(rpm).epsilon(1e-9));
        // Gravity in the coned blade axes (x out of plane, z along the blade); the
        // blade's points accelerate by -omega^2 (h + s) sin(beta) cos(beta) along x.
        const double gx =
            g * (std::sin(tilt) * std::cos(beta) + std::cos(tilt) * std::cos(psi) * std::sin(beta));
        const double gy = -g * std::cos(tilt) * std::sin(psi);
        const double my = s1 * gx - omega * omega * std::sin(beta) * std::cos(beta) * (h * s1 + s2);
        CHECK(csv.at(k, "RootMyc1") == doctest::Approx(my / 1000).epsilon(1e-9));
        CHECK(csv.at(k, "RootMxc1") == doctest::Approx(-s1 * gy / 1000).epsilon(1e-9));
    }
}

} // namespace

TEST_CASE("an OpenFAST deck with every ElastoDyn DOF off (--dofs): the rotor turns at "
          "RotSpeed, the blade root carries its weight and its spin") {
    const std::string dir = scratch_dir("cli", "no_dof_deck");
    const std::string deck = std::string(YAMSC_TEST_DATA_DIR) + "/reference/operating/deck";
    const std::string model = dir + "/rigid.mbd";
    std::string off;
    for (const char* flag : {"FlapDOF1", "FlapDOF2", "EdgeDOF", "TwFADOF1", "TwFADOF2", "TwSSDOF1",
                             "TwSSDOF2", "YawDOF", "GenDOF", "DrTrDOF"})
        off += (off.empty() ? "" : ",") + std::string(flag) + "=off";
    REQUIRE(exit_status(yamsc + " from-openfast " + deck + "/NREL-5MW.fst --dofs " + off + " -o " +
                        model + " > /dev/null 2>&1") == 0);
    check_rigid_rotor(model, 0, 8.9836); // the deck's Azimuth and RotSpeed
    // A full deck: the blades turn with the controller's pitch input (0 here, as BlPitch).
    CHECK(read_file(model).find(
              "joint rotor -> blade1 { rotate y PreCone1; at (0, 0, HubRad); rotate z -pitch }") !=
          std::string::npos);
}

TEST_CASE("an ElastoDyn file with every DOF False, pitched, at another azimuth") {
    const std::string dir = scratch_dir("cli", "no_dof_elastodyn");
    const std::string deck = std::string(YAMSC_TEST_DATA_DIR) + "/reference/operating/deck/";
    for (const char* f :
         {"NRELOffshrBsline5MW_Blade.dat", "NRELOffshrBsline5MW_Onshore_ElastoDyn_Tower.dat"})
        write_file(dir + "/" + f, read_file(deck + f));
    // Every flag False, BlPitch 10 deg, Azimuth 30 deg, RotSpeed 12.1 rpm.
    std::istringstream in(read_file(deck + "NRELOffshrBsline5MW_Onshore_ElastoDyn.dat"));
    std::string text, line;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string value, key;
        words >> value >> key;
        if (value == "True" && key.find("DOF") != std::string::npos) line = "False " + key;
        if (key.rfind("BlPitch(", 0) == 0) line = "10 " + key;
        if (key == "Azimuth") line = "30 Azimuth";
        if (key == "RotSpeed") line = "12.1 RotSpeed";
        text += line + "\n";
    }
    const std::string elastodyn = dir + "/ElastoDyn.dat", model = dir + "/pitched.mbd";
    write_file(elastodyn, text);
    REQUIRE(exit_status(yamsc + " from-openfast " + elastodyn + " -o " + model +
                        " > /dev/null 2>&1") == 0);
    // The pitch turns the blade about its own axis, on which its mass lies: the root
    // moments in the cone axes do not change.
    check_rigid_rotor(model, 30, 12.1);
    const std::string written = read_file(model);
    CHECK(param(written, "BlPitch1") == 10);
    CHECK(written.find("joint rotor -> blade1 { rotate y PreCone1; at (0, 0, HubRad); rotate z "
                       "-BlPitch1 }") != std::string::npos);
}
