// The NREL 5-MW in full-field turbulence under ROSCO with AeroDyn's blade elements,
// against OpenFAST + AeroDyn + ROSCO in the same TurbSim file: every run listed in
// tests/data/reference/turbulence/runs.txt (a held run is its CSV, its .bts and one
// line there). Each run's deck is the operating deck with the run's own start
// (ElastoDyn's initial state from its first row) and InflowWind's WindType 3 on the
// run's file; `from-openfast` writes the model, which runs as its header says (ABM4
// coupled loosely, DT 0.00625 s, as long as the run). After the first 60 s: means
// within 2 %, standard deviations within 10 %, and the damage-equivalent loads
// (Wöhler exponent 4 for the tower and shaft, 10 for the blade root; 1 Hz, ASTM
// counting, openfast_toolbox's 100 bins) within 10 %.
#include "validation_support.hpp"

#include "analysis/rainflow.hpp"

#include <cmath>
#include <filesystem>

// Built with ROSCO only (tests/CMakeLists.txt: gfortran builds it).
#ifdef YAMSC_ROSCO_DISCON

using namespace validation;
using yamsc::analysis::Table;
namespace fs = std::filesystem;

namespace {

const fs::path turbulence = fs::path(reference_dir) / "turbulence";
constexpr double transient = 60; // s

/// The values of a column from `transient` on.
std::vector<double> after_transient(const Table& t, const std::string& name) {
    const std::vector<double>& time = t.data.front();
    const std::vector<double>& v = column(t, name);
    std::vector<double> out;
    for (std::size_t i = 0; i < time.size(); ++i)
        if (time[i] >= transient) out.push_back(v[i]);
    REQUIRE(out.size() > 1);
    return out;
}

double mean(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return s / static_cast<double>(v.size());
}

double standard_deviation(const std::vector<double>& v) {
    const double m = mean(v);
    double s = 0;
    for (double x : v) s += (x - m) * (x - m);
    return std::sqrt(s / static_cast<double>(v.size()));
}

double equivalent_load(const Table& t, const std::string& name, double wohler) {
    const std::vector<double> v = after_transient(t, name);
    const double duration = t.data.front().back() - transient;
    return yamsc::analysis::equivalent_load(yamsc::analysis::rainflow(v), wohler, duration, {});
}

/// The channels the comparison holds to its bounds, with the DEL's Wöhler exponent
/// (0: none).
struct Channel {
    const char* name;
    double wohler;
};
const Channel channels[] = {{"RotSpeed_[rpm]", 0},   {"BlPitch1_[deg]", 0},
                            {"GenPwr_[kW]", 0},      {"RotThrust_[kN]", 0},
                            {"TwrBsMyt_[kN-m]", 4},  {"RootMyc1_[kN-m]", 10},
                            {"RootMxc1_[kN-m]", 10}, {"LSShftMxa_[kN-m]", 4}};

void check_run(const std::string& csv, const std::string& wind) {
    CAPTURE(csv);
    const Table openfast = yamsc::analysis::read_table((turbulence / csv).string());
    const std::string stem = fs::path(csv).stem().string();
    const fs::path folder = fs::path(work_dir) / ("turbulent_" + stem);
    const fs::path fst = deck_starting_as(openfast, folder);
    const fs::path inflow = folder / "NRELOffshrBsline5MW_InflowWind.dat";
    std::string text = read(inflow.string());
    set_entry(text, "WindType", "3");
    set_entry(text, "FileName_BTS", "\"" + (turbulence / wind).string() + "\"");
    std::ofstream(inflow.string()) << text;

    convert_in_wind(fst, folder);

    const yamsc::driver::SimOptions o =
        header_run(folder, (folder / "turbine.mbd").string(), openfast, 0.05, YAMSC_ROSCO_DISCON);
    std::ostringstream out, err;
    REQUIRE_MESSAGE(yamsc::analysis::sim(o, out, err) == 0, err.str());
    const Table yamsc_run = yamsc::analysis::read_table(o.output);

    for (const Channel& c : channels) {
        const std::string name = c.name;
        CAPTURE(name);
        const std::vector<double> got = after_transient(yamsc_run, name);
        const std::vector<double> want = after_transient(openfast, name);
        const double mean_error = mean(got) / mean(want) - 1;
        const double std_error = standard_deviation(got) / standard_deviation(want) - 1;
        MESSAGE(stem << " " << name << ": mean " << mean(got) << " (OpenFAST " << mean(want) << ", "
                     << 100 * mean_error << " %), std " << standard_deviation(got) << " ("
                     << standard_deviation(want) << ", " << 100 * std_error << " %)");
        CHECK(std::fabs(mean_error) <= 0.02);
        CHECK(std::fabs(std_error) <= 0.10);
        if (c.wohler > 0) {
            const double del = equivalent_load(yamsc_run, name, c.wohler);
            const double reference = equivalent_load(openfast, name, c.wohler);
            MESSAGE(stem << " " << name << ": DEL m=" << c.wohler << " " << del << " (OpenFAST "
                         << reference << ", " << 100 * (del / reference - 1) << " %)");
            CHECK(std::fabs(del / reference - 1) <= 0.10);
        }
    }
}

} // namespace

// Run by the `turbulent` test (tests/CMakeLists.txt), which builds ROSCO.
TEST_CASE("blade elements in turbulence: every run of runs.txt against OpenFAST + AeroDyn + "
          "ROSCO" *
          doctest::skip()) {
    std::ifstream manifest((turbulence / "runs.txt").string());
    REQUIRE(manifest.good());
    int runs = 0;
    for (std::string line; std::getline(manifest, line);) {
        std::istringstream fields(line);
        std::string csv, wind;
        if (!(fields >> csv) || csv[0] == '#') continue;
        REQUIRE_MESSAGE(static_cast<bool>(fields >> wind), "runs.txt: no wind file for " << csv);
        check_run(csv, wind);
        ++runs;
    }
    CHECK(runs >= 1);
}

#endif
