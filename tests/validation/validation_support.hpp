#pragma once
// Shared by the validation tests: the reference decks, running yamsc's commands in
// process, and reading numbers out of their text.
#include "analysis/channels.hpp"
#include "analysis/commands.hpp"
#include "analysis/compare.hpp"
#include "openfast/from_openfast.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>
#include <string>
#include <sys/stat.h>

namespace validation {

inline const std::string reference_dir = std::string(YAMSC_TEST_DATA_DIR) + "/reference";
inline const std::string work_dir = std::string(YAMSC_TEST_BINARY_DIR) + "/validation";

/// One of the paper's free-decay cases with its OpenFAST reference.
struct Case {
    std::string folder; // under tests/data/reference
    std::string model;  // the model's name (file work_dir/<model>.mbd)
    double tmax;
    std::vector<std::string> channels;     // DOF channels that must agree
    std::string deck = "Main_Spar_ED.fst"; // in the folder
};

inline const Case land_case{
    "land_3dof_F0T2N0S1", "land_3dof", 4.0, {"Q_TFA1_[m]", "Q_TSS1_[m]", "Azimuth_[deg]"}};
inline const Case floating_case{"floating_3dof_F2T1RNA",
                                "floating_3dof",
                                7.0,
                                {"PtfmSurge_[m]", "PtfmPitch_[deg]", "Q_TFA1_[m]"}};

/// Every ElastoDyn DOF of the onshore NREL 5-MW, 30 s (issue 13).
inline const Case land_16dof_case{"land_16dof_free_decay",
                                  "land_16dof",
                                  30.0,
                                  {"Q_TFA1_[m]", "Q_TSS1_[m]", "Q_TFA2_[m]", "Q_TSS2_[m]",
                                   "NacYaw_[deg]", "RotSpeed_[rpm]", "Q_DrTr_[rad]", "Q_B1F1_[m]",
                                   "Q_B1E1_[m]", "Q_B1F2_[m]", "Q_B2F1_[m]", "Q_B2E1_[m]",
                                   "Q_B2F2_[m]", "Q_B3F1_[m]", "Q_B3E1_[m]", "Q_B3F2_[m]"},
                                  "NREL5MW_Onshore_FreeDecay.fst"};

/// A whole file; one that cannot be opened fails the test (a missing deck is not an empty one).
inline std::string read(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    REQUIRE_MESSAGE(in.good(), "cannot read " << path);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

/// The column `name` of a table (the test fails without it).
inline const std::vector<double>& column(const yamsc::analysis::Table& t, const std::string& name) {
    const int j = t.find(name);
    REQUIRE_MESSAGE(j >= 0, "no column " << name);
    return t.data[static_cast<std::size_t>(j)];
}

/// The mean of a column over the rows with time at least `from`.
inline double mean_after(const yamsc::analysis::Table& t, const std::string& name, double from) {
    const std::vector<double>& time = t.data.front();
    const std::vector<double>& v = column(t, name);
    double sum = 0;
    int n = 0;
    for (std::size_t i = 0; i < time.size(); ++i)
        if (time[i] >= from) {
            sum += v[i];
            ++n;
        }
    REQUIRE(n > 0);
    return sum / n;
}

inline std::string model_path(const Case& c) {
    return work_dir + "/" + c.model + ".mbd";
}
inline std::string reference_csv(const Case& c) {
    return reference_dir + "/" + c.folder + "/openfast_reference.csv";
}

/// `yamsc from-openfast <case>/Main_Spar_ED.fst -o <work>/<model>.mbd`, in process.
inline std::string convert(const Case& c, std::vector<std::pair<std::string, bool>> dofs = {}) {
    ::mkdir(work_dir.c_str(), 0755);
    yamsc::driver::FromOpenFastOptions o;
    o.deck = reference_dir + "/" + c.folder + "/" + c.deck;
    o.output = model_path(c);
    o.dofs = std::move(dofs);
    std::ostringstream out, err;
    REQUIRE_MESSAGE(yamsc::openfast::from_openfast(o, out, err) == 0, err.str());
    return out.str() + err.str();
}

/// `yamsc sim <model> --channels openfast [--linear] -o csv` (RK4, dt 0.01, or
/// the method and steps given): the table written.
inline yamsc::analysis::Table
simulate(const Case& c, bool linear, std::string* log = nullptr,
         yamsc::driver::SimMethod method = yamsc::driver::SimMethod::rk4, double dt = 0.01,
         double dt_out = 0.0) {
    yamsc::driver::SimOptions o;
    o.model = model_path(c);
    o.tmax = c.tmax;
    o.dt = dt;
    o.dt_out = dt_out;
    o.method = method;
    o.channels = yamsc::driver::Channels::openfast;
    o.linear = linear;
    o.verbose = linear; // prints the linear model's frequencies
    o.output = work_dir + "/" + c.model + (linear ? "_linear" : "") + ".csv";
    std::ostringstream out, err;
    REQUIRE_MESSAGE(yamsc::analysis::sim(o, out, err) == 0, err.str());
    if (log) *log = out.str();
    return yamsc::analysis::read_table(o.output);
}

/// Sets ElastoDyn/InflowWind entry `key` of `text` (value first, then the key) to `value`.
inline void set_entry(std::string& text, const std::string& key, const std::string& value) {
    const std::regex line("(^|\n)[ \t]*[^ \t\n]+([ \t]+" +
                          std::regex_replace(key, std::regex(R"([()])"), R"(\$&)") + "[ \t])");
    std::smatch m;
    REQUIRE_MESSAGE(std::regex_search(text, m, line), "no entry " << key);
    text.replace(static_cast<std::size_t>(m.position(0)), static_cast<std::size_t>(m.length(0)),
                 m[1].str() + "   " + value + m[2].str());
}

inline std::string format(double v) {
    std::ostringstream s;
    s.precision(10);
    s << v;
    return s.str();
}

/// The ROSCO NREL 5-MW deck the operating, turbulent and aero runs were made from.
inline const std::filesystem::path operating = std::filesystem::path(reference_dir) / "operating";

/// A copy of that deck in `folder` (replaced) whose ElastoDyn initial state is the
/// first row of OpenFAST's `run` (deflections, pitch, azimuth, rotor speed): its
/// `.fst`.
inline std::filesystem::path deck_starting_as(const yamsc::analysis::Table& run,
                                              const std::filesystem::path& folder) {
    namespace fs = std::filesystem;
    fs::remove_all(folder);
    fs::create_directories(folder.parent_path());
    fs::copy(operating / "deck", folder, fs::copy_options::recursive);
    const fs::path ed = folder / "NRELOffshrBsline5MW_Onshore_ElastoDyn.dat";
    std::string text = read(ed.string());
    const std::vector<std::pair<const char*, std::vector<const char*>>> start{
        {"OoPDefl1_[m]", {"OoPDefl"}},
        {"IPDefl1_[m]", {"IPDefl"}},
        {"BlPitch1_[deg]", {"BlPitch(1)", "BlPitch(2)", "BlPitch(3)"}},
        {"Azimuth_[deg]", {"Azimuth"}},
        {"RotSpeed_[rpm]", {"RotSpeed"}},
        {"TTDspFA_[m]", {"TTDspFA"}},
        {"TTDspSS_[m]", {"TTDspSS"}}};
    for (const auto& [channel, keys] : start)
        if (run.find(channel) >= 0)
            for (const char* key : keys) set_entry(text, key, format(column(run, channel).front()));
    std::ofstream(ed.string()) << text;
    return folder / "NREL-5MW.fst";
}

/// `yamsc from-openfast` of the deck `fst` in `folder` (to `folder/turbine.mbd`):
/// the model's text, whose header's command must be the deck's in wind (the
/// deck's AeroDyn and InflowWind files, DT, ABM4 coupled loosely).
inline std::string convert_in_wind(const std::filesystem::path& fst,
                                   const std::filesystem::path& folder) {
    yamsc::driver::FromOpenFastOptions f;
    f.deck = fst.string();
    f.output = (folder / "turbine.mbd").string();
    std::ostringstream out, err;
    REQUIRE_MESSAGE(yamsc::openfast::from_openfast(f, out, err) == 0, err.str());
    const std::string model = read(f.output);
    REQUIRE(model.find("#     --aero NRELOffshrBsline5MW_Onshore_AeroDyn15.dat \\\n") !=
            std::string::npos);
    REQUIRE(model.find(" --dt 0.00625 ") != std::string::npos);
    REQUIRE(model.find("#     --wind NRELOffshrBsline5MW_InflowWind.dat \\\n") !=
            std::string::npos);
    REQUIRE(model.find("#     --method abm4") != std::string::npos);
    REQUIRE(model.find("#     --coupling loose --interp-order 2") != std::string::npos);
    return model;
}

/// `yamsc sim` of a model `from-openfast` wrote from a deck in `folder` (the deck
/// started as OpenFAST's `run`), as the model's header says in wind: the
/// deck's AeroDyn and InflowWind files, ROSCO with its DISCON.IN, ABM4 at DT
/// 0.00625 s, the deck's loose coupling, as long as the run, the controller's
/// pitch starting at the run's; OpenFAST's channels, rows every dt_out, to
/// `folder/run.csv`.
inline yamsc::driver::SimOptions header_run(const std::filesystem::path& folder,
                                            const std::string& model,
                                            const yamsc::analysis::Table& run, double dt_out,
                                            const std::string& controller) {
    yamsc::driver::SimOptions o;
    o.model = model;
    o.aero = (folder / "NRELOffshrBsline5MW_Onshore_AeroDyn15.dat").string();
    o.wind = (folder / "NRELOffshrBsline5MW_InflowWind.dat").string();
    o.controller = controller;
    o.controller_input = (folder / "DISCON.IN").string();
    o.tmax = run.data.front().back();
    o.dt = 0.00625;
    o.dt_out = dt_out;
    o.method = yamsc::driver::SimMethod::abm4;
    o.coupling = yamsc::driver::SimCoupling::loose;
    o.interp_order = 2;
    const double pitch0 = column(run, "BlPitch1_[deg]").front();
    if (pitch0 != 0) o.u = {{"pitch", 0, pitch0 * M_PI / 180}};
    o.channels = yamsc::driver::Channels::openfast;
    o.output = (folder / "run.csv").string();
    return o;
}

} // namespace validation
