// The NREL 5-MW in wind under ROSCO with AeroDyn's blade elements, against OpenFAST +
// AeroDyn + ROSCO: every run `openfast_<case>.csv` in tests/data/reference/operating
// (the given 8 and 16 m/s; another run of the same deck is one more file there).
// Each run's deck is the folder's deck with the run's own start (ElastoDyn's initial
// state from its first row) and wind (steady at its first Wind1VelX, or the deck's
// uniform wind file `<case>.wnd`); `from-openfast` writes the model, which runs as its
// header says (ABM4 coupled loosely, DT 0.00625 s, as long as the run) under ROSCO.
#include "validation_support.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <regex>

// Built with ROSCO only (tests/CMakeLists.txt: gfortran builds it).
#ifdef YAMSC_ROSCO_DISCON

using namespace validation;
using yamsc::analysis::Table;
namespace fs = std::filesystem;

namespace {

/// The mean over the last `window` seconds of the run.
double tail_mean(const Table& t, const std::string& name, double window) {
    return mean_after(t, name, t.data.front().back() - window);
}

/// The deck of run `stem` in `folder`: ElastoDyn's initial state from the run's first
/// row, InflowWind's steady wind from it unless the deck has `<stem>.wnd`.
fs::path deck_of(const std::string& stem, const Table& run, const fs::path& folder) {
    const fs::path fst = deck_starting_as(run, folder);
    const fs::path inflow = folder / "NRELOffshrBsline5MW_InflowWind.dat";
    std::string text = read(inflow.string());
    if (fs::exists(folder / (stem + ".wnd"))) {
        set_entry(text, "WindType", "2");
        set_entry(text, "Filename_Uni", "\"" + stem + ".wnd\"");
    } else {
        set_entry(text, "HWindSpeed", format(column(run, "Wind1VelX_[m/s]").front()));
    }
    std::ofstream(inflow.string()) << text;
    return fst;
}

struct Tolerance {
    const char* channel;
    double relative, absolute; // either bound passes
};

/// The bounds on the means of the last 50 s.
const Tolerance tolerances[] = {{"RotSpeed_[rpm]", 0.005, 0}, {"GenPwr_[kW]", 0.01, 0},
                                {"BlPitch1_[deg]", 0, 0.3},   {"RotThrust_[kN]", 0.02, 0},
                                {"TTDspFA_[m]", 0.03, 0},     {"RootMyc1_[kN-m]", 0.03, 0}};

/// `yamsc trim` of the run's model at its mean rotor speed: the pitch that holds
/// it at the mean generator torque above rated, the torque at its pitch below,
/// against the run's own means (the blocks' discrete states settled).
void check_trim(const yamsc::driver::SimOptions& run, const Table& openfast) {
    const double rpm = tail_mean(openfast, "RotSpeed_[rpm]", 50);
    const double torque = 1000 * tail_mean(openfast, "GenTq_[kN-m]", 50);
    const double pitch = tail_mean(openfast, "BlPitch1_[deg]", 50);
    yamsc::driver::TrimOptions o;
    o.model = run.model;
    o.aero = run.aero;
    o.wind = run.wind;
    o.at = {{"psi", 1, rpm * M_PI / 30}};
    o.u = {{"pitch", 0, pitch * M_PI / 180}, {"gen_torque", 0, torque}};
    const bool above_rated = pitch > 1;
    o.adjust = {above_rated ? "pitch" : "gen_torque"};
    o.json = true;
    std::ostringstream out, err;
    REQUIRE_MESSAGE(yamsc::analysis::trim(o, out, err) == 0, err.str());
    const std::string json = out.str();
    CHECK(json.find("\"discrete_passes\":0") == std::string::npos);
    auto number = [&](const std::string& array, std::size_t index) {
        std::size_t at = json.find("\"" + array + "\":[") + array.size() + 4;
        for (std::size_t i = 0; i < index; ++i) at = json.find(',', at) + 1;
        return std::stod(json.substr(at));
    };
    // The input's index among "inputs":["V_wind","pitch",...].
    auto input = [&](const std::string& name) {
        const std::size_t from = json.find("\"inputs\":[");
        const std::size_t at = json.find("\"" + name + "\"", from);
        REQUIRE(at != std::string::npos);
        return static_cast<std::size_t>(std::count(json.begin() + static_cast<long>(from),
                                                   json.begin() + static_cast<long>(at), ','));
    };
    if (above_rated) {
        const double trimmed = number("u", input("pitch")) * 180 / M_PI;
        MESSAGE("trim: pitch " << trimmed << " deg (OpenFAST's mean " << pitch << " deg)");
        CHECK(std::fabs(trimmed - pitch) <= 0.05);
    } else {
        const double trimmed = number("u", input("gen_torque"));
        MESSAGE("trim: generator torque " << trimmed << " N m (OpenFAST's mean " << torque << ")");
        CHECK(std::fabs(trimmed / torque - 1) <= 0.005);
    }
}

void check_run(const fs::path& reference) {
    const std::string stem = reference.stem().string().substr(std::string("openfast_").size());
    CAPTURE(stem);
    const Table openfast = yamsc::analysis::read_table(reference.string());
    const fs::path folder = fs::path(work_dir) / ("operating_" + stem);
    const fs::path fst = deck_of(stem, openfast, folder);

    // The header's command: blade elements, ABM4 coupled loosely, the deck's TMax and DT.
    const std::string model = convert_in_wind(fst, folder);
    // The blades turn with the controller's pitch, as ElastoDyn's do.
    REQUIRE(model.find("rotate z -pitch }") != std::string::npos);

    const yamsc::driver::SimOptions o =
        header_run(folder, (folder / "turbine.mbd").string(), openfast, 0.025, YAMSC_ROSCO_DISCON);
    std::ostringstream out, err;
    REQUIRE_MESSAGE(yamsc::analysis::sim(o, out, err) == 0, err.str());
    const Table yamsc_run = yamsc::analysis::read_table(o.output);

    for (const Tolerance& t : tolerances) {
        const std::string channel = t.channel;
        CAPTURE(channel);
        const double got = tail_mean(yamsc_run, channel, 50);
        const double want = tail_mean(openfast, channel, 50);
        const std::string difference = t.absolute > 0
                                           ? std::to_string(got - want)
                                           : std::to_string(100 * (got / want - 1)) + " %";
        MESSAGE(stem << " " << channel << ": " << got << " (OpenFAST " << want << ", " << difference
                     << ")");
        if (t.absolute > 0)
            CHECK(std::fabs(got - want) <= t.absolute);
        else
            CHECK(std::fabs(got / want - 1) <= t.relative);
    }
    const std::vector<double>& wind = column(openfast, "Wind1VelX_[m/s]");
    if (*std::min_element(wind.begin(), wind.end()) == *std::max_element(wind.begin(), wind.end()))
        check_trim(o, openfast);
}

} // namespace

// Run by the `rosco_blade_elements` test (tests/CMakeLists.txt), which builds ROSCO.
TEST_CASE("blade elements under ROSCO: every operating run against OpenFAST + AeroDyn + ROSCO" *
          doctest::skip()) {
    std::vector<fs::path> runs;
    for (const auto& entry : fs::directory_iterator(operating)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind("openfast_", 0) == 0 && entry.path().extension() == ".csv")
            runs.push_back(entry.path());
    }
    std::sort(runs.begin(), runs.end());
    REQUIRE(runs.size() >= 2); // the given 8 and 16 m/s
    for (const fs::path& run : runs) check_run(run);
}

#endif
