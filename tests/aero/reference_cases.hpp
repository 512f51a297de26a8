#pragma once
// OpenFAST's reference runs of data/reference/aero by kind, as its manifest
// cases.txt lists them (one line per run: file, kind, the deck entries
// make_cases.py changed as `key=value`), and the operating deck with a run's
// entries set, as make_cases.py's setkey sets them. A run of a kind held
// elsewhere is its CSV (a UA driver run: and its .dvr) plus one line.
#include "test_files.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace reference_cases {

inline const std::string aero_dir = std::string(YAMSC_TEST_DATA_DIR) + "/reference/aero/";
inline const std::string deck_dir = std::string(YAMSC_TEST_DATA_DIR) + "/reference/operating/deck";

enum class Kind {
    rigid,      // every ElastoDyn DOF off, fixed speed and pitch, 9 output nodes
    flexible,   // blades and tower flexible, fixed speed and pitch
    dbemt_step, // rigid rotor, a uniform wind step, dynamic inflow
    tower,      // a flexible run with tower influence or drag
    ua_driver,  // OpenFAST's unsteady-aerodynamics driver (with its .dvr)
};

using Settings = std::vector<std::pair<std::string, std::string>>;

struct Case {
    std::string file; // in data/reference/aero
    Kind kind = Kind::rigid;
    Settings settings; // the deck's entries as make_cases.py set them
    // From the run's first row (not for the UA driver): the hub-height wind's
    // speed, the rotor speed and blade 1's pitch.
    double wind = 0, rpm = 0, pitch_deg = 0;

    std::string name() const { return file.substr(0, file.rfind('.')); }
    std::string path() const { return aero_dir + file; }
    std::optional<std::string> setting(const std::string& key) const {
        for (const auto& [k, v] : settings)
            if (k == key) return v;
        return std::nullopt;
    }
    double number(const std::string& key, double otherwise) const {
        const auto v = setting(key);
        return v ? std::stod(*v) : otherwise;
    }
};

inline Kind kind_of(const std::string& word) {
    static const std::map<std::string, Kind> kinds = {{"rigid", Kind::rigid},
                                                      {"flexible", Kind::flexible},
                                                      {"dbemt_step", Kind::dbemt_step},
                                                      {"tower", Kind::tower},
                                                      {"ua_driver", Kind::ua_driver}};
    const auto it = kinds.find(word);
    REQUIRE_MESSAGE(it != kinds.end(), "cases.txt: unknown kind " << word);
    return it->second;
}

/// The first data row of a reference CSV by column name (without the unit).
inline std::map<std::string, double> first_row(const std::string& path) {
    std::ifstream in(path);
    REQUIRE_MESSAGE(in.good(), "cannot open " << path);
    std::string header, row, name, value;
    std::getline(in, header);
    std::getline(in, row);
    std::istringstream h(header), r(row);
    std::map<std::string, double> columns;
    while (std::getline(h, name, ',') && std::getline(r, value, ','))
        columns[name.substr(0, name.find("_["))] = std::stod(value);
    return columns;
}

/// A column of a reference CSV by name (without the unit).
inline std::vector<double> column(const std::string& path, const std::string& name) {
    std::ifstream in(path);
    REQUIRE_MESSAGE(in.good(), "cannot open " << path);
    std::string line, cell;
    std::getline(in, line);
    std::istringstream h(line);
    std::size_t at = 0;
    while (std::getline(h, cell, ',') && cell.substr(0, cell.find("_[")) != name) ++at;
    std::vector<double> values;
    while (std::getline(in, line)) {
        std::istringstream r(line);
        for (std::size_t i = 0; std::getline(r, cell, ','); ++i)
            if (i == at) values.push_back(std::stod(cell));
    }
    REQUIRE_MESSAGE(!values.empty(), path << ": no column " << name);
    return values;
}

/// A uniform wind step as make_cases.py writes it (its step.wnd): `before`
/// up to `time`, `after` from one time step later; read off the run's rows
/// (Wind1VelX: the last row at the first speed is the step's time).
struct WindStep {
    double time = 0, before = 0, after = 0;
    double at(double t) const { return t < time + 1e-9 ? before : after; }
};
inline WindStep wind_step(const Case& c) {
    const std::vector<double> t = column(c.path(), "Time"), u = column(c.path(), "Wind1VelX");
    WindStep s{t.front(), u.front(), u.back()};
    std::size_t i = 0;
    while (i + 1 < u.size() && u[i + 1] == s.before) ++i;
    s.time = t[i];
    for (std::size_t j = i + 1; j < u.size(); ++j)
        REQUIRE_MESSAGE(u[j] == s.after, c.file << ": the wind is not one step");
    return s;
}

/// Every run of `kind` in the manifest, in its order.
inline std::vector<Case> cases(Kind kind) {
    std::ifstream in(aero_dir + "cases.txt");
    REQUIRE_MESSAGE(in.good(), "no " << aero_dir << "cases.txt");
    std::vector<Case> found;
    for (std::string line; std::getline(in, line);) {
        line = line.substr(0, line.find('#'));
        std::istringstream words(line);
        Case c;
        std::string kind_word, setting;
        if (!(words >> c.file)) continue;
        const bool has_kind = static_cast<bool>(words >> kind_word);
        REQUIRE_MESSAGE(has_kind, "cases.txt: no kind for " << c.file);
        c.kind = kind_of(kind_word);
        while (words >> setting) {
            const auto eq = setting.find('=');
            const bool key_value = eq != std::string::npos && eq > 0;
            REQUIRE_MESSAGE(key_value, "cases.txt: " << c.file << ": not key=value: " << setting);
            c.settings.emplace_back(setting.substr(0, eq), setting.substr(eq + 1));
        }
        if (c.kind != kind) continue;
        if (kind != Kind::ua_driver) {
            const auto row = first_row(c.path());
            c.wind = std::hypot(row.at("Wind1VelX"), row.at("Wind1VelY"));
            c.rpm = row.at("RotSpeed");
            c.pitch_deg = row.at("BlPitch1");
        }
        found.push_back(std::move(c));
    }
    REQUIRE_MESSAGE(!found.empty(), "cases.txt lists no run of this kind");
    return found;
}

/// The flexible run a tower run adds its tower to: the same wind, rotor speed
/// and pitch.
inline Case base_run(const Case& tower) {
    for (const Case& c : cases(Kind::flexible))
        if (c.wind == tower.wind && c.rpm == tower.rpm && c.pitch_deg == tower.pitch_deg) return c;
    FAIL(tower.file << ": cases.txt has no flexible run at its wind, rotor speed and pitch");
    return tower;
}

/// The start of a run's last 20 s (the flexible runs' window).
inline double last_20_s(const Case& c) {
    return column(c.path(), "Time").back() - 20;
}

/// The deck's files whose entries a setting may name (make_cases.py's).
inline const std::vector<std::string>& deck_files() {
    static const std::vector<std::string> files = {
        "NRELOffshrBsline5MW_Onshore_ElastoDyn.dat", "NRELOffshrBsline5MW_Onshore_AeroDyn15.dat",
        "NRELOffshrBsline5MW_InflowWind.dat", "NRELOffshrBsline5MW_Onshore_ServoDyn.dat",
        "NREL-5MW.fst"};
    return files;
}
inline const std::string aerodyn_file = "/NRELOffshrBsline5MW_Onshore_AeroDyn15.dat";
inline const std::string elastodyn_file = "/NRELOffshrBsline5MW_Onshore_ElastoDyn.dat";

/// make_cases.py's setkey over the deck in `dir`: the line whose second word is
/// `key`, in whichever of the deck's files holds it (exactly one line), gets
/// `value` as its first word.
inline void set_entry(const std::string& dir, const std::string& key, const std::string& value) {
    int found = 0;
    for (const std::string& file : deck_files()) {
        const std::string path = dir + "/" + file;
        std::istringstream in(test_support::read_file(path));
        std::string text, line;
        bool changed = false;
        while (std::getline(in, line)) {
            std::istringstream words(line);
            std::string first, second;
            if (words >> first >> second && second == key) {
                line = value + "   " + key + line.substr(line.find(key) + key.size());
                changed = true;
                ++found;
            }
            text += line + "\n";
        }
        if (changed) test_support::write_file(path, text);
    }
    REQUIRE_MESSAGE(found == 1, "the deck has " << found << " entries " << key);
}

/// The operating deck copied to scratch directory `name` with `settings` set,
/// and AeroDyn's node outputs at the references' nodes (BlOutNd).
inline std::string deck(const std::string& name, const Settings& settings) {
    namespace fs = std::filesystem;
    const std::string d = test_support::scratch_dir("aero", name);
    fs::remove_all(d);
    fs::copy(deck_dir, d, fs::copy_options::recursive);
    set_entry(d, "NBlOuts", "9");
    const std::string ad = d + aerodyn_file;
    std::istringstream in(test_support::read_file(ad));
    std::string text, line;
    while (std::getline(in, line)) {
        if (line.find("BlOutNd") != std::string::npos)
            line = "3, 5, 7, 9, 11, 13, 15, 17, 18    BlOutNd             - Blade nodes whose "
                   "values will be output  (-)";
        text += line + "\n";
    }
    test_support::write_file(ad, text);
    for (const auto& [key, value] : settings) set_entry(d, key, value);
    return d;
}

/// Whether the run sets an entry a check cannot represent yet (say so).
inline bool sets_any(const Case& c, const std::vector<std::string>& keys) {
    for (const std::string& key : keys)
        if (c.setting(key) && std::stod(*c.setting(key)) != 0) {
            MESSAGE(c.file << ": left out, this check cannot represent " << key << " = "
                           << *c.setting(key));
            return true;
        }
    return false;
}

} // namespace reference_cases
