// `yamsc from-openfast`: what the model written from a deck contains, the DOF switches,
// the lumped rigid rotor, and the reports of entries that are not converted.
#include "diag/diagnostics.hpp"
#include "driver/bindings.hpp"
#include "validation_support.hpp"

#include <fstream>
#include <regex>

using namespace validation;

namespace {

/// The value of `param NAME = value` in a model text.
double param(const std::string& text, const std::string& name) {
    std::smatch m;
    REQUIRE(std::regex_search(text, m, std::regex("param " + name + " = ([-0-9.e+]+)")));
    return std::stod(m[1].str());
}

std::vector<std::string> dofs(const std::string& text) {
    std::vector<std::string> out;
    const std::regex dof("\\ndof ([a-z0-9_]+)");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), dof);
         it != std::sregex_iterator(); ++it)
        out.push_back((*it)[1].str());
    return out;
}

} // namespace

TEST_CASE("the land deck: its DOFs, initial state, tower-top joint and OpenFAST channels") {
    const std::string report = convert(land_case);
    CHECK(report.find("3 DOFs (q_fa1, q_ss1, psi)") != std::string::npos);
    const std::string text = read(model_path(land_case));
    CHECK(dofs(text) == std::vector<std::string>{"q_fa1", "q_ss1", "psi"});
    // TTDspFA = 2 and TTDspSS = -2 become the tower modes; RotSpeed = 10 rpm the rate.
    CHECK(text.find("q_fa1 = 2 ") != std::string::npos);
    CHECK(text.find("q_ss1 = -2 ") != std::string::npos);
    CHECK(text.find("psi' = 10 * pi / 30 ") != std::string::npos);
    CHECK(text.find("linearize { psi' = 10 * pi / 30 }") != std::string::npos);
    CHECK(text.find("joint tower.tip -> nacelle { elastic_rotation = exact }") !=
          std::string::npos);
    CHECK(text.find("output Q_TSS1 = -q_ss1") != std::string::npos);
    CHECK(text.find("NRELOffshrBsline5MW_Offshore_ElastoDyn_Tower.dat\" elastodyn_tower") !=
          std::string::npos);
    CHECK(text.find("elements = 100") != std::string::npos); // TwrNodes, ElastoDyn's elements
    CHECK(param(text, "TowerBsHt") == 20);
    CHECK(param(text, "NacYIner") == 2.60789e6);
    // The .fst run and the ignored entries are named with their lines.
    CHECK(text.find("TMax = 4 s, DT = 0.01 s") != std::string::npos);
    CHECK(text.find("Spar_ED_ForED.dat: Echo:4, Method:5, DT:6") != std::string::npos);
    // The rigid rotor carries the generator's inertia and torque: the shaft's share.
    CHECK(text.find("output LSShftMxa = -reaction_moment(rotor).x / 1000 + (GBRatio * "
                    "gen_torque + GenIner * GBRatio^2 * psi'') / 1000 in rotor") !=
          std::string::npos);
}

TEST_CASE("the rigid rotor is lumped as ElastoDyn lumps it (independent numbers)") {
    // Hub 56780 kg and 115926 kg m^2; three 61.5 m blades (AdjBlMs = 1.04536) on 100
    // elements, coned -2.5 deg: computed independently with numpy (docs/validation.md).
    const std::string text = read(model_path(land_case));
    CHECK(param(text, "RotMass") == doctest::Approx(109582.3424).epsilon(1e-9));
    CHECK(param(text, "RotCMx") == doctest::Approx(-0.4628969134).epsilon(1e-8));
    CHECK(param(text, "RotIxx") == doctest::Approx(38479110.19).epsilon(1e-9));
    CHECK(param(text, "RotIyy") == doctest::Approx(19231242.39).epsilon(1e-9));
    CHECK(param(text, "RotIzz") == param(text, "RotIyy"));
    // The floating deck has BldNodes = 17: a little less mass, as in ElastoDyn.
    convert(floating_case);
    const std::string floating = read(model_path(floating_case));
    CHECK(param(floating, "RotMass") == doctest::Approx(109389.8424).epsilon(1e-9));
    CHECK(param(floating, "PtfmCMzt") == -90);
    CHECK(floating.find("com = (PtfmCMxt, PtfmCMyt, PtfmCMzt - PtfmRefzt)") != std::string::npos);
    CHECK(floating.find("{ at (0, 0, PtfmRefzt); translate x surge; rotate y pitch }") !=
          std::string::npos);
    CHECK(floating.find("pitch = 1 deg") != std::string::npos);
    // GenDOF off: the rotor turns at the fixed RotSpeed (0 here).
    CHECK(floating.find("rotate x psi0 + Omega0 * t") != std::string::npos);
}

TEST_CASE("--dofs switches ElastoDyn's flags; unknown flags are usage errors") {
    Case c = land_case;
    c.model = "land_switched";
    convert(c, {{"TwSSDOF1", false}, {"yawdof", true}, {"DrTrDOF", true}});
    const std::string text = read(model_path(c));
    CHECK(dofs(text) == std::vector<std::string>{"q_fa1", "nac_yaw", "psi", "drtr"});
    CHECK(text.find("spring drtr stiffness DTTorSpr damping DTTorDmp") != std::string::npos);
    CHECK(text.find("output Azimuth = (psi + drtr) * 180 / pi") != std::string::npos);
    CHECK(text.find("rotate z nac_yaw") != std::string::npos);
    CHECK(text.find("q_ss1") == std::string::npos);
    yamsc::driver::FromOpenFastOptions o;
    o.deck = reference_dir + "/" + land_case.folder + "/Main_Spar_ED.fst";
    o.output = work_dir + "/never.mbd";
    o.dofs = {{"TwFADOF3", true}};
    std::ostringstream out, err;
    CHECK_THROWS_WITH_AS(yamsc::openfast::from_openfast(o, out, err),
                         "--dofs: unknown ElastoDyn DOF 'TwFADOF3' (did you mean 'TwFADOF1'?)",
                         yamsc::driver::UsageError);
}

TEST_CASE("flexible blades, tower modes 2 and the drivetrain: the full 16-DOF onshore deck") {
    Case c = land_case;
    c.model = "nrel5mw_16dof";
    yamsc::driver::FromOpenFastOptions o;
    o.deck = std::string(YAMSC_TEST_DATA_DIR) + "/nrel5mw/NREL5MW_ED_Onshore.dat";
    o.output = model_path(c);
    std::ostringstream out, err;
    REQUIRE(yamsc::openfast::from_openfast(o, out, err) == 0);
    // This ElastoDyn file predates Gravity in ElastoDyn: said, and the standard value used.
    CHECK(err.str().find("no Gravity in the deck: using 9.80665") != std::string::npos);
    const std::string text = read(o.output);
    CHECK(dofs(text).size() == 16);
    CHECK(text.find("joint hub -> blade2 { rotate x 120 deg; rotate y PreCone2; at (0, 0, "
                    "HubRad) }") != std::string::npos);
    CHECK(text.find("modes = (flap1 -> q_b3_flap1, edge1 -> q_b3_edge1, flap2 -> q_b3_flap2)") !=
          std::string::npos);
    // ElastoDyn's generator: GenIner geared at GBRatio; the low-speed shaft is massless.
    CHECK(text.find("rigid gen_shaft { mass = 0 }") != std::string::npos);
    CHECK(text.find("rigid generator { mass = 0; inertia = (GenIner, 0, 0) }") !=
          std::string::npos);
    CHECK(text.find("rotate x GBRatio * psi }") != std::string::npos);
    CHECK(text.find("elements = 17") != std::string::npos); // BldNodes
    // The blades' second-order spin inertia on the hub, and the tip deflections.
    CHECK(text.find("torque on hub in hub = (-((") != std::string::npos);
    // The Coriolis forces of the radial shortening: gyroscopic, so the flap-1 force of the
    // edge rate and the edge force of the flap rate have opposite coefficients,
    // 2 (D_e,11 - D_1,e1) with D_i,jk = sum over the elements of m cos(cone) Phi_y,i AxRedBld_jk.
    CHECK(text.find("genforce q_b1_flap1 = (psi' + drtr') * (42.6455576654") != std::string::npos);
    CHECK(text.find("genforce q_b1_edge1 = (psi' + drtr') * (-42.6455576654") != std::string::npos);
    CHECK(text.find("output OoPDefl1 = ") != std::string::npos);
    CHECK(text.find("output TTDspSS = position(nacelle).y in tower") != std::string::npos);
    CHECK(param(text, "GenIner") == 534.116);
    CHECK(param(text, "ShftGagL") == 1.912);
    // ElastoDyn's load channels: minus the joints' reactions, in kN and kN m.
    for (const char* line :
         {"output TwrBsMyt = -reaction_moment(tower).y / 1000 in tower",
          "output RootMyb1 = -reaction_moment(blade1).y / 1000 in blade1",
          "output LSShftMxa = -reaction_moment(hub).x / 1000 in hub",
          "output LSSGagMya = -(reaction_moment(hub).y + ShftGagL * reaction_force(hub).z) / "
          "1000 in hub",
          "output RotThrust = -reaction_force(hub).x / 1000 in hub"})
        CHECK_MESSAGE(text.find(line) != std::string::npos, line);
}

TEST_CASE("ElastoDyn's strain gauges become section loads in the gauges' deflected axes") {
    ::mkdir(work_dir.c_str(), 0755);
    // The 16-DOF onshore deck with two tower and two blade gauges.
    const std::string nrel = std::string(YAMSC_TEST_DATA_DIR) + "/nrel5mw/";
    std::string ed = read(nrel + "NREL5MW_ED_Onshore.dat");
    ed = std::regex_replace(ed, std::regex("\"NRELOffshrBsline5MW_"),
                            "\"" + nrel + "NRELOffshrBsline5MW_");
    ed = std::regex_replace(ed, std::regex(" 0   NTwGages"), " 2   NTwGages");
    ed = std::regex_replace(ed, std::regex(" 10   TwrGagNd"), " 10, 19   TwrGagNd");
    ed = std::regex_replace(ed, std::regex(" 0   NBlGages"), " 1   NBlGages");
    const std::string path = work_dir + "/gauges_ED.dat";
    std::ofstream(path) << ed;
    yamsc::driver::FromOpenFastOptions o;
    o.deck = path;
    o.output = work_dir + "/gauges.mbd";
    std::ostringstream out, err;
    REQUIRE(yamsc::openfast::from_openfast(o, out, err) == 0);
    const std::string text = read(o.output);
    // ElastoDyn's element J is the SID node J + 1; the channels are minus the
    // sections' loads, the blade's turned by the structural twist (6.55 deg at
    // element 9 of 17, ElastoDyn's ThetaS).
    for (const char* line :
         {"output TwHt1MLxt = -reaction_moment(tower.node(11)).x / 1000 in tower.node(11)",
          "output TwHt2MLyt = -reaction_moment(tower.node(20)).y / 1000 in tower.node(20)",
          "output TwHt2MLzt = -reaction_moment(tower.node(20)).z / 1000 in tower.node(20)",
          "output Spn1MLzb1 = -reaction_moment(blade1.node(10)).z / 1000 in blade1.node(10)",
          "output Spn1MLxb1 = (-0.993", "output Spn1MLyb1 = (-0.114"})
        CHECK_MESSAGE(text.find(line) != std::string::npos, line);
    CHECK(text.find("TwHt3") == std::string::npos);
    CHECK(text.find("Spn2") == std::string::npos);
    // Used, so not in the list of ignored entries.
    CHECK(text.find("NTwGages:") == std::string::npos);
    CHECK(text.find("BldGagNd:") == std::string::npos);
    std::ostringstream check_out, check_err;
    yamsc::driver::CheckOptions c;
    c.model = o.output;
    CHECK(yamsc::driver::check(c, check_out, check_err) == 0);
    CHECK(check_err.str().find("error") == std::string::npos);
}

TEST_CASE("unknown and unsupported entries are warnings at their line, never dropped") {
    ::mkdir(work_dir.c_str(), 0755);
    // A copy of the land deck's ElastoDyn file with an unknown entry and furling on; its
    // blade and tower files named by absolute paths.
    std::string ed = read(reference_dir + "/" + land_case.folder + "/Spar_ED_ForED.dat");
    const std::string nrel = std::string(YAMSC_TEST_DATA_DIR) + "/nrel5mw/";
    ed = std::regex_replace(ed, std::regex("\\.\\./\\.\\./nrel5mw/"), nrel);
    ed = std::regex_replace(ed, std::regex("False         Furling"), "True          Furling");
    ed = std::regex_replace(ed, std::regex("  0   PtfmPitch"), "  2   PtfmPitch");
    ed = std::regex_replace(ed, std::regex("(\\n\\s+0\\s+TipMass\\(1\\))"),
                            "\n      42   FooBar      - an entry ElastoDyn never had$1");
    const std::string path = work_dir + "/odd_ED.dat";
    std::ofstream(path) << ed;
    yamsc::driver::FromOpenFastOptions o;
    o.deck = path;
    o.output = work_dir + "/odd.mbd";
    std::ostringstream out, err;
    REQUIRE(yamsc::openfast::from_openfast(o, out, err) == 0);
    CHECK(err.str().find("odd_ED.dat:73:7: warning: unknown ElastoDyn entry 'FooBar': not "
                         "converted [unknown-property]") != std::string::npos);
    CHECK(err.str().find("odd_ED.dat:107:1: warning: furling is not converted") !=
          std::string::npos);
    CHECK(out.str().find("2 warning(s)") != std::string::npos);
    // PtfmPitch is "initial or fixed": with its DOF off, the platform is held there.
    const std::string text = read(o.output);
    CHECK(text.find("joint ground -> platform { at (0, 0, PtfmRefzt); rotate y 2 deg }") !=
          std::string::npos);
    CHECK(text.find("input hydro_fx") == std::string::npos);
}

TEST_CASE("a deck with a bad value fails with its location and writes nothing") {
    ::mkdir(work_dir.c_str(), 0755);
    std::string ed = read(reference_dir + "/" + land_case.folder + "/Spar_ED_ForED.dat");
    ed = std::regex_replace(ed, std::regex("240000   NacMass"), "heavy    NacMass");
    const std::string path = work_dir + "/bad_ED.dat";
    std::ofstream(path) << ed;
    yamsc::driver::FromOpenFastOptions o;
    o.deck = path;
    o.output = work_dir + "/bad.mbd";
    std::remove(o.output.c_str());
    std::ostringstream out, err;
    CHECK(yamsc::openfast::from_openfast(o, out, err) == 1);
    CHECK(err.str().find("bad_ED.dat:79:6: error: 'NacMass' must be a number, not 'heavy'") !=
          std::string::npos);
    CHECK(!std::ifstream(o.output).good());
}
