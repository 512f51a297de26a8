// The OC3-Hywind lines at the undisplaced platform against MAP++'s own summary
// of the same lines (MAP++ 1.20.10, as OpenFAST's OC3-Hywind regression deck
// writes it: water 1025 kg/m^3, 320 m deep, CB = 0.001, the copies at 240 and
// 120 degrees; its gravity is printed as 9.81, to two decimals, and its weight
// in water, 698.09 N/m, is that of 9.80665). Line 1 is the file's own line; lines 2 and 3 are
// REPEAT's copies, whose node positions MAP++ rounds to four decimals: the
// summary's fourth significant digit from the end tells them apart, and so
// must ours.
#include "analysis/map_mooring.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <string>

using namespace yamsc;

namespace {

struct SummaryLine {
    double H, V, H_anchor, L_bottom;
};

// MAP++'s summary: H, V at the fairlead, H at the anchor (V there is 0: the
// line lies on the seabed), Lb the length on the seabed.
const SummaryLine map_summary[3] = {{736939.290, 535727.992, 736845.198, 134.785},
                                    {736939.764, 535728.146, 736845.671, 134.785},
                                    {736939.764, 535728.146, 736845.671, 134.785}};

} // namespace

TEST_CASE("the OC3-Hywind lines at rest equal MAP++'s summary of the same deck") {
    const analysis::MooringEnvironment map_environment{320, 1025, 9.80665};
    diag::Diagnostics diags;
    const auto lines = analysis::read_map_mooring(std::string(YAMSC_SOURCE_DIR) +
                                                      "/tests/data/mooring/oc3_hywind_friction.map",
                                                  map_environment, diags);
    REQUIRE(lines);
    REQUIRE(lines->size() == 3);
    const runtime::mooring::MooringLoads m = runtime::mooring::mooring_loads(*lines, {});
    for (std::size_t k = 0; k < 3; ++k) {
        CAPTURE(k);
        const runtime::mooring::CatenarySolution& s = m.lines[k].solution;
        // The summary prints 3 decimals of newtons: 1e-3 N of 7e5 is 1.4e-9.
        CHECK(s.fairlead_horizontal == doctest::Approx(map_summary[k].H).epsilon(2e-9));
        CHECK(s.fairlead_vertical == doctest::Approx(map_summary[k].V).epsilon(2e-9));
        CHECK(s.anchor_horizontal == doctest::Approx(map_summary[k].H_anchor).epsilon(2e-9));
        CHECK(s.length_on_seabed == doctest::Approx(map_summary[k].L_bottom).epsilon(1e-5));
    }
    // Total: the three lines pull the spar down by 3 V and hold it centred.
    CHECK(m.force[2] == doctest::Approx(-(535727.992 + 2 * 535728.146)).epsilon(2e-9));
    CHECK(std::fabs(m.force[0]) < 1.0);
}
