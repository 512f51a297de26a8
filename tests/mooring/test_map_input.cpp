// MAP++'s input file: the OC3-Hywind lines read and converted as MAP++ sets them
// up (weights in water, `depth`, REPEAT), and its errors located.
#include "analysis/map_mooring.hpp"
#include "diag/read_text.hpp"
#include "map/map_input.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <string>

using namespace yamsc;

namespace {

const analysis::MooringEnvironment oc3{320, 1025, 9.80665};

std::string file_text(const std::string& path) {
    diag::Diagnostics diags;
    const auto f = diag::read_text_file(path, diags);
    REQUIRE(f);
    return f->text();
}

std::string errors_of(const std::string& text) {
    auto file = std::make_shared<const diag::SourceFile>("moor.map", text);
    diag::Diagnostics diags;
    const auto in = map::read_map_input(file, diags);
    if (in) analysis::mooring_lines(*in, oc3, diags);
    return diags.render();
}

std::string replaced(std::string text, const std::string& what, const std::string& with) {
    const auto at = text.find(what);
    REQUIRE(at != std::string::npos);
    return text.replace(at, what.size(), with);
}

const std::string oc3_path = std::string(YAMSC_SOURCE_DIR) + "/tests/data/mooring/oc3_hywind.map";

} // namespace

TEST_CASE("the OC3-Hywind MAP++ file: three lines as MAP++ places them, the published weight "
          "and restoring matrix") {
    diag::Diagnostics diags;
    const auto lines = analysis::read_map_mooring(oc3_path, oc3, diags);
    INFO(diags.render());
    REQUIRE(lines);
    REQUIRE(lines->size() == 3);
    // Table 5-1's weight in water, 698.094 N/m: its printed digits, cut after the third
    // decimal (MAP++'s value is 698.09454).
    CHECK(std::abs((*lines)[0].properties.weight_in_fluid - 698.094) < 1e-3);
    CHECK((*lines)[0].anchor[2] == -320);
    // REPEAT turns the copies by minus the angle, at four decimals.
    CHECK((*lines)[1].anchor[0] == -426.935);
    CHECK((*lines)[1].anchor[1] == -739.4731);
    CHECK((*lines)[2].anchor[1] == 739.4731);
    CHECK((*lines)[1].fairlead[0] == -2.6);
    CHECK((*lines)[1].fairlead[1] == -4.5033);
    const auto m = runtime::mooring::mooring_loads(*lines, {});
    CHECK(-m.derivative[0] == doctest::Approx(41180).epsilon(0.002));
    CHECK(-m.derivative[6 * 2 + 2] == doctest::Approx(11940).epsilon(0.002));
    CHECK(-m.derivative[6 * 5 + 5] == doctest::Approx(11560000).epsilon(0.002));
    CHECK(-m.force[2] == doctest::Approx(1607000).epsilon(0.001));
}

TEST_CASE("MAP++ files with errors: each at its line and column") {
    const std::string good = file_text(oc3_path);
    CHECK(errors_of(good).empty());
    CHECK(errors_of(replaced(good, "384.243E6", "384.243Q6"))
              .find("moor.map:4:35: error: EA is not a number: '384.243Q6'") != std::string::npos);
    CHECK(errors_of(replaced(good, "1    Fix ", "1    Fixd"))
              .find("moor.map:8:6: error: unknown node type 'Fixd' (Fix, Vessel or Connect) "
                    "(did you mean 'Fix'?)") != std::string::npos);
    CHECK(errors_of(replaced(good, "-70.0", "depth"))
              .find("moor.map:9:34: error: `depth` (the water depth) is only for a Fix node's Z, "
                    "not for another node's") != std::string::npos);
    CHECK(errors_of(replaced(good, "1       chain", "1       chian"))
              .find("moor.map:13:9: error: unknown line type 'chian' (did you mean 'chain'?)") !=
          std::string::npos);
    CHECK(errors_of(replaced(good, "902.2     1         2", "902.2     1         3"))
              .find("moor.map:13:39: error: no node 3 (the file has 2)") != std::string::npos);
    CHECK(errors_of(replaced(good, "2    Vessel", "2    Connect"))
              .find("moor.map:9:1: error: Connect nodes (lines joined into a network) are not "
                    "supported") != std::string::npos);
    CHECK(errors_of(replaced(good, " outer_tol", " outer_toll"))
              .find("moor.map:18:2: warning: unknown MAP++ solver option 'outer_toll' (ignored) "
                    "(did you mean 'OUTER_TOL'?)") != std::string::npos);
    CHECK(errors_of(replaced(good, "1       chain", "3.3e45  chain"))
              .find("moor.map:13:1: error: Line must be a whole number from 1 to 10000") !=
          std::string::npos);
    std::string many = " repeat";
    for (int k = 1; k <= 361; ++k) many += " " + std::to_string(k);
    CHECK(errors_of(replaced(good, " repeat 120 240", many))
              .find("moor.map:19:2: error: more than 360 REPEAT angles") != std::string::npos);
    const std::string cut = good.substr(0, good.find("---------------------- LINE PROPERTIES"));
    CHECK(errors_of(cut).find("error: the MAP++ file ends before its LINE PROPERTIES section") !=
          std::string::npos);
    const std::string short_row =
        errors_of(replaced(good, "853.87     0        depth     0        0        #       #",
                           "853.87     0        depth"));
    CHECK(short_row.find("moor.map:8:1: error: a NODE PROPERTIES row needs 10 values, found 6") !=
          std::string::npos);
    CHECK(short_row.find("out of order") == std::string::npos); // the next node is still node 2
}
