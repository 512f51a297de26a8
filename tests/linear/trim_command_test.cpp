// `yamsc trim` and `yamsc lin --trim`: the pendulum held by a torque trims to
// its parameter th0 from any start; the 2-DOF turbine's tower settles under the
// nacelle's overhanging weight at the same point from a perturbed start, and
// lin --trim linearizes there without the moving-point warning.
#include "generated_model.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <string>

using namespace linear_test;

namespace {

struct Run {
    bool ok;
    std::string out, err;
};

Run yamsc(const std::string& args) {
    const std::string dir = scratch_dir("trim_command");
    const bool ok =
        run(std::string(YAMSC_EXE) + " " + args + " > " + dir + "/out.txt 2> " + dir + "/err.txt");
    return {ok, read_file(dir + "/out.txt"), read_file(dir + "/err.txt")};
}

/// The first number of a JSON array `"key":[x, ...]`.
double first_of(const std::string& json, const std::string& key) {
    const auto at = json.find("\"" + key + "\":[");
    REQUIRE(at != std::string::npos);
    return std::strtod(json.c_str() + at + key.size() + 4, nullptr);
}

const std::string source = YAMSC_SOURCE_DIR;
const std::string pendulum = source + "/tests/linear/models/pendulum_op.mbd";
const std::string turbine = source + "/models/nrel5mw_land_2dof.mbd";

} // namespace

TEST_CASE("trim: the pendulum held by its torque returns to th0 from any start") {
    for (const char* start : {"theta=0", "theta=1.1", "theta=-0.2"}) {
        CAPTURE(start);
        const Run r = yamsc("trim " + pendulum + " --at " + start + " --json");
        REQUIRE(r.ok);
        CHECK(first_of(r.out, "q") == doctest::Approx(0.4).epsilon(1e-13));
    }
    // Another th0 moves the torque of the `linearize` block, and the trim with it.
    const Run moved = yamsc("trim " + pendulum + " --set th0=0.9 --at theta=0 --json");
    REQUIRE(moved.ok);
    CHECK(first_of(moved.out, "q") == doctest::Approx(0.9).epsilon(1e-13));
}

TEST_CASE("trim: a torque beyond m g L has no equilibrium: exit 1 with the residual by DOF") {
    const Run r = yamsc("trim " + pendulum + " --u tau=20");
    CHECK_FALSE(r.ok);
    CHECK(r.err.find("trim did not converge") != std::string::npos);
    CHECK(r.err.find("theta") != std::string::npos);
}

TEST_CASE("trim: the 2-DOF turbine's static tower deflection, the same from a perturbed start") {
    const Run at_rest = yamsc("trim " + turbine + " --json");
    const Run perturbed = yamsc("trim " + turbine + " --at q=0.8 --json");
    REQUIRE(at_rest.ok);
    REQUIRE(perturbed.ok);
    const double q = first_of(at_rest.out, "q");
    CHECK(q == doctest::Approx(first_of(perturbed.out, "q")).epsilon(1e-10));
    // The nacelle's weight ahead of the tower bends it upwind by about 9 mm.
    CHECK(q == doctest::Approx(-0.009237054658).epsilon(1e-8));
    CHECK(std::fabs(first_of(at_rest.out, "residual")) < 1e-6);

    const Run lin = yamsc("lin " + turbine + " --trim");
    REQUIRE(lin.ok);
    CHECK(lin.err.find("not an equilibrium") == std::string::npos);
    CHECK(lin.out.find("0.32696") != std::string::npos);
    const Run plain = yamsc("lin " + turbine);
    CHECK(plain.err.find("not an equilibrium") != std::string::npos);
}

TEST_CASE("trim: the paper's 3-DOF turbine, parked and spinning, from perturbed starts") {
    const std::string model = source + "/models/nrel5mw_land_3dof.mbd";
    for (const char* rotor : {"psi'=0", "psi'=1.2671"}) {
        CAPTURE(rotor);
        // parked, the azimuth has no stiffness: held, as OpenFAST locks the generator
        const std::string hold = std::string(rotor) == "psi'=0" ? " --hold psi" : "";
        const Run a = yamsc("trim " + model + " --at \"" + rotor + "\"" + hold + " --json");
        const Run b =
            yamsc("trim " + model + " --at \"" + rotor + ",q1=0.7,q2=-0.4\"" + hold + " --json");
        REQUIRE(a.ok);
        REQUIRE(b.ok);
        CHECK(first_of(b.out, "q") == doctest::Approx(first_of(a.out, "q")).epsilon(1e-9));
        CHECK(std::fabs(first_of(a.out, "q")) < 0.05); // millimetres, not the start's 0.7 m
    }
}

TEST_CASE("trim: --hold keeps a DOF; unknown names are errors") {
    const Run held = yamsc("trim " + pendulum + " --at theta=0.1 --hold theta --json");
    REQUIRE(held.ok);
    CHECK(first_of(held.out, "q") == 0.1);
    const Run unknown = yamsc("trim " + pendulum + " --hold thta");
    CHECK_FALSE(unknown.ok);
    CHECK(unknown.err.find("did you mean 'theta'") != std::string::npos);
}

TEST_CASE("trim --adjust: the pitch of steady operation in wind, and lin about it") {
    const std::string operating = source + "/models/nrel5mw_land_operating.mbd --aero " + source +
                                  "/models/data/Cp_Ct_Cq.NREL5MW.txt --wind 16";
    const std::string rated = " --at \"psi'=1.2671\" --u pitch=0.2,gen_torque=43093.55";
    const Run r = yamsc("trim " + operating + rated + " --adjust pitch --json");
    REQUIRE(r.ok);
    CHECK(r.out.find("\"adjusted\":[\"pitch\"]") != std::string::npos);
    // inputs: V_wind, pitch, ...: the pitch that holds 12.1 rpm at rated torque
    const auto u = r.out.find("\"u\":[");
    REQUIRE(u != std::string::npos);
    const double pitch = std::strtod(r.out.c_str() + r.out.find(',', u) + 1, nullptr);
    CHECK(pitch == doctest::Approx(0.20899).epsilon(1e-4));

    const Run lin = yamsc("lin " + operating + rated + " --trim --adjust pitch");
    REQUIRE(lin.ok);
    CHECK(lin.err.find("not an equilibrium") == std::string::npos);
    // without the adjustment the rotor is out of balance: lin says so
    CHECK(yamsc("lin " + operating + rated + " --trim").err.find("not an equilibrium") !=
          std::string::npos);

    const Run two = yamsc("trim " + operating + rated + " --adjust pitch,gen_torque");
    CHECK_FALSE(two.ok);
    CHECK(two.err.find("2 input(s) for 1 DOF(s) held at a rate (psi)") != std::string::npos);
    const Run typo = yamsc("trim " + operating + rated + " --adjust pich");
    CHECK_FALSE(typo.ok);
    CHECK(typo.err.find("did you mean 'pitch'") != std::string::npos);
    // sweeping the input the rotor block declares as its wind while --wind sets it
    const Run both = yamsc("lin " + operating + rated + " --sweep V_wind=10:2:12");
    CHECK_FALSE(both.ok);
    CHECK(both.err.find("--sweep V_wind=.. sets the wind: drop --wind") != std::string::npos);
    CHECK_FALSE(yamsc("lin " + operating + rated + " --adjust pitch").ok); // needs --trim
}
