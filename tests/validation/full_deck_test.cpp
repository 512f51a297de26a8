// `yamsc from-openfast` on a full deck (.fst with InflowWind, AeroDyn and ServoDyn):
// the rotor block's parameters, the wind, the generator and the controller hookup it
// writes, and a model that runs in wind exactly as the shipped operating model does.
#include "driver/values.hpp"
#include "validation_support.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <regex>

using namespace validation;
using yamsc::analysis::Table;

namespace {

const std::string deck = reference_dir + "/operating/deck/NREL-5MW.fst";
const std::string models = std::string(YAMSC_SOURCE_DIR) + "/models";
const std::string table = models + "/data/Cp_Ct_Cq.NREL5MW.txt";

/// The shipped operating model's DOFs: tower FA1/SS1, generator, drivetrain.
const std::vector<std::pair<std::string, bool>> operating_dofs{
    {"FlapDOF1", false}, {"FlapDOF2", false}, {"EdgeDOF", false},
    {"TwFADOF2", false}, {"TwSSDOF2", false}, {"YawDOF", false}};

std::string
convert_full_deck(const std::string& output, const std::string& cp_table,
                  std::string* log = nullptr,
                  const std::vector<std::pair<std::string, bool>>& dofs = operating_dofs,
                  const std::string& fst = deck) {
    ::mkdir(work_dir.c_str(), 0755);
    yamsc::driver::FromOpenFastOptions o;
    o.deck = fst;
    o.output = output;
    o.dofs = dofs;
    o.cp_table = cp_table;
    o.aero = yamsc::driver::RotorAero::table; // these tests are the table rotor's
    std::ostringstream out, err;
    REQUIRE_MESSAGE(yamsc::openfast::from_openfast(o, out, err) == 0, err.str());
    if (log) *log = out.str() + err.str();
    return read(output);
}

double param(const std::string& text, const std::string& name) {
    std::smatch m;
    REQUIRE_MESSAGE(std::regex_search(text, m, std::regex("\nparam " + name + " = ([-0-9.e+]+)")),
                    "no param " << name);
    return std::stod(m[1].str());
}

/// `yamsc sim MODEL --aero TABLE --wind 8 -o WORK/NAME.csv` with the options `more`
/// sets, and the table it writes.
Table sim_8mps(const std::string& model, const std::string& name,
               const std::function<void(yamsc::driver::SimOptions&)>& more) {
    yamsc::driver::SimOptions o;
    o.model = model;
    o.aero = table;
    o.wind = "8";
    o.output = work_dir + "/" + name + ".csv";
    more(o);
    std::ostringstream out, err;
    REQUIRE_MESSAGE(yamsc::analysis::sim(o, out, err) == 0, err.str());
    return yamsc::analysis::read_table(o.output);
}

Table run_in_wind(const std::string& model, const std::string& name) {
    return sim_8mps(model, name, [](yamsc::driver::SimOptions& o) {
        o.tmax = 5;
        o.dt = 0.02;
        o.set = yamsc::driver::parse_assignments("VS_Rgn2K=2.31055", "--set");
    });
}

} // namespace

TEST_CASE("a full deck: the rotor block, the wind, the generator and the controller hookup") {
    std::string log;
    const std::string text = convert_full_deck(work_dir + "/full_deck.mbd", "", &log);
    // AeroDyn: TipRad (ElastoDyn) and AirDens (the .fst); ServoDyn: GenEff, a DLL
    // controller (no region-2 law of ServoDyn's own).
    CHECK(param(text, "rotor_radius") == 63);
    CHECK(param(text, "air_density") == 1.225);
    CHECK(param(text, "GenEff") == 94.4);
    CHECK(param(text, "VS_Rgn2K") == 0);
    CHECK(text.find("NREL-5MW.fst:32") != std::string::npos);
    CHECK(text.find("NRELOffshrBsline5MW_Onshore_ServoDyn.dat:30") != std::string::npos);
    CHECK(text.find("\ninput V_wind ") != std::string::npos);
    CHECK(text.find("\ninput pitch ") != std::string::npos);
    // The command: the table ROSCO reads (DISCON.IN's PerfFileName), InflowWind's
    // steady 8 m/s, ServoDyn's DLL and its input, the .fst's run.
    CHECK(text.find("#   yamsc sim full_deck.mbd \\\n") != std::string::npos);
    CHECK(text.find("operating/deck/Cp_Ct_Cq.NREL5MW.txt \\\n") != std::string::npos);
    CHECK(text.find("#     --wind 8 \\\n") != std::string::npos);
    CHECK(text.find("operating/rosco_build/libdiscon.so \\\n") != std::string::npos);
    CHECK(text.find("operating/deck/DISCON.IN \\\n") != std::string::npos);
    CHECK(text.find("#     --tmax 200 --dt 0.00625\n") != std::string::npos);
    CHECK(text.find("#   (--aero from PerfFileName, DISCON.IN; --wind from "
                    "NRELOffshrBsline5MW_InflowWind.dat:14)\n") != std::string::npos);
    // The rotor block of --aero, declared on those channels (docs/language.md, Load blocks).
    CHECK(
        text.find("\nload rotor_table aero {\n"
                  "    wind = V_wind; pitch = pitch; thrust = thrust; rotor_torque = aero_torque\n"
                  "    speed = rotor_speed; hub_velocity = hub_shaft_velocity\n"
                  "    radius = rotor_radius; density = air_density\n}\n") != std::string::npos);
    // What the block and a controller read.
    for (const char* channel :
         {"output rotor_speed = (psi' + drtr')",
          "output hub_shaft_velocity = velocity(rotor).x in rotor",
          "output GenPwr = GenEff / 100 * GBRatio * psi' * (gen_torque + VS_Rgn2K * (GBRatio * "
          "psi')^2) / 1000",
          "output YawBrTAxp = q_fa1''", "output YawBrTAyp = q_ss1''"})
        CHECK_MESSAGE(text.find(channel) != std::string::npos, channel);
    // What is approximated is said at its line; the missing controller library too.
    CHECK(log.find("NREL-5MW.fst:20:11: warning: CompAero = 2: AeroDyn's blade elements") !=
          std::string::npos);
    CHECK(log.find("NRELOffshrBsline5MW_Onshore_ServoDyn.dat:86:1: warning: the controller "
                   "library '../rosco_build/libdiscon.so' does not exist") != std::string::npos);
    // ElastoDyn v5's new entries at their defaults are accounted for, not unknown.
    CHECK(log.find("unknown ElastoDyn entry") == std::string::npos);
    CHECK(text.find("PitchDOF:") != std::string::npos);

    // --cp-table names another table; it may not be the output.
    const std::string given = convert_full_deck(work_dir + "/full_deck_table.mbd", table);
    CHECK(given.find("models/data/Cp_Ct_Cq.NREL5MW.txt \\\n") != std::string::npos);
    yamsc::driver::FromOpenFastOptions o;
    o.deck = deck;
    o.output = table;
    o.cp_table = table;
    std::ostringstream out, err;
    CHECK_THROWS(yamsc::openfast::from_openfast(o, out, err));
}

TEST_CASE("a full deck's model runs in wind as the shipped operating model does") {
    // The same structure, block channels and generator: 5 s at 8 m/s with the
    // table and ServoDyn's region-2 law agree to rounding.
    convert_full_deck(work_dir + "/full_deck_run.mbd", "");
    const Table written = run_in_wind(work_dir + "/full_deck_run.mbd", "full_deck_8mps");
    const Table shipped = run_in_wind(models + "/nrel5mw_land_operating.mbd", "shipped_8mps");
    for (const char* channel :
         {"RotSpeed", "GenPwr", "TTDspFA", "Q_TFA1", "Q_DrTr", "aero_thrust"}) {
        const int a = written.find(channel), b = shipped.find(channel);
        REQUIRE_MESSAGE(a >= 0, channel);
        REQUIRE_MESSAGE(b >= 0, channel);
        const auto& x = written.data[static_cast<std::size_t>(a)];
        const auto& y = shipped.data[static_cast<std::size_t>(b)];
        REQUIRE(x.size() == y.size());
        double worst = 0, scale = 0;
        for (std::size_t i = 0; i < x.size(); ++i) {
            worst = std::max(worst, std::fabs(x[i] - y[i]));
            scale = std::max(scale, std::fabs(y[i]));
        }
        CHECK_MESSAGE(worst <= 1e-9 * scale, channel << ": " << worst << " of " << scale);
    }
    // It does move: the rotor block drives it (8.98 rpm start, table torque).
    const int rpm = shipped.find("RotSpeed");
    CHECK(shipped.data[static_cast<std::size_t>(rpm)].back() !=
          shipped.data[static_cast<std::size_t>(rpm)].front());
}

TEST_CASE("a full deck's sheared steady wind: InflowWind's file, or the hub height's speed") {
    // The deck with InflowWind's power law (PLexp 0.14 from RefHt 50 m): the table
    // rotor reads the wind at the apex, 87.6 + 1.96256 + 5.0191 sin(5 deg) = 90.0 m;
    // the blade elements the InflowWind file itself, its shear at every node.
    namespace fs = std::filesystem;
    const fs::path copy = fs::path(work_dir) / "deck_shear";
    fs::remove_all(copy);
    fs::copy(reference_dir + "/operating/deck", copy, fs::copy_options::recursive);
    std::string inflow = read((copy / "NRELOffshrBsline5MW_InflowWind.dat").string());
    inflow = std::regex_replace(inflow, std::regex("  90   RefHt "), "  50   RefHt ");
    inflow = std::regex_replace(inflow, std::regex("  0   PLexp "), "  0.14   PLexp ");
    std::ofstream((copy / "NRELOffshrBsline5MW_InflowWind.dat").string()) << inflow;
    yamsc::driver::FromOpenFastOptions o;
    o.deck = (copy / "NREL-5MW.fst").string();
    o.output = work_dir + "/full_deck_shear.mbd";
    {
        // The deck's own DOFs: flexible blades, the blade elements.
        std::ostringstream out, err;
        REQUIRE_MESSAGE(yamsc::openfast::from_openfast(o, out, err) == 0, err.str());
        const std::string text = read(o.output);
        CHECK(text.find("#     --wind deck_shear/NRELOffshrBsline5MW_InflowWind.dat \\\n") !=
              std::string::npos);
        CHECK(text.find("--wind from NRELOffshrBsline5MW_InflowWind.dat:5") != std::string::npos);
        CHECK(err.str().find("PLexp") == std::string::npos);
    }
    // Rigid blades with other DOFs: one rotor body, the table rotor.
    o.dofs = operating_dofs;
    std::ostringstream out, err;
    REQUIRE_MESSAGE(yamsc::openfast::from_openfast(o, out, err) == 0, err.str());
    const std::string text = read(o.output);
    std::smatch m;
    REQUIRE(std::regex_search(text, m, std::regex("#     --wind ([0-9.e+-]+) \\\\")));
    const double hub = 87.6 + 1.96256 + 5.0191 * std::sin(5 * M_PI / 180);
    CHECK(std::stod(m[1].str()) == doctest::Approx(8 * std::pow(hub / 50, 0.14)).epsilon(1e-12));
    CHECK(err.str().find("PLexp = 0.14") != std::string::npos);
}

TEST_CASE("a full deck in a TurbSim full field: the InflowWind file for either rotor") {
    // WindType 3: the blade elements sample the field at every node; the table rotor
    // reads its hub-height wind (the field's reference speed), with a warning.
    namespace fs = std::filesystem;
    const fs::path copy = fs::path(work_dir) / "deck_turbsim";
    fs::remove_all(copy);
    fs::create_directories(copy.parent_path());
    fs::copy(reference_dir + "/operating/deck", copy, fs::copy_options::recursive);
    std::string inflow = read((copy / "NRELOffshrBsline5MW_InflowWind.dat").string());
    std::string turbsim = inflow;
    const std::size_t type = turbsim.find(" 1   WindType");
    REQUIRE(type != std::string::npos);
    turbsim[type + 1] = '3';
    std::ofstream((copy / "NRELOffshrBsline5MW_InflowWind.dat").string()) << turbsim;
    yamsc::driver::FromOpenFastOptions o;
    o.deck = (copy / "NREL-5MW.fst").string();
    o.output = work_dir + "/full_deck_turbsim.mbd";
    for (const bool table_rotor : {false, true}) {
        CAPTURE(table_rotor);
        if (table_rotor) o.dofs = operating_dofs;
        std::ostringstream out, err;
        REQUIRE_MESSAGE(yamsc::openfast::from_openfast(o, out, err) == 0, err.str());
        const std::string text = read(o.output);
        CHECK(text.find("#     --wind deck_turbsim/NRELOffshrBsline5MW_InflowWind.dat \\\n") !=
              std::string::npos);
        CHECK(text.find("--wind from NRELOffshrBsline5MW_InflowWind.dat:5") != std::string::npos);
        CHECK((err.str().find("WindType = 3: the rotor block of a Cp/Ct/Cq table takes the "
                              "full field's hub-height wind") != std::string::npos) == table_rotor);
    }
}

namespace {

/// The deck copied to `folder`, its ServoDyn file edited by `edits` (regex -> text).
std::string deck_copy(const std::string& folder,
                      const std::vector<std::pair<std::string, std::string>>& edits) {
    namespace fs = std::filesystem;
    const fs::path copy = fs::path(work_dir) / folder;
    fs::remove_all(copy);
    fs::create_directories(copy.parent_path());
    fs::copy(reference_dir + "/operating/deck", copy, fs::copy_options::recursive);
    const fs::path servo = copy / "NRELOffshrBsline5MW_Onshore_ServoDyn.dat";
    std::string text = read(servo.string());
    for (const auto& [from, to] : edits) {
        const std::string edited = std::regex_replace(text, std::regex(from), to);
        REQUIRE_MESSAGE(edited != text, from);
        text = edited;
    }
    std::ofstream(servo.string()) << text;
    return (copy / "NREL-5MW.fst").string();
}

constexpr double yaw_spring = 9.02832e9; // YawSpr [N m/rad]
constexpr double pi = 3.14159265358979323846;

} // namespace

TEST_CASE("ServoDyn's yaw spring and damper (YCMode 0) act on the yaw DOF with the deck's values") {
    std::string log;
    const std::string text =
        convert_full_deck(work_dir + "/full_deck_yaw.mbd", "", &log, {{"YawDOF", true}});
    CHECK(param(text, "YawSpr") == 9.02832e9);
    CHECK(param(text, "YawDamp") == 1.916e7);
    CHECK(text.find("\nparam YawNeut = 0 deg ") != std::string::npos);
    for (const char* line : {"NRELOffshrBsline5MW_Onshore_ServoDyn.dat:63)",
                             "NRELOffshrBsline5MW_Onshore_ServoDyn.dat:64)",
                             "NRELOffshrBsline5MW_Onshore_ServoDyn.dat:65)"})
        CHECK_MESSAGE(text.find(line) != std::string::npos, line);
    // ServoDyn's YawMom = -YawSpr (yaw - YawNeut) - YawDamp yaw' on ElastoDyn's yaw DOF;
    // the `yaw_moment` input stays for other loads.
    CHECK(text.find("\nspring nac_yaw stiffness YawSpr damping YawDamp\n"
                    "genforce nac_yaw = YawSpr * YawNeut\n") != std::string::npos);
    CHECK(text.find("torque on nacelle in nacelle = (0, 0, yaw_moment)") != std::string::npos);
    CHECK(log.find("YCMode") == std::string::npos);
    // Without the yaw DOF there is nothing to hold.
    const std::string locked = convert_full_deck(work_dir + "/full_deck_no_yaw.mbd", "");
    CHECK(locked.find("YawSpr") == std::string::npos);
    CHECK(locked.find("spring nac_yaw") == std::string::npos);
}

TEST_CASE("yaw control and the override yaw maneuver are warnings; the spring holds YawNeut") {
    const std::string fst =
        deck_copy("deck_yaw_control", {{"          0   YCMode ", "          5   YCMode "},
                                       {"          0   YawNeut ", "        -12.5   YawNeut "},
                                       {"     9999.9   TYawManS ", "        100   TYawManS "}});
    std::string log;
    const std::string text = convert_full_deck(work_dir + "/full_deck_yaw_control.mbd", "", &log,
                                               {{"YawDOF", true}}, fst);
    CHECK(text.find("\nparam YawNeut = -12.5 deg ") != std::string::npos);
    CHECK(text.find("\nspring nac_yaw stiffness YawSpr damping YawDamp\n") != std::string::npos);
    CHECK(log.find("NRELOffshrBsline5MW_Onshore_ServoDyn.dat:61:11: warning: YCMode = 5: the yaw "
                   "commands are not converted") != std::string::npos);
    CHECK(log.find("NRELOffshrBsline5MW_Onshore_ServoDyn.dat:66:") != std::string::npos);
    CHECK(log.find("TYawManS = 100: the override yaw maneuver is not converted") !=
          std::string::npos);
    // ServoDyn's own range checks.
    const std::string bad =
        deck_copy("deck_yaw_bad", {{"1.916E\\+07   YawDamp ", "-1   YawDamp "}});
    yamsc::driver::FromOpenFastOptions o;
    o.deck = bad;
    o.output = work_dir + "/full_deck_yaw_bad.mbd";
    o.dofs = {{"YawDOF", true}};
    std::ostringstream out, err;
    CHECK(yamsc::openfast::from_openfast(o, out, err) == 1);
    CHECK(err.str().find("ServoDyn.dat:65:3: error: YawDamp must not be negative") !=
          std::string::npos);
}

TEST_CASE("ServoDyn's channels with --channels openfast: GenTq, GenPwr, BlPitch1") {
    // The operating DOFs at a given torque and pitch: GenTq is the torque in kN m,
    // GenPwr GenTq GenSpeed GenEff (94.4 %, the deck's), BlPitch1 = BldPitch1.
    convert_full_deck(work_dir + "/full_deck_channels.mbd", "");
    const Table t =
        sim_8mps(work_dir + "/full_deck_channels.mbd", "full_deck_channels", [](auto& o) {
            o.tmax = 2;
            o.dt = 0.02;
            o.u = yamsc::driver::parse_assignments("gen_torque=21000,pitch=1.5deg", "--u");
            o.channels = yamsc::driver::Channels::openfast;
        });
    const auto& torque = column(t, "GenTq_[kN-m]");
    const auto& power = column(t, "GenPwr_[kW]");
    const auto& speed = column(t, "GenSpeed_[rpm]");
    for (const char* name :
         {"BlPitch1_[deg]", "BlPitch2_[deg]", "BlPitch3_[deg]", "BldPitch1_[deg]"})
        for (double pitch : column(t, name)) CHECK(pitch == doctest::Approx(1.5).epsilon(1e-12));
    for (std::size_t i = 0; i < torque.size(); ++i) {
        CHECK(torque[i] == doctest::Approx(21).epsilon(1e-12));
        CHECK(power[i] == doctest::Approx(21 * speed[i] * pi / 30 * 0.944).epsilon(1e-9));
    }
    // The rotor speeds up or slows down: GenPwr follows GenSpeed, not a constant.
    CHECK(speed.back() != doctest::Approx(speed.front()).epsilon(1e-4));
}

namespace {

/// The full 16-DOF deck as from-openfast writes it, 25 s in 8 m/s with the table
/// rotor under a controller: the yaw spring holds the nacelle, the tower top stands
/// near OpenFAST's, the generator channels show the controller's torque.
void run_16dof_in_wind(const std::string& name, const std::string& controller,
                       const std::string& controller_input) {
    convert_full_deck(work_dir + "/full_deck_16dof.mbd", "", nullptr, {});
    const Table t = sim_8mps(work_dir + "/full_deck_16dof.mbd", name, [&](auto& o) {
        o.tmax = 25;
        o.dt = 0.00625; // the deck's DT; RK4 as the header's command
        o.dt_out = 0.025;
        o.controller = controller;
        o.controller_input = controller_input;
    });
    const Table openfast =
        yamsc::analysis::read_table(reference_dir + "/operating/openfast_steady_8mps.csv");
    // The table's torque Q about the shaft, tilted 5 deg (ShftTilt), has the yaw
    // component -Q sin(5 deg) on the nacelle (the generator's torque pair is internal);
    // the spring answers it with the static yaw -Q sin(5 deg) / YawSpr. On it rings
    // the yaw mode (2.7 Hz, 2 % damped), excited by the blades' vibrations (the table
    // gives them no aerodynamic damping). A free yaw turns under the same moment by
    // Q sin(5 deg) t^2 / (2 J), J ~ 2.5e7 kg m^2: about 100 deg in 25 s.
    const double mean_yaw = mean_after(t, "NacYaw", 10);
    const double static_yaw =
        -mean_after(t, "aero_torque_out", 10) * std::sin(5 * pi / 180) / yaw_spring * 180 / pi;
    double worst_yaw = 0;
    for (double y : column(t, "NacYaw")) worst_yaw = std::max(worst_yaw, std::fabs(y));
    MESSAGE(name << ": NacYaw, mean of 10-25 s " << mean_yaw << " deg (the spring's static "
                 << static_yaw << " deg), largest " << worst_yaw << " deg");
    CHECK(mean_yaw == doctest::Approx(static_yaw).epsilon(0.05));
    CHECK(worst_yaw < 10 * std::fabs(static_yaw));
    // Tower-top fore-aft displacement near OpenFAST's mean, 0.187 m.
    const double fa = mean_after(t, "TTDspFA", 15);
    const double fa_openfast = mean_after(openfast, "TTDspFA_[m]", 15);
    MESSAGE(name << ": TTDspFA, mean of 15-25 s: " << fa << " m, OpenFAST " << fa_openfast << " m");
    // The table's thrust at 8 m/s is 4-5 % above AeroDyn's BEM (dynamic inflow and
    // unsteady aerodynamics), and the tower bends 6-7 % more (docs/validation.md);
    // the shipped six-DOF model's 150 s runs hold 8 % too (operating_test.cpp).
    CHECK(fa == doctest::Approx(fa_openfast).epsilon(0.08));
    // The generator channels show the controller's torque and the deck's efficiency.
    const auto& torque = column(t, "GenTq");
    const auto& power = column(t, "GenPwr");
    const auto& speed = column(t, "GenSpeed");
    for (std::size_t i = 0; i < torque.size(); ++i)
        CHECK(power[i] == doctest::Approx(torque[i] * speed[i] * pi / 30 * 0.944).epsilon(1e-9));
    const double tq = mean_after(t, "GenTq", 15);
    MESSAGE(name << ": GenTq, mean of 15-25 s: " << tq << " kN m (OpenFAST "
                 << mean_after(openfast, "GenTq_[kN-m]", 15) << "), GenPwr "
                 << mean_after(t, "GenPwr", 15) << " kW");
    CHECK(tq == doctest::Approx(mean_after(openfast, "GenTq_[kN-m]", 15)).epsilon(0.05));
}

} // namespace

TEST_CASE("the full 16-DOF deck in 8 m/s wind under the baseline controller: the yaw spring "
          "holds the nacelle") {
    run_16dof_in_wind("full_deck_16dof_baseline", YAMSC_BASELINE_DISCON, "");
}

#ifdef YAMSC_ROSCO_DISCON
// Run by the `rosco` test (tests/CMakeLists.txt), which builds ROSCO.
TEST_CASE("the full 16-DOF deck in 8 m/s wind under ROSCO: the yaw spring holds the nacelle" *
          doctest::skip()) {
    run_16dof_in_wind("full_deck_16dof_rosco", YAMSC_ROSCO_DISCON,
                      std::string(YAMSC_TEST_DATA_DIR) + "/rosco/DISCON.IN");
}
#endif
