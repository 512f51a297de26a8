// `yamsc from-openfast` on a full deck (.fst with InflowWind, AeroDyn and ServoDyn):
// the rotor block's parameters, the wind, the generator and the controller hookup it
// writes, and a model that runs in wind exactly as the shipped operating model does.
#include "driver/values.hpp"
#include "validation_support.hpp"

#include <cmath>
#include <filesystem>
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

std::string convert_full_deck(const std::string& output, const std::string& cp_table,
                              std::string* log = nullptr) {
    ::mkdir(work_dir.c_str(), 0755);
    yamsc::driver::FromOpenFastOptions o;
    o.deck = deck;
    o.output = output;
    o.dofs = operating_dofs;
    o.cp_table = cp_table;
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

Table run_in_wind(const std::string& model, const std::string& name) {
    yamsc::driver::SimOptions o;
    o.model = model;
    o.aero = table;
    o.wind = "8";
    o.tmax = 5;
    o.dt = 0.02;
    o.set = yamsc::driver::parse_assignments("VS_Rgn2K=2.31055", "--set");
    o.output = work_dir + "/" + name + ".csv";
    std::ostringstream out, err;
    REQUIRE_MESSAGE(yamsc::analysis::sim(o, out, err) == 0, err.str());
    return yamsc::analysis::read_table(o.output);
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

TEST_CASE("a full deck's sheared steady wind is taken at the hub height") {
    // The deck with InflowWind's power law (PLexp 0.14 from RefHt 50 m): the rotor
    // block reads the wind at the apex, 87.6 + 1.96256 + 5.0191 sin(5 deg) = 90.0 m.
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
