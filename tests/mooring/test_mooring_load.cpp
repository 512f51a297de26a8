// `load mooring` on models/oc3_spar_rigid.mbd with --mooring: the lines' stiffness
// in the linear model (-dF/dq with the block less without) against the exact
// derivative of the runtime's lines and the OC3 definition's published matrix,
// and trim's static offset against the balance of forces at the point it finds.
#include "analysis/load_blocks.hpp"
#include "analysis/loaded_model.hpp"
#include "analysis/map_mooring.hpp"
#include "analysis/sea_state_setup.hpp"
#include "codegen/routines.hpp"
#include "diag/errors.hpp"
#include "modes_at_rest.hpp"
#include "openfast/from_openfast.hpp"

#include <yamsc/modal.hpp>
#include <yamsc/mooring/mooring_system.hpp>
#include <yamsc/second_order.hpp>
#include <yamsc/trim.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>

namespace {

using namespace yamsc;

const std::string model_path = std::string(YAMSC_SOURCE_DIR) + "/models/oc3_spar_rigid.mbd";
const std::string map_file = std::string(YAMSC_TEST_DATA_DIR) + "/mooring/oc3_hywind.map";

analysis::Loaded& spar() {
    static std::optional<analysis::Loaded> l = [] {
        std::ostringstream err;
        auto loaded = analysis::load(model_path, {}, "", false, err, {}, codegen::abi_routines());
        REQUIRE_MESSAGE(loaded, err.str());
        return loaded;
    }();
    return *l;
}

analysis::BlockOptions with_mooring() {
    analysis::BlockOptions b;
    b.mooring = map_file;
    return b;
}

std::vector<runtime::mooring::Line> lines() {
    diag::Diagnostics diags;
    auto l = analysis::read_map_mooring(map_file, {320, 1025, 9.80665}, diags);
    REQUIRE_MESSAGE(l, diags.render());
    return *l;
}

double param(const analysis::Loaded& l, const std::string& name) {
    return l.params.at(static_cast<std::size_t>(l.library->param_index(name)));
}

// Rotation x, then y, then z of the platform's joint.
runtime::mooring::Pose pose_of(const std::vector<double>& q) {
    const double cx = std::cos(q[3]), sx = std::sin(q[3]), cy = std::cos(q[4]), sy = std::sin(q[4]),
                 cz = std::cos(q[5]), sz = std::sin(q[5]);
    runtime::mooring::Pose p;
    p.position = {q[0], q[1], q[2]};
    // Rx Ry Rz, row-major
    p.rotation = {cy * cz,
                  -cy * sz,
                  sy,
                  sx * sy * cz + cx * sz,
                  -sx * sy * sz + cx * cz,
                  -sx * cy,
                  -cx * sy * cz + sx * sz,
                  cx * sy * sz + sx * cz,
                  cx * cy};
    return p;
}

} // namespace

TEST_CASE("load mooring: the lines' stiffness in lin is the runtime's exact one and OC3's") {
    analysis::Loaded& l = spar();
    const runtime::ModelView moored = analysis::with_load_blocks(l, with_mooring());
    // dF/dq of the closed view (the chain rule through the mesh) less the
    // model's own: the lines' part. (K0 is not used: at a point that is not an
    // equilibrium it holds d(M q''0)/dq too, and q''0 differs with the lines.)
    auto dF_dq = [](const runtime::ModelView& v) {
        const std::vector<double> zero(6, 0.0), u(static_cast<std::size_t>(v.nu), 0.0);
        std::vector<double> dq(36), dqd(36), du(static_cast<std::size_t>(6 * v.nu));
        v.jacobians(0, zero.data(), zero.data(), u.data(), dq.data(), dqd.data(), du.data());
        return dq;
    };
    const std::vector<double> held = dF_dq(moored), free = dF_dq(l.view);
    const runtime::mooring::MooringLoads exact =
        runtime::mooring::mooring_loads(lines(), runtime::mooring::Pose{});
    auto k = [&](int i, int j) {
        const auto n = static_cast<std::size_t>(6 * (i - 1) + (j - 1));
        return free[n] - held[n];
    };
    for (int i = 1; i <= 6; ++i)
        for (int j = 1; j <= 6; ++j) {
            CAPTURE(i);
            CAPTURE(j);
            double e = -exact.derivative[static_cast<std::size_t>(6 * (i - 1) + (j - 1))];
            // The angles turn about x, then the turned y, then z: the pitch's and
            // yaw's axes turn with the angles before them, which the lines' small
            // moment at rest (the rounded REPEAT coordinates) sees.
            if (i == 5 && j == 4) e -= exact.moment[2];
            if (i == 6 && j == 4) e += exact.moment[1];
            if (i == 6 && j == 5) e -= exact.moment[0];
            // The block's derivatives are exact (the chain rule through the mesh):
            // what is left is round-off on entries up to 3e8.
            CHECK(k(i, j) == doctest::Approx(e).epsilon(1e-7).scale(3e8));
        }
    // NREL/TP-500-47535, section 5.2, good to about 0.2 % (docs/mooring.md).
    CHECK(k(1, 1) == doctest::Approx(41180).epsilon(0.002));
    CHECK(k(2, 2) == doctest::Approx(41180).epsilon(0.002));
    CHECK(k(3, 3) == doctest::Approx(11940).epsilon(0.002));
    CHECK(k(4, 4) == doctest::Approx(311100000).epsilon(0.002));
    CHECK(k(5, 5) == doctest::Approx(311100000).epsilon(0.002));
    CHECK(k(6, 6) == doctest::Approx(11560000).epsilon(0.002));
    CHECK(k(1, 5) == doctest::Approx(-2821000).epsilon(0.003));
    CHECK(k(5, 1) == doctest::Approx(-2816000).epsilon(0.003));
}

TEST_CASE("load mooring: trim's offset balances buoyancy, weight, thrust and the lines") {
    analysis::Loaded& l = spar();
    const runtime::ModelView moored = analysis::with_load_blocks(l, with_mooring());
    const double thrust = 800e3; // about the rated thrust [N]
    std::vector<double> u(static_cast<std::size_t>(moored.nu), 0.0);
    u[0] = thrust; // f_x, the model's only declared input
    REQUIRE(moored.input_names[0] == "f_x");
    const std::vector<double> zero(6, 0.0);
    const runtime::TrimResult t = runtime::trim(moored, zero, zero, u, std::vector<bool>(6, false));
    REQUIRE(t.converged);
    const runtime::mooring::MooringLoads m = runtime::mooring::mooring_loads(lines(), pose_of(t.q));
    const double g = param(l, "g"), rho = param(l, "rho_w");
    const double mass = param(l, "PtfmMass") + param(l, "TwrMass") + param(l, "M_N");
    const double area = M_PI * std::pow(param(l, "D_wp"), 2) / 4;
    const double buoyancy = rho * g * (param(l, "V_0") - area * t.q[2]);
    MESSAGE("trimmed: surge " << t.q[0] << " m, heave " << t.q[2] << " m, pitch "
                              << t.q[4] * 180 / M_PI << " deg");
    // Forces along ground x and z: nothing else acts along them.
    CHECK(m.force[0] + thrust == doctest::Approx(0).scale(thrust * 1e-6));
    CHECK(m.force[1] == doctest::Approx(0).scale(thrust * 1e-6));
    CHECK(buoyancy - mass * g + m.force[2] == doctest::Approx(0).scale(mass * g * 1e-9));
    // Downwind, and tilted downwind (the thrust acts 90 m above the lines).
    CHECK(t.q[0] > 0);
    CHECK(t.q[4] > 0);
}

TEST_CASE("load hydrodyn: --hydro's file is read with located errors, its water checked") {
    // The spar with a hydrodyn declaration beside its mooring, in the build folder.
    std::string text;
    {
        std::ifstream in(model_path);
        std::stringstream s;
        s << in.rdbuf();
        text = s.str();
    }
    const std::string anchor = "load mooring lines {";
    REQUIRE(text.find(anchor) != std::string::npos);
    text.insert(text.find(anchor),
                "load hydrodyn hydro { platform = platform; density = rho_w }\n");
    const std::string path = "spar_with_hydrodyn_declaration.mbd";
    std::ofstream(path) << text;
    std::ostringstream err;
    auto l = analysis::load(path, {}, "", false, err, {}, codegen::abi_routines());
    REQUIRE_MESSAGE(l, err.str());
    analysis::BlockOptions b;
    // A SeaState file given as the HydroDyn file: the error is at its line.
    b.hydro = std::string(YAMSC_TEST_DATA_DIR) + "/hydro/oc3_sea_state.dat";
    try {
        analysis::with_load_blocks(*l, b);
        FAIL("no error");
    } catch (const diag::UserError& e) {
        CHECK(std::string(e.what()).find("oc3_sea_state.dat:5:1: error:") != std::string::npos);
    }
    // Without a depth role nor a SeaState file, the water has no depth.
    b.hydro = std::string(YAMSC_TEST_DATA_DIR) + "/hydro/oc3_spar_strip.dat";
    try {
        analysis::with_load_blocks(*l, b);
        FAIL("no error");
    } catch (const diag::UserError& e) {
        CHECK(std::string(e.what()).find("no water depth") != std::string::npos);
    }
}

namespace {

// The spar's diameter at z (NREL/TP-500-47535, table 2-1): 6.5 m above 4 m depth,
// 9.4 m below 12 m, linear between.
double spar_diameter(double z) {
    if (z >= -4) return 6.5;
    if (z <= -12) return 9.4;
    return 6.5 + (9.4 - 6.5) * (-4 - z) / 8;
}

// Strip theory's transverse added mass of the submerged spar (Ca rho pi D^2 / 4
// per length, draft 120 m) about the still-water level, in the platform's DOFs
// at rest: int a, int a z, int a z^2 (Simpson, 1 cm strips).
std::vector<double> spar_added_mass(double ca, double rho) {
    double a0 = 0, a1 = 0, a2 = 0;
    const int n = 12000;
    const double h = 120.0 / n;
    for (int i = 0; i <= n; ++i) {
        const double z = -120 + i * h;
        const double w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
        const double a = ca * rho * M_PI * std::pow(spar_diameter(z), 2) / 4;
        a0 += w * a * h / 3;
        a1 += w * a * z * h / 3;
        a2 += w * a * z * z * h / 3;
    }
    std::vector<double> A(36, 0.0);
    A[0] = A[7] = a0;   // surge, sway
    A[4] = A[24] = a1;  // surge-pitch: x = z pitch
    A[9] = A[19] = -a1; // sway-roll: y = -z roll
    A[21] = A[28] = a2; // roll, pitch
    return A;
}

// The undamped frequencies [Hz] of (M + A) q'' + K q = 0, sorted.
std::vector<double> frequencies(const std::vector<double>& M, const std::vector<double>& K) {
    // A = -(M)^-1 K by Gauss-Jordan on [M | K].
    const int n = 6;
    std::vector<double> a(M), b(K);
    for (int c = 0; c < n; ++c) {
        int p = c;
        for (int r = c + 1; r < n; ++r)
            if (std::abs(a[r * n + c]) > std::abs(a[p * n + c])) p = r;
        for (int k = 0; k < n; ++k) {
            std::swap(a[c * n + k], a[p * n + k]);
            std::swap(b[c * n + k], b[p * n + k]);
        }
        for (int r = 0; r < n; ++r) {
            if (r == c) continue;
            const double f = a[r * n + c] / a[c * n + c];
            for (int k = 0; k < n; ++k) {
                a[r * n + k] -= f * a[c * n + k];
                b[r * n + k] -= f * b[c * n + k];
            }
        }
    }
    std::vector<double> state(4 * n * n, 0.0);
    for (int i = 0; i < n; ++i) {
        state[static_cast<std::size_t>(i * 2 * n + n + i)] = 1;
        for (int k = 0; k < n; ++k)
            state[static_cast<std::size_t>((n + i) * 2 * n + k)] = -b[i * n + k] / a[i * n + i];
    }
    std::vector<double> f;
    for (const runtime::Mode& m : runtime::modal_analysis(state, n)) f.push_back(m.freq_hz);
    return f;
}

} // namespace

TEST_CASE("the moored OC3 spar's platform frequencies with strip theory's added mass") {
    analysis::Loaded& l = spar();
    const runtime::ModelView moored = analysis::with_load_blocks(l, with_mooring());
    std::vector<double> u(static_cast<std::size_t>(moored.nu), 0.0);
    const std::vector<double> zero(6, 0.0);
    const runtime::TrimResult t = runtime::trim(moored, zero, zero, u, std::vector<bool>(6, false));
    REQUIRE(t.converged);
    const runtime::SecondOrderModel s = runtime::second_order_model(moored, t.q, t.qd, u);
    std::vector<double> M = s.M0;
    const std::vector<double> A = spar_added_mass(0.969954, param(l, "rho_w"));
    for (std::size_t i = 0; i < 36; ++i) M[i] += A[i];
    const std::vector<double> dry = frequencies(s.M0, s.K0), wet = frequencies(M, s.K0);
    for (std::size_t i = 0; i < 6; ++i)
        MESSAGE("mode " << i + 1 << ": " << dry[i] << " Hz without added mass, " << wet[i]
                        << " Hz with");
    // The published frequencies (Jonkman's OC3 definition, RAFT's OC3 model):
    // surge and sway 0.008 Hz, to one digit (so +-6 %); roll and pitch 0.034 Hz,
    // to two (+-1.5 %), and the hydrostatics here are the displaced volume's
    // where the published ones come from WAMIT's panels: 2 %; yaw 0.121 Hz to
    // three digits (+-0.4 %, no added mass in yaw either way).
    CHECK(wet[0] == doctest::Approx(0.008).epsilon(0.0625));
    CHECK(wet[1] == doctest::Approx(0.008).epsilon(0.0625));
    CHECK(wet[3] == doctest::Approx(0.034).epsilon(0.02));
    CHECK(wet[4] == doctest::Approx(0.034).epsilon(0.02));
    CHECK(wet[5] == doctest::Approx(0.121).epsilon(0.005));
    // Heave: strip theory's transverse Ca adds no mass in heave, where WAMIT's
    // A33 (the bottom's) lowers the published 0.0324 Hz: ours is above it, by
    // less than 2.5 % (an A33 of 5 % of the system's mass).
    CHECK(wet[2] > 0.0324);
    CHECK(wet[2] < 0.0324 * 1.025);
    // Without added mass surge is faster by sqrt(1 + A11 / M11) (its coupling
    // with pitch aside: 1 %).
    CHECK(dry[0] / wet[0] == doctest::Approx(std::sqrt((s.M0[0] + A[0]) / s.M0[0])).epsilon(0.01));
}

namespace {

/// The model at `path` with its hydrodyn (the OC3 strip-theory file) and
/// mooring blocks, trimmed: its frequencies [Hz] there.
std::vector<double> frequencies_at_path(const std::string& name) {
    std::ostringstream err;
    auto l = analysis::load(name, {}, "", false, err, {}, codegen::abi_routines());
    REQUIRE_MESSAGE(l, err.str());
    analysis::BlockOptions b = with_mooring();
    b.hydro = std::string(YAMSC_TEST_DATA_DIR) + "/hydro/oc3_spar_strip.dat";
    const runtime::ModelView v = analysis::with_load_blocks(*l, b);
    std::vector<double> f;
    for (const runtime::Mode& m : test_support::modes_at_rest(v)) f.push_back(m.freq_hz);
    REQUIRE(f.size() == static_cast<std::size_t>(v.nq));
    for (std::size_t i = 0; i < f.size(); ++i)
        MESSAGE(name << " mode " << i + 1 << ": " << f[i] << " Hz");
    return f;
}

/// The same for the model `name` of models/.
std::vector<double> frequencies_at_trim(const std::string& name) {
    return frequencies_at_path(std::string(YAMSC_SOURCE_DIR) + "/models/" + name);
}

} // namespace

TEST_CASE("load hydrodyn and load mooring: the OC3 spar's frequencies from HydroDyn's strip "
          "theory") {
    // models/oc3_spar_hydrodyn.mbd: the same spar with its hydrostatics and added
    // mass from the HydroDyn file's members (Ca 0.969954) instead of the model's
    // equations: the frequencies of the test above, where the added mass was
    // integrated by hand, to the strips' discretization.
    const std::vector<double> f = frequencies_at_trim("oc3_spar_hydrodyn.mbd");
    // The model-written hydrostatics and hand-integrated added mass gave 0.0080626,
    // 0.0329401, 0.0334861 and 0.121191 Hz: HydroDyn's buoyancy is the members' own
    // volume (the same 8,029 m^3), its added mass on MDivSize strips where the
    // test above integrates on 1 cm ones (7e-5 in pitch).
    CHECK(f[0] == doctest::Approx(0.0080626).epsilon(2e-4));
    CHECK(f[2] == doctest::Approx(0.0329401).epsilon(2e-4));
    CHECK(f[4] == doctest::Approx(0.0334861).epsilon(2e-4));
    CHECK(f[5] == doctest::Approx(0.121191).epsilon(2e-4));
    // Beside the published ones, as in the test above.
    CHECK(f[0] == doctest::Approx(0.008).epsilon(0.0625));
    CHECK(f[4] == doctest::Approx(0.034).epsilon(0.02));
    CHECK(f[5] == doctest::Approx(0.121).epsilon(0.005));
}

TEST_CASE("the paper's floating 3-DOF example with HydroDyn's and MAP++'s loads") {
    // models/nrel5mw_floating_3dof_loads.mbd: its floater's origin is the tower
    // base, 10 m above the water, so the files' points are placed from there.
    const std::vector<double> f = frequencies_at_trim("nrel5mw_floating_3dof_loads.mbd");
    // Surge: the lines and the added mass as on the six-DOF spar (0.0080625 Hz
    // there); the paper's floater is 0.4 % heavier (7.5e6 against 7,466,330 kg).
    CHECK(f[0] == doctest::Approx(0.0080625).epsilon(0.003));
    // Pitch: the paper's floater hangs its CM lower (110 m below the tower base
    // against OC3's 99.9), so it is stiffer in pitch than the OC3 spar's 0.0335 Hz;
    // the tower's mode is below the paper's 0.799 Hz of the floater without water,
    // whose pitch then yields to the tower's bending.
    CHECK(f[1] > 0.0335);
    CHECK(f[2] < 0.799);
}

TEST_CASE("load hydrodyn with --sea-state: Wave1Elev is the SeaState file's field at its point") {
    std::ostringstream err;
    auto l = analysis::load(std::string(YAMSC_SOURCE_DIR) + "/models/oc3_spar_hydrodyn.mbd", {}, "",
                            false, err, {}, codegen::abi_routines());
    REQUIRE_MESSAGE(l, err.str());
    analysis::BlockOptions b = with_mooring();
    b.hydro = std::string(YAMSC_TEST_DATA_DIR) + "/hydro/oc3_spar_strip.dat";
    b.sea_state = std::string(YAMSC_TEST_DATA_DIR) + "/hydro/oc3_sea_state.dat";
    const runtime::ModelView v = analysis::with_load_blocks(*l, b);
    // The same field made apart, in the model's water (its parameters: 1025, 9.80665, 320).
    diag::Diagnostics diags;
    auto sea = seastate::read_seastate_input(b.sea_state, diags);
    REQUIRE(sea);
    runtime::hydro::Water water;
    water.density = 1025;
    water.gravity = 9.80665;
    water.depth = 320;
    runtime::hydro::WaveSettings w = analysis::wave_settings(*sea, water, diags);
    w.water = water;
    const auto field = runtime::hydro::make_wave_field(w);
    const int at = [&] {
        for (std::size_t i = 0; i < v.output_names.size(); ++i)
            if (v.output_names[i] == "hydro_Wave1Elev") return static_cast<int>(i);
        return -1;
    }();
    REQUIRE(at >= 0);
    std::vector<double> q(6, 0.0), u(static_cast<std::size_t>(v.nu), 0.0),
        y(static_cast<std::size_t>(v.ny));
    double largest = 0;
    for (double t : {0.0, 13.7, 101.25, 377.0}) {
        v.outputs(t, q.data(), q.data(), u.data(), y.data());
        CAPTURE(t);
        CHECK(y[static_cast<std::size_t>(at)] ==
              doctest::Approx(field->elevation(t, 0, 0)).epsilon(1e-12));
        largest = std::max(largest, std::abs(y[static_cast<std::size_t>(at)]));
    }
    CHECK(largest > 0.1); // a sea of Hs 6 m, not still water
}

TEST_CASE("from-openfast of a floating deck declares load hydrodyn and load mooring") {
    // The floating reference deck with HydroDyn and MAP++ switched on, their files
    // ours, and the .fst's water (OpenFAST v4's entries), in the build folder.
    const std::string reference =
        std::string(YAMSC_TEST_DATA_DIR) + "/reference/floating_3dof_F2T1RNA";
    std::string fst;
    {
        std::ifstream in(reference + "/Main_Spar_ED.fst");
        std::stringstream s;
        s << in.rdbuf();
        fst = s.str();
    }
    auto replace = [&](const std::string& from, const std::string& to) {
        const std::size_t at = fst.find(from);
        REQUIRE(at != std::string::npos);
        fst.replace(at, from.size(), to);
    };
    const std::string data = YAMSC_TEST_DATA_DIR;
    replace("\"Spar_ED_ForED.dat\"", "\"" + reference + "/Spar_ED_ForED.dat\"");
    replace("          0   CompHydro", "          1   CompHydro");
    replace("          0   CompMooring", "          1   CompMooring");
    replace("\"unused\"                                                 HydroFile",
            "\"" + data + "/hydro/oc3_spar_strip.dat\" HydroFile");
    replace("\"unused\"                                                 MooringFile",
            "\"" + data + "/mooring/oc3_hywind.map\" MooringFile");
    fst += "1025 WtrDens - water density\n320 WtrDpth - water depth\n0 MSL2SWL - offset\n";
    std::ofstream("floating_blocks.fst") << fst;
    driver::FromOpenFastOptions o;
    o.deck = "floating_blocks.fst";
    o.output = "floating_blocks.mbd";
    std::ostringstream out, err;
    REQUIRE_MESSAGE(openfast::from_openfast(o, out, err) == 0, err.str());
    std::string text;
    {
        std::ifstream in(o.output);
        std::stringstream s;
        s << in.rdbuf();
        text = s.str();
    }
    CHECK(text.find("load hydrodyn hydro { platform = platform; depth = WtrDpth; density = "
                    "WtrDens; gravity = Gravity }") != std::string::npos);
    CHECK(text.find("load mooring lines {") != std::string::npos);
    CHECK(text.find("hydro_fx") == std::string::npos);
    CHECK(text.find("--hydro " + data + "/hydro/oc3_spar_strip.dat") != std::string::npos);
    // Its platform reference point is 20 m up (PtfmRefzt): the files' points are
    // placed from there. The deck's platform is the paper's (7.5e6 kg, CM at -90 m):
    // surge as the OC3 spar's, pitch beside the published 0.034 Hz.
    const std::vector<double> f = frequencies_at_path(o.output);
    CHECK(f[0] == doctest::Approx(0.0080625).epsilon(0.003));
    CHECK(f[1] == doctest::Approx(0.034).epsilon(0.02));
}
