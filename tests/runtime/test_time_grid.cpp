// The output time grid shared by the integrators.
#include "yamsc/integration.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <string>

using namespace yamsc::runtime;

TEST_CASE("a grid whose step divides the span has no sliver step at the end") {
    const TimeGrid grid(0.0, 0.3, 0.1); // 0.3 / 0.1 = 2.9999999999999996 in doubles
    REQUIRE(grid.size() == 4);
    CHECK(grid[1] == 0.1);
    CHECK(grid[2] == 0.2);
    CHECK(grid[3] == 0.3);

    const TimeGrid long_run(0.0, 1000.0, 0.001);
    CHECK(long_run.size() == 1000001);
    CHECK(long_run[500000] == 500.0); // computed, not accumulated
}

TEST_CASE("a grid whose step does not divide the span ends with a short step") {
    const TimeGrid grid(1.0, 2.0, 0.4);
    REQUIRE(grid.size() == 4);
    CHECK(grid[2] == doctest::Approx(1.8));
    CHECK(grid[3] == 2.0);
}

TEST_CASE("an empty span is a single point; bad grids are rejected") {
    const TimeGrid point(2.0, 2.0, 0.1);
    CHECK(point.size() == 1);
    CHECK(point[0] == 2.0);
    CHECK_THROWS_WITH_AS(TimeGrid(0.0, 1.0, 0.0), "time step must be positive, got 0",
                         std::invalid_argument);
    CHECK_THROWS_AS(TimeGrid(0.0, 1.0, -1e-9), std::invalid_argument);
    CHECK_THROWS_AS(TimeGrid(1.0, 0.0, 0.1), std::invalid_argument);
    CHECK_THROWS_AS(TimeGrid(0.0, INFINITY, 0.1), std::invalid_argument);
    CHECK_THROWS_AS(TimeGrid(0.0, 1e9, 1e-3), std::invalid_argument);
}

TEST_CASE("state names are the DOF names, rates primed") {
    ModelView view;
    view.nq = 2;
    view.dof_names = {"q", "psi"};
    CHECK(state_name(view, 0) == "q");
    CHECK(state_name(view, 1) == "psi");
    CHECK(state_name(view, 3) == "psi'");
}
