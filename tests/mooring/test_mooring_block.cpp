// The mooring lines as a load block on a body's mesh channels: its loads are the
// lines' force and moment in body axes, its derivatives exact against central
// differences of its own evaluation, its outputs the lines' tensions.
#include "mooring/oc3_lines.hpp"

#include <yamsc/mooring/mooring_block.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

using namespace yamsc::runtime;
using namespace yamsc::runtime::mooring;

namespace {

// The 18 mesh outputs of a body frame at a pose: r, v, w, then its axes.
std::vector<double> frame_reads(const Pose& p) {
    std::vector<double> r(18, 0.0);
    for (int i = 0; i < 3; ++i) {
        r[static_cast<std::size_t>(i)] = p.position[static_cast<std::size_t>(i)];
        for (int c = 0; c < 3; ++c)
            r[static_cast<std::size_t>(9 + 3 * c + i)] =
                p.rotation[static_cast<std::size_t>(3 * i + c)];
    }
    r[3] = 0.4; // velocities the quasi-static lines ignore
    r[8] = 0.01;
    return r;
}

Pose displaced() {
    // surge 12 m, sway -3 m, heave 1.5 m, turned 0.2 rad about z then 0.05 about y
    const double cz = std::cos(0.2), sz = std::sin(0.2), cy = std::cos(0.05), sy = std::sin(0.05);
    Pose p;
    p.position = {12.0, -3.0, 1.5};
    p.rotation = {cz * cy, -sz, cz * sy, sz * cy, cz, sz * sy, -sy, 0, cy};
    return p;
}

std::shared_ptr<const LoadBlock> block() {
    MooringSetup s;
    s.lines = test::oc3_lines();
    s.output_prefix = "moor_";
    for (int i = 0; i < 18; ++i) s.frame_outputs.push_back(40 + i);
    for (int i = 0; i < 6; ++i) s.loads.push_back(7 + i);
    return mooring_block(std::move(s));
}

} // namespace

TEST_CASE("the block's loads are the lines' force and moment in body axes; its outputs their "
          "tensions") {
    const auto b = block();
    CHECK(b->ports().outputs_read.size() == 18);
    CHECK(b->ports().loads == std::vector<int>{7, 8, 9, 10, 11, 12});
    CHECK(b->output_names() == std::vector<std::string>{"moor_T_fair1", "moor_T_fair2",
                                                        "moor_T_fair3", "moor_T_anch1",
                                                        "moor_T_anch2", "moor_T_anch3"});
    const Pose pose = displaced();
    const std::vector<double> r = frame_reads(pose);
    double loads[6], out[6];
    b->evaluate(0, nullptr, r.data(), loads, nullptr, out);
    const MooringLoads m = mooring_loads(test::oc3_lines(), pose);
    for (int row = 0; row < 3; ++row) {
        double f = 0, mo = 0;
        for (int i = 0; i < 3; ++i) {
            f += pose.rotation[static_cast<std::size_t>(3 * i + row)] *
                 m.force[static_cast<std::size_t>(i)];
            mo += pose.rotation[static_cast<std::size_t>(3 * i + row)] *
                  m.moment[static_cast<std::size_t>(i)];
        }
        CHECK(loads[row] == doctest::Approx(f).epsilon(1e-14));
        CHECK(loads[3 + row] == doctest::Approx(mo).epsilon(1e-14));
    }
    for (int k = 0; k < 3; ++k) {
        CHECK(out[k] == m.lines[static_cast<std::size_t>(k)].tension());
        // Without friction the anchor keeps H, and V where the line lies on the seabed is 0.
        CHECK(out[3 + k] ==
              doctest::Approx(m.lines[static_cast<std::size_t>(k)].solution.anchor_horizontal)
                  .epsilon(1e-14));
    }
}

TEST_CASE("the block's exact derivatives equal central differences of its evaluation") {
    const auto b = block();
    const std::vector<double> r = frame_reads(displaced());
    BlockJacobian exact, differences;
    b->derivatives(0, nullptr, r.data(), exact);
    central_differences(*b, 0, nullptr, r.data(), differences, 1e-7);
    REQUIRE(exact.loads_r.size() == differences.loads_r.size());
    double scale = 0;
    for (double v : exact.loads_r) scale = std::max(scale, std::abs(v));
    for (std::size_t i = 0; i < exact.loads_r.size(); ++i) {
        CAPTURE(i / 18);
        CAPTURE(i % 18);
        CHECK(std::abs(exact.loads_r[i] - differences.loads_r[i]) < 1e-6 * scale);
    }
}
