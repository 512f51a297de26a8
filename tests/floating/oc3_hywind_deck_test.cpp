// The NREL 5-MW on the OC3-Hywind spar as an OpenFAST deck of our own
// (tests/data/oc3_hywind): `from-openfast` declares HydroDyn's strip theory and
// MAP++'s lines as blocks, and `lin --trim` of the turbine, parked and without
// aerodynamics, gives the system's frequencies beside the published ones
// (docs/validation.md, Floating: the OC3-Hywind turbine from its deck).
#include "floating_support.hpp"
#include "modes_at_rest.hpp"

#include "analysis/loaded_model.hpp"
#include "codegen/routines.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace {

using namespace yamsc;

// The blades rigid: the platform and tower modes are the ones compared, and the
// blades' nine DOFs would triple the model's compile time (docs/validation.md).
const std::string deck_path = floating::data_dir + "/oc3_hywind/OC3Hywind_RigidBlades.fst";

/// The lines' delta connection in yaw (NREL/TP-500-47535, Table 5-1: 98,340,000
/// N m/rad): the OC3 deck gives it as HydroDyn's AddCLin, which HydroDyn applies
/// with potential flow only (PotMod 1); with strip theory the model carries it.
/// 0 here, so that the deck's own system and the published one are one model
/// (one compilation) with C_yaw set per case.
const std::string yaw_spring = "\nparam C_yaw = 0  # the delta connection's yaw stiffness "
                               "[N m/rad]\ntorque on platform in ground = (0, 0, -C_yaw * yaw)\n";

/// Each DOF's frequency [Hz]: that of the mode in which it moves most, rotations
/// weighed by 100 m (the spar's pitch moves the reference point 70 m per radian
/// in surge, so an unweighed shape names pitch "surge").
std::map<std::string, double> frequencies(const std::string& model,
                                          const analysis::BlockOptions& blocks,
                                          const std::vector<driver::Assignment>& set = {}) {
    std::ostringstream err;
    auto l = analysis::load(model, set, "", false, err, {}, codegen::abi_routines());
    REQUIRE_MESSAGE(l, err.str());
    const runtime::ModelView v = analysis::with_load_blocks(*l, blocks);
    const auto modes = test_support::modes_at_rest(v);
    std::map<std::string, double> f, share;
    for (const runtime::Mode& m : modes) {
        std::vector<double> weighed(m.shape.size());
        for (std::size_t i = 0; i < m.shape.size(); ++i) {
            const std::string& dof = v.dof_names[i];
            const bool rotation = dof == "roll" || dof == "pitch" || dof == "yaw";
            weighed[i] = std::abs(m.shape[i]) * (rotation ? 100.0 : 1.0);
        }
        const double largest = *std::max_element(weighed.begin(), weighed.end());
        for (std::size_t i = 0; i < weighed.size(); ++i) {
            const std::string& dof = v.dof_names[i];
            if (weighed[i] / largest > share[dof]) {
                share[dof] = weighed[i] / largest;
                f[dof] = m.freq_hz;
            }
        }
        MESSAGE(model << ": " << m.freq_hz << " Hz");
    }
    return f;
}

} // namespace

TEST_CASE("the OC3-Hywind deck: from-openfast declares HydroDyn and MAP++ as load blocks") {
    const openfast::OpenFastDeck deck = floating::read_deck(deck_path);
    CHECK(deck.offshore.hydro_file == floating::data_dir + "/hydro/oc3_spar_strip.dat");
    CHECK(deck.offshore.mooring_file == floating::data_dir + "/mooring/oc3_hywind.map");
    CHECK(deck.offshore.sea_state_file == floating::data_dir + "/hydro/oc3_sea_state.dat");
    REQUIRE(deck.offshore.water_depth);
    REQUIRE(deck.offshore.water_density);
    CHECK(*deck.offshore.water_depth == 320);
    CHECK(*deck.offshore.water_density == 1025);
    CHECK(deck["PtfmMass"] == 7466330);
    const std::string text = floating::read(floating::convert(deck_path, "oc3_hywind"));
    CHECK(text.find("load hydrodyn hydro { platform = platform; depth = WtrDpth; density = "
                    "WtrDens; gravity = Gravity }") != std::string::npos);
    CHECK(text.find("load mooring lines {") != std::string::npos);
    CHECK(text.find("hydro_fx") == std::string::npos);
    for (const char* dof : {"surge", "sway", "heave", "roll", "pitch", "yaw", "q_fa1", "q_ss1"})
        CHECK(text.find(std::string("\ndof ") + dof + " ") != std::string::npos);
}

TEST_CASE("the OC3-Hywind deck: lin --trim's frequencies beside the published") {
    const openfast::OpenFastDeck deck = floating::read_deck(deck_path);
    // Still water: the deck's SeaState file is a JONSWAP sea, whose loads at t = 0
    // would be part of the trimmed point (a free decay is run in still water).
    analysis::BlockOptions blocks = floating::deck_blocks(deck);
    blocks.sea_state.clear();
    const std::string model = floating::convert(deck_path, "oc3_hywind");
    {
        std::ofstream(floating::work_dir + "/oc3_hywind_yaw_spring.mbd")
            << floating::read(model) << yaw_spring;
    }
    const std::string with_spring = floating::work_dir + "/oc3_hywind_yaw_spring.mbd";
    const auto deck_f = frequencies(with_spring, blocks, {{"C_yaw", 0, 0}});
    const auto f = frequencies(with_spring, blocks, {{"C_yaw", 0, 98340000}});

    // The system as the deck defines it, to what this model gives (the tolerances
    // the eigen-solution's round-off and trim's residual, not the physics).
    CHECK(f.at("surge") == doctest::Approx(0.0080625).epsilon(1e-3));
    CHECK(f.at("sway") == doctest::Approx(0.0080625).epsilon(1e-3));
    CHECK(f.at("heave") == doctest::Approx(0.032939).epsilon(1e-3));
    CHECK(f.at("roll") == doctest::Approx(0.033188).epsilon(1e-3));
    CHECK(f.at("pitch") == doctest::Approx(0.033198).epsilon(1e-3));
    CHECK(f.at("q_ss1") == doctest::Approx(0.47262).epsilon(1e-3));
    CHECK(f.at("q_fa1") == doctest::Approx(0.47887).epsilon(1e-3));
    // Yaw: the lines alone (OpenFAST's strip-theory run of this deck) and with the
    // delta connection's spring.
    CHECK(deck_f.at("yaw") == doctest::Approx(0.039345).epsilon(1e-3));
    CHECK(f.at("yaw") == doctest::Approx(0.12119).epsilon(2e-3));

    // Beside the published full-system values (Jonkman, NREL/TP-500-47535; RAFT),
    // each tolerance the reason of docs/validation.md's table:
    CHECK(f.at("surge") == doctest::Approx(0.008).epsilon(0.0625)); // one digit
    CHECK(f.at("heave") == doctest::Approx(0.0324).epsilon(0.02));  // WAMIT's keel A33
    CHECK(f.at("pitch") == doctest::Approx(0.034).epsilon(0.025));  // two digits, panels
    CHECK(f.at("roll") == doctest::Approx(0.034).epsilon(0.025));
    CHECK(f.at("yaw") == doctest::Approx(0.121).epsilon(0.005)); // three digits
    // The tower's first modes in the coupled system, 0.48-0.50 Hz published:
    // fore-aft at the band's lower end; side-side below it, since the locked rotor
    // turns about its shaft in side-side (its polar inertia) and about a diameter
    // in fore-aft (half of it). Flexible blades lower both by 2-3 %, below the band
    // (docs/validation.md).
    CHECK(f.at("q_fa1") == doctest::Approx(0.48).epsilon(0.005));
    CHECK(f.at("q_ss1") < f.at("q_fa1"));
}

TEST_CASE("the OC3-Hywind deck with flexible blades: the platform's frequencies unchanged") {
    // The full deck (19 DOFs: the blades' flap 1, flap 2, edge 1 on): the platform
    // modes are the rigid-blade deck's. The tower's couple with the blades' flap
    // (0.4663 and 0.4688 Hz, their shapes led by the blade tips): not told apart
    // here (docs/validation.md).
    const std::string fst = floating::data_dir + "/oc3_hywind/OC3Hywind.fst";
    analysis::BlockOptions blocks = floating::deck_blocks(floating::read_deck(fst));
    blocks.sea_state.clear();
    const auto f = frequencies(floating::convert(fst, "oc3_hywind_flexible"), blocks);
    CHECK(f.at("surge") == doctest::Approx(0.0080625).epsilon(1e-3));
    CHECK(f.at("heave") == doctest::Approx(0.032939).epsilon(1e-3));
    CHECK(f.at("pitch") == doctest::Approx(0.033198).epsilon(1e-3));
    CHECK(f.at("yaw") == doctest::Approx(0.039345).epsilon(1e-3));
}
