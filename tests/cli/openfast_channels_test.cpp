// `--channels openfast`: the CSV written straight from a simulation's stored rows
// is the table of OpenFAST's channels, byte for byte, angles wrapped to [0, 360).
#include "test_files.hpp"

#include "analysis/channels.hpp"
#include "diag/errors.hpp"

#include <doctest/doctest.h>

using namespace yamsc::analysis;

namespace {

/// Two states, three outputs (two of them OpenFAST channels), three rows.
yamsc::runtime::SimulationResult result_of_three_rows() {
    yamsc::runtime::SimulationResult r;
    r.columns = {"time", "theta", "theta'", "Azimuth", "swing", "Q_TFA1"};
    r.nx = 2;
    r.ny = 3;
    r.time = {0.0, 0.5, 1.0};
    r.states = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6};
    r.outputs = {370.0, 1.0, 0.25, -10.0, 2.0, -0.125, 719.5, 3.0, 1e-12};
    return r;
}

} // namespace

TEST_CASE("--channels openfast: the streamed CSV equals the table's, angles wrapped") {
    const auto r = result_of_three_rows();
    const auto columns = openfast_columns(r, 3);
    REQUIRE(columns.size() == 2);
    CHECK(columns[0].name == "Azimuth_[deg]");
    CHECK(columns[0].output == 0);
    CHECK(columns[0].wrap_360);
    CHECK(columns[1].name == "Q_TFA1_[m]");
    CHECK(columns[1].output == 2);

    const Table t = openfast_table(r, 3);
    CHECK(t.columns == std::vector<std::string>{"Time_[s]", "Azimuth_[deg]", "Q_TFA1_[m]"});
    CHECK(t.data[1] == std::vector<double>{10.0, 350.0, 359.5});
    CHECK(t.data[2] == std::vector<double>{0.25, -0.125, 1e-12});

    const std::string dir = test_support::scratch_dir("cli", "openfast_channels");
    write_openfast_csv(r, 3, dir + "/streamed.csv");
    write_table_csv(t, dir + "/table.csv");
    const std::string streamed = test_support::read_file(dir + "/streamed.csv");
    CHECK(streamed == test_support::read_file(dir + "/table.csv"));
    CHECK(streamed == "Time_[s],Azimuth_[deg],Q_TFA1_[m]\n"
                      "0,10,0.25\n0.5,350,-0.125\n1,359.5,1e-12\n");
}

TEST_CASE("--channels openfast: a model without OpenFAST's channels is refused") {
    auto r = result_of_three_rows();
    r.columns = {"time", "theta", "theta'", "a", "b", "c"};
    CHECK_THROWS_AS(openfast_columns(r, 3), yamsc::diag::UserError);
}
