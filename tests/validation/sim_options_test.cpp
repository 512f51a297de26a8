// `yamsc sim`: the model's `initial` block and --ic, --linear, --channels openfast,
// --compare and --plot, end to end through the command line.
#include "driver/bindings.hpp"
#include "validation_support.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>

using namespace validation;
using yamsc::analysis::read_table;
using yamsc::analysis::Table;

namespace {

std::string write(const std::string& name, const std::string& text) {
    ::mkdir(work_dir.c_str(), 0755);
    const std::string path = work_dir + "/" + name;
    std::ofstream(path) << text;
    return path;
}

/// Runs the yamsc executable; its standard output.
std::string run_yamsc(const std::string& args, int expected_status = 0) {
    const std::string out = work_dir + "/cli_stdout.txt";
    const int raw =
        std::system((std::string(YAMSC_EXE) + " " + args + " > " + out + " 2>&1").c_str());
    CHECK(WEXITSTATUS(raw) == expected_status);
    return read(out);
}

// A pendulum (length 1, g = 9.81) with a default initial state that uses a parameter.
const std::string pendulum = R"(model swing "pendulum with an initial state"
param g = 9.81
param theta0 = 0.5       # initial angle [rad]
dof theta
gravity (0, 0, -g)
rigid bob { mass = 1; com = (0, 0, -1) }
joint ground -> bob { rotate y theta }
initial { theta = theta0; theta' = 0.25 }
output PtfmPitch = theta * 180 / pi   # an OpenFAST channel, for the test
)";

} // namespace

TEST_CASE("sim starts from the initial block; --ic overrides single values, --set moves it") {
    const std::string model = write("swing.mbd", pendulum);
    const std::string csv = work_dir + "/swing.csv";
    run_yamsc("sim " + model + " --tmax 0.02 --dt 0.01 -o " + csv);
    Table t = read_table(csv);
    CHECK(t.columns == std::vector<std::string>{"time", "theta", "theta'", "PtfmPitch"});
    CHECK(t.data[1][0] == 0.5);
    CHECK(t.data[2][0] == 0.25);
    run_yamsc("sim " + model + " --tmax 0.02 --dt 0.01 --ic theta=0.1 -o " + csv);
    t = read_table(csv);
    CHECK(t.data[1][0] == 0.1);
    CHECK(t.data[2][0] == 0.25); // the rate still from the block
    run_yamsc("sim " + model + " --tmax 0.02 --dt 0.01 --set theta0=0.3 -o " + csv);
    CHECK(read_table(csv).data[1][0] == doctest::Approx(0.3).epsilon(1e-12));
    CHECK(run_yamsc("sim " + model + " --tmax 0.02 --dt 0.01 --ic phi=1", 1)
              .find("--ic: unknown DOF 'phi'") != std::string::npos);
}

TEST_CASE("--linear integrates the linear model: a harmonic oscillator at sqrt(g/L)") {
    const std::string model = write("swing.mbd", pendulum);
    const std::string csv = work_dir + "/swing_linear.csv";
    const std::string log =
        run_yamsc("sim " + model + " --tmax 2 --dt 0.001 --linear -v -o " + csv);
    CHECK(log.find("modes [Hz]: 0.4984") != std::string::npos); // sqrt(9.81)/2pi
    const Table lin = read_table(csv);
    const double w = std::sqrt(9.81);
    double worst = 0;
    for (std::size_t i = 0; i < lin.rows(); ++i) {
        const double t = lin.data[0][i];
        worst = std::max(
            worst, std::abs(lin.data[1][i] - (0.5 * std::cos(w * t) + 0.25 / w * std::sin(w * t))));
    }
    CHECK(worst < 1e-8);
    // The nonlinear pendulum at 0.5 rad is slower: clearly not the same.
    run_yamsc("sim " + model + " --tmax 2 --dt 0.001 -o " + csv);
    const Table nonlinear = read_table(csv);
    CHECK(std::abs(nonlinear.data[1].back() - lin.data[1].back()) > 1e-2);
    // --at moves the operating point: about theta = 0.5 the linear model is exact at t = 0.
    run_yamsc("sim " + model +
              " --tmax 0.01 --dt 0.01 --linear --at \"theta=0.5,theta'=0.25\" -o " + csv);
    CHECK(read_table(csv).data[1][1] == doctest::Approx(nonlinear.data[1][10]).epsilon(1e-6));
    run_yamsc("sim " + model + " --tmax 1 --dt 0.01 --at theta=0.5", 2);
}

TEST_CASE("--channels openfast, --compare and --plot") {
    const std::string model = write("swing.mbd", pendulum);
    const std::string csv = work_dir + "/swing_of.csv", svg = work_dir + "/swing.svg";
    const std::string reference = work_dir + "/swing_ref.csv";
    for (const std::string& f : {svg, csv, reference}) std::remove(f.c_str());
    // The reference is read first: a missing one fails before anything is written.
    CHECK(run_yamsc("sim " + model + " --tmax 1 --dt 0.01 -o " + csv + " --compare " + reference, 1)
              .find("cannot read") != std::string::npos);
    CHECK(!std::ifstream(csv).good());
    // The output may not replace the table it is compared with.
    run_yamsc("sim " + model + " --tmax 1 --dt 0.01 --channels openfast -o " + reference);
    CHECK(run_yamsc(
              "sim " + model + " --tmax 1 --dt 0.01 -o " + reference + " --compare " + reference, 2)
              .find("must not replace an input") != std::string::npos);
    const std::string log =
        run_yamsc("sim " + model + " --tmax 1 --dt 0.01 --channels openfast -o " + csv +
                  " --compare " + reference + " --plot " + svg);
    const Table t = read_table(csv);
    CHECK(t.columns == std::vector<std::string>{"Time_[s]", "PtfmPitch_[deg]"});
    CHECK(t.data[1][0] == doctest::Approx(0.5 * 180 / M_PI).epsilon(1e-9));
    // Compared with itself: no error.
    CHECK(log.find("PtfmPitch_[deg]") != std::string::npos);
    CHECK(log.find("0.000 %") != std::string::npos);
    CHECK(log.find("1.000000") != std::string::npos);
    const std::string plot = read(svg);
    CHECK(plot.find("<polyline") != std::string::npos);
    CHECK(plot.find("reference (swing_ref.csv)") != std::string::npos);
    // A model without OpenFAST outputs has no OpenFAST channels.
    CHECK(run_yamsc("sim " + std::string(YAMSC_SOURCE_DIR) +
                        "/models/pendulum.mbd --tmax 0.1 --dt 0.01 --channels openfast",
                    1)
              .find("no output named as an OpenFAST channel") != std::string::npos);
    run_yamsc("sim " + model + " --tmax 1 --dt 0.01 --channels fast", 2);
    CHECK(run_yamsc("sim " + model + " --tmax 1 --dt 0.01 --plot " + svg +
                        " --plot-channels theta,nope",
                    1)
              .find("unknown channel 'nope'") != std::string::npos);
}

TEST_CASE("from-openfast on the command line writes a model that simulates") {
    const std::string out = work_dir + "/cli_land.mbd";
    const std::string log = run_yamsc("from-openfast " + reference_dir + "/" + land_case.folder +
                                      "/Main_Spar_ED.fst --dofs TwSSDOF1=off -o " + out);
    CHECK(log.find("2 DOFs (q_fa1, psi)") != std::string::npos);
    CHECK(run_yamsc("from-openfast " + out + " -o x.mbd --dofs TwSSDOF1", 2).find("NAME=on|off") !=
          std::string::npos);
    CHECK(run_yamsc("from-openfast /nonexistent.fst -o x.mbd", 1).find("cannot read") !=
          std::string::npos);
}
