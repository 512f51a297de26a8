// `lin --sweep NAME=.. --schedule FILE`: the schedule's columns interpolated
// linearly at the swept value as --at assignments (DOFs, rates with their
// primes, inputs); located errors for a schedule that does not fit the sweep.
#include "analysis/sweep_schedule.hpp"
#include "diag/errors.hpp"
#include "generated_model.hpp"

#include <doctest/doctest.h>

#include <fstream>

using namespace linear_test;
using yamsc::analysis::read_sweep_schedule;
using yamsc::analysis::schedule_at;

namespace {

std::string schedule_file(const std::string& name, const std::string& text) {
    const std::string path = scratch_dir("sweep_schedule") + "/" + name;
    std::ofstream(path) << text;
    return path;
}

} // namespace

TEST_CASE("schedule: columns interpolated at the swept value, rates by their primes") {
    const std::string path = schedule_file("ok.csv", "# steady states\n"
                                                     "V_wind,psi',gen_torque,pitch\n"
                                                     "4,0.75,2500,0\n"
                                                     "12,1.25,43000,0.06\n"
                                                     "16,1.25,43000,0.2\n");
    const auto s = read_sweep_schedule(path, "V_wind");
    auto at = schedule_at(s, 8);
    REQUIRE(at.size() == 3);
    CHECK(at[0].name == "psi");
    CHECK(at[0].primes == 1);
    CHECK(at[0].value == doctest::Approx(1.0).epsilon(1e-15));
    CHECK(at[1].name == "gen_torque");
    CHECK(at[1].primes == 0);
    CHECK(at[1].value == doctest::Approx(22750).epsilon(1e-15));
    at = schedule_at(s, 16); // the last row itself
    CHECK(at[2].value == 0.2);
    at = schedule_at(s, 4);
    CHECK(at[1].value == 2500);
}

TEST_CASE("schedule: errors name the file and what does not fit") {
    const std::string path = schedule_file("bad.csv", "V_wind,pitch\n4,0\n8,0.1\n");
    CHECK_THROWS_WITH_AS(read_sweep_schedule(path, "psi'"),
                         doctest::Contains("bad.csv:1: the schedule's first column is 'V_wind'"),
                         yamsc::diag::UserError);
    const auto s = read_sweep_schedule(path, "V_wind");
    CHECK_THROWS_WITH_AS(schedule_at(s, 9), doctest::Contains("V_wind = 9 lies outside"),
                         yamsc::diag::UserError);
    const std::string one = schedule_file("one.csv", "V_wind,pitch\n4,0\n");
    CHECK_THROWS_WITH_AS(read_sweep_schedule(one, "V_wind"), doctest::Contains("two rows"),
                         yamsc::diag::UserError);
    const std::string falling = schedule_file("falling.csv", "V_wind,pitch\n8,0\n4,0\n");
    CHECK_THROWS_WITH_AS(read_sweep_schedule(falling, "V_wind"), doctest::Contains("falling.csv:3"),
                         yamsc::diag::UserError);
}
