#pragma once
// The operating deck with every ElastoDyn DOF off, as OpenFAST's rigid-rotor
// reference runs make it (data/reference/aero/README.md: 8.9886 rpm, pitch 0,
// quasi-steady BEM, output nodes 3, 5, ..., 17, 18), converted by from-openfast,
// and the rows of a run matched with a reference's.
#include "analysis/compare.hpp"
#include "openfast/from_openfast.hpp"
#include "test_files.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace aero_test {

/// `text` (an OpenFAST input file) with the value of `key` replaced.
inline std::string set_entry(std::string text, const std::string& key, const std::string& value) {
    return std::regex_replace(text, std::regex("\n\\s*\\S+(\\s+)" + key + "\\b"),
                              "\n  " + value + "$1" + key);
}

struct RigidDeck {
    std::string model;      // the converted model
    std::string aerodyn;    // the deck's AeroDyn file, quasi-steady
    std::string inflowwind; // the deck's InflowWind file (steady 8 m/s)
};

/// The deck copied into `dir`/deck, every DOF off, converted into `dir`/rigid.mbd.
inline RigidDeck rigid_deck(const std::string& dir) {
    namespace fs = std::filesystem;
    fs::copy(std::string(YAMSC_TEST_DATA_DIR) + "/reference/operating/deck", dir + "/deck",
             fs::copy_options::recursive | fs::copy_options::overwrite_existing);
    const std::string ed = dir + "/deck/NRELOffshrBsline5MW_Onshore_ElastoDyn.dat";
    std::string text = test_support::read_file(ed);
    for (const char* dof : {"FlapDOF1", "FlapDOF2", "EdgeDOF", "TeetDOF", "DrTrDOF", "GenDOF",
                            "YawDOF", "TwFADOF1", "TwFADOF2", "TwSSDOF1", "TwSSDOF2"})
        text = set_entry(text, dof, "False");
    text = set_entry(text, "RotSpeed", "8.9885664");
    test_support::write_file(ed, text);
    RigidDeck d;
    d.aerodyn = dir + "/deck/NRELOffshrBsline5MW_Onshore_AeroDyn15.dat";
    // The reference's quasi-steady BEM: no dynamic inflow, no unsteady airfoils.
    std::string aero = set_entry(test_support::read_file(d.aerodyn), "NBlOuts", "9");
    aero = set_entry(aero, "DBEMT_Mod", "0");
    aero = set_entry(aero, "UA_Mod", "0");
    aero = std::regex_replace(aero, std::regex("\n[^\n]*BlOutNd"),
                              "\n3, 5, 7, 9, 11, 13, 15, 17, 18    BlOutNd");
    test_support::write_file(d.aerodyn, aero);
    d.inflowwind = dir + "/deck/NRELOffshrBsline5MW_InflowWind.dat";
    yamsc::driver::FromOpenFastOptions o;
    o.deck = dir + "/deck/NREL-5MW.fst";
    o.output = dir + "/rigid.mbd";
    std::ostringstream out, err;
    REQUIRE_MESSAGE(yamsc::openfast::from_openfast(o, out, err) == 0, err.str());
    d.model = o.output;
    return d;
}

/// The column `name` of `t` (a test failure without it).
inline std::vector<double> column(const yamsc::analysis::Table& t, const std::string& name) {
    const int c = t.find(name);
    REQUIRE_MESSAGE(c >= 0, name);
    return t.data[static_cast<std::size_t>(c)];
}

/// For every 8th row r of `ref` and the row i of `y` at the same instant (both
/// every 0.025 s from 0): the azimuth to 1e-6, RtFldCp and RtFldCt within 0.5 %,
/// the nine output nodes' angles of attack within 0.1 deg (the rigid-rotor
/// tolerances), then more(i, r); the number of rows compared.
template <class More>
int compare_rotor_rows(const yamsc::analysis::Table& y, const yamsc::analysis::Table& ref,
                       More&& more) {
    const auto t_ref = column(ref, "Time_[s]"), t_y = column(y, "Time_[s]");
    int compared = 0;
    for (std::size_t r = 0; r < t_ref.size(); r += 8) {
        const auto i = static_cast<std::size_t>(std::lround(t_ref[r] / 0.025));
        REQUIRE(i < t_y.size());
        CHECK(t_y[i] == doctest::Approx(t_ref[r]));
        CAPTURE(t_ref[r]);
        for (const auto& [name, rel] : {std::pair<std::string, double>{"Azimuth_[deg]", 1e-6},
                                        {"RtFldCp_[-]", 0.005},
                                        {"RtFldCt_[-]", 0.005}}) {
            CAPTURE(name);
            CHECK(column(y, name)[i] == doctest::Approx(column(ref, name)[r]).epsilon(rel));
        }
        for (int j = 1; j <= 9; ++j) {
            const std::string alpha = "B1N" + std::to_string(j) + "Alpha_[deg]";
            CHECK(std::abs(column(y, alpha)[i] - column(ref, alpha)[r]) < 0.1);
        }
        more(i, r);
        ++compared;
    }
    return compared;
}

} // namespace aero_test
