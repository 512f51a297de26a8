// `--mooring` takes MAP++'s and MoorDyn's files: told apart by their sections,
// both read as the same quasi-static lines, and a file that is neither refused
// at its first line. The OC3-Hywind lines of both files, closed around the rigid
// spar, give the same forcing (to the π MAP++ rounds, docs/mooring.md).
#include "analysis/load_blocks.hpp"
#include "analysis/loaded_model.hpp"
#include "analysis/mooring_files.hpp"
#include "codegen/routines.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace yamsc;

namespace {

const std::string data = std::string(YAMSC_TEST_DATA_DIR) + "/mooring/";

} // namespace

TEST_CASE("mooring files: MAP++'s and MoorDyn's told apart by their sections") {
    CHECK(analysis::mooring_format("---------------------- LINE DICTIONARY ----\n") ==
          analysis::MooringFormat::map);
    CHECK(analysis::mooring_format("x\n--------- line types ---------\n") ==
          analysis::MooringFormat::moordyn);
    // A name in a row is not a header: only lines with dashes count.
    CHECK_FALSE(analysis::mooring_format("LINE TYPES\nLINE DICTIONARY\n"));
    CHECK_FALSE(analysis::mooring_format(""));
    CHECK(analysis::mooring_format_info(analysis::MooringFormat::moordyn).name == "MoorDyn");
}

TEST_CASE("mooring files: both files give the OC3-Hywind lines; neither is refused") {
    const analysis::MooringEnvironment oc3{320, 1025, 9.80665};
    diag::Diagnostics dm, dd;
    const auto map = analysis::read_mooring_file(data + "oc3_hywind.map", oc3, dm);
    const auto moordyn = analysis::read_mooring_file(data + "oc3_hywind_moordyn.dat", oc3, dd);
    REQUIRE_MESSAGE(map, dm.render());
    REQUIRE_MESSAGE(moordyn, dd.render());
    CHECK(dd.render().find("quasi-static") != std::string::npos); // MoorDyn's warning
    REQUIRE(map->size() == 3);
    REQUIRE(moordyn->size() == 3);
    // MoorDyn lists the anchors in another order: match them by anchor.
    for (const auto& a : *map) {
        bool found = false;
        for (const auto& b : *moordyn)
            if (std::hypot(a.anchor[0] - b.anchor[0], a.anchor[1] - b.anchor[1]) < 1e-3) {
                found = true;
                CHECK(b.properties.length == a.properties.length);
                // MAP++'s π is 3.14159264: its weight in water is 4e-10 larger.
                CHECK(b.properties.weight_in_fluid ==
                      doctest::Approx(a.properties.weight_in_fluid).epsilon(1e-9));
                for (int i = 0; i < 3; ++i) CHECK(b.fairlead[i] == doctest::Approx(a.fairlead[i]));
            }
        CHECK(found);
    }

    const auto dir = std::filesystem::temp_directory_path() / "yamsc_mooring_files";
    std::filesystem::create_directories(dir);
    const auto bad = dir / "lines.txt";
    std::ofstream(bad) << "three lines\n--- NODES ---\n";
    diag::Diagnostics db;
    CHECK_FALSE(analysis::read_mooring_file(bad, oc3, db));
    CHECK(db.render().find("lines.txt:1:1: error: not a mooring file") != std::string::npos);
}

TEST_CASE("mooring files: --mooring with MoorDyn's file closes the spar as with MAP++'s") {
    std::ostringstream err;
    auto l = analysis::load(std::string(YAMSC_SOURCE_DIR) + "/models/oc3_spar_rigid.mbd", {}, "",
                            false, err, {}, codegen::abi_routines());
    REQUIRE_MESSAGE(l, err.str());
    analysis::BlockOptions with_map, with_moordyn;
    with_map.mooring = data + "oc3_hywind.map";
    with_moordyn.mooring = data + "oc3_hywind_moordyn.dat";
    const runtime::ModelView a = analysis::with_load_blocks(*l, with_map);
    const runtime::ModelView b = analysis::with_load_blocks(*l, with_moordyn);
    const std::vector<double> q{3.0, -1.0, 0.5, 0.02, 0.05, 0.1}, qd(6, 0.0), u(a.nu, 0.0);
    std::vector<double> Fa(6), Fb(6);
    a.forcing(0, q.data(), qd.data(), u.data(), Fa.data());
    b.forcing(0, q.data(), qd.data(), u.data(), Fb.data());
    for (int i = 0; i < 6; ++i) CHECK(Fb[i] == doctest::Approx(Fa[i]).epsilon(1e-8));
    CHECK(std::fabs(Fa[0]) > 1e4); // the surge offset is held back by the lines
}
