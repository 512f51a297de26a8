// Reading an OpenFAST deck: the `.fst` glue-code file (optional) and the ElastoDyn
// main file, with every entry accounted for (see deck.hpp).
#include "openfast/deck.hpp"

#include "openfast/gauge_nodes.hpp"

#include "diag/read_text.hpp"
#include "elastodyn/file.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <set>

namespace yamsc::openfast {

namespace fs = std::filesystem;
using diag::Kind;

namespace {

std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

/// `BlPitch(1)` -> `blpitch1`: the key compared without case and parentheses.
std::string canonical(const std::string& key) {
    std::string out;
    for (char c : key)
        if (c != '(' && c != ')')
            out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

using elastodyn::Token;
using elastodyn::tokenize;

bool is_key(const Token& t) {
    if (t.quoted || t.text.empty() || !std::isalpha(static_cast<unsigned char>(t.text[0])))
        return false;
    const std::string l = lower(t.text);
    return l != "true" && l != "false" && l != "t" && l != "f" && l != "default" && l != "unused" &&
           l != "none";
}

// How `from-openfast` treats each entry of the ElastoDyn main file.
// `off_by_default`: features of newer ElastoDyn files that the model does not have
// (pitch DOF, platform reference offsets, yaw friction): without effect at their
// default 0 or False, a warning otherwise.
enum class Use { dof, number, file, ignored, two_bladed, furling, optional_number, off_by_default };

/// The numeric entries of the ElastoDyn main file that the model uses, in ElastoDyn's
/// spelling (without "()"): the one list both the classification of the entries
/// and their names in OpenFastDeck::num come from.
const std::vector<std::string>& numeric_entries() {
    static const std::vector<std::string> names{
        "OoPDefl",   "IPDefl",    "BlPitch1",  "BlPitch2",  "BlPitch3",  "Azimuth",   "RotSpeed",
        "NacYaw",    "TTDspFA",   "TTDspSS",   "PtfmSurge", "PtfmSway",  "PtfmHeave", "PtfmRoll",
        "PtfmPitch", "PtfmYaw",   "NumBl",     "TipRad",    "HubRad",    "PreCone1",  "PreCone2",
        "PreCone3",  "HubCM",     "OverHang",  "ShftTilt",  "NacCMxn",   "NacCMyn",   "NacCMzn",
        "Twr2Shft",  "TowerHt",   "TowerBsHt", "PtfmCMxt",  "PtfmCMyt",  "PtfmCMzt",  "PtfmRefzt",
        "TipMass1",  "TipMass2",  "TipMass3",  "HubMass",   "HubIner",   "GenIner",   "NacMass",
        "NacYIner",  "YawBrMass", "PtfmMass",  "PtfmRIner", "PtfmPIner", "PtfmYIner", "BldNodes",
        "GBRatio",   "DTTorSpr",  "DTTorDmp",  "TwrNodes"};
    return names;
}

/// Numeric entries the model uses when present (defaults otherwise).
const std::vector<std::string>& optional_numeric_entries() {
    static const std::vector<std::string> names{"Gravity",    "AzimB1Up",   "GBoxEff", "PtfmXYIner",
                                                "PtfmYZIner", "PtfmXZIner", "ShftGagL"};
    return names;
}

const std::map<std::string, Use>& elastodyn_keys() {
    static const std::map<std::string, Use> keys = [] {
        std::map<std::string, Use> k;
        for (const std::string& f : elastodyn_dof_flags()) k[canonical(f)] = Use::dof;
        for (const std::string& n : numeric_entries()) k[canonical(n)] = Use::number;
        for (const std::string& n : optional_numeric_entries())
            k[canonical(n)] = Use::optional_number;
        for (const char* n : {"BldFile1", "BldFile2", "BldFile3", "TwrFile"})
            k[canonical(n)] = Use::file;
        for (const char* n : {"Echo",          "Method",        "DT",
                              "NcIMUxn",       "NcIMUyn",       "NcIMUzn",
                              "SumPrint",      "OutFile",       "TabDelim",
                              "OutFmt",        "TStart",        "DecFact",
                              "NTwGages",      "TwrGagNd",      "NBlGages",
                              "BldGagNd",      "OutList",       "BldNd_BladesOut",
                              "BldNd_BlOutNd", "OutList_Nodal", "BldNd_Blades",
                              "BldNd_Nodes"})
            k[canonical(n)] = Use::ignored;
        for (const char* n : {"PitchDOF", "PtfmRefxt", "PtfmRefyt", "YawFrctMod", "PBrIner1",
                              "PBrIner2", "PBrIner3", "BlPIner1", "BlPIner2", "BlPIner3"})
            k[canonical(n)] = Use::off_by_default;
        // Yaw friction coefficients: used only with YawFrctMod != 0 (warned above).
        for (const char* n : {"M_CSmax", "M_FCSmax", "M_MCSmax", "M_CD", "M_FCD", "M_MCD", "sig_v",
                              "sig_v2", "OmgCut"})
            k[canonical(n)] = Use::ignored;
        k[canonical("HubIner_Teeter")] = Use::two_bladed;
        for (const char* n : {"TeetDefl", "UndSling", "Delta3", "TeetMod", "TeetDmpP", "TeetDmp",
                              "TeetCDmp", "TeetSStP", "TeetHStP", "TeetSSSp", "TeetHSSp"})
            k[canonical(n)] = Use::two_bladed;
        k[canonical("TeetDOF")] = Use::two_bladed;
        k[canonical("Furling")] = Use::furling;
        k[canonical("FurlFile")] = Use::furling;
        return k;
    }();
    return keys;
}

/// The glue-code switches whose modules add loads that the model leaves as inputs.
const std::vector<std::pair<std::string, std::string>>& fst_modules() {
    static const std::vector<std::pair<std::string, std::string>> modules{
        {"CompInflow", "inflow wind"},
        {"CompAero", "aerodynamic loads"},
        {"CompServo", "control and generator torque"},
        {"CompHydro", "hydrodynamic loads"},
        {"CompSub", "substructure dynamics"},
        {"CompMooring", "mooring loads"},
        {"CompIce", "ice loads"}};
    return modules;
}

/// CompMooring values whose lines become `load mooring`: MAP++ (1) and MoorDyn
/// (3), whose file yamsc reads as quasi-static lines (docs/mooring.md).
bool mooring_as_block(const std::string& comp_mooring) {
    return comp_mooring == "1" || comp_mooring == "3";
}

std::string file_line(const diag::SourceFile& f, int line) {
    return fs::path(f.path()).filename().string() + ":" + std::to_string(line);
}

/// Resolves `name` (quoted in the deck) relative to the folder of `from`.
std::string resolve(const std::string& name, const diag::SourceFile& from) {
    fs::path p(name);
    if (p.is_absolute()) return p.lexically_normal().string();
    return (fs::path(from.path()).parent_path() / p).lexically_normal().string();
}

class Reader {
public:
    Reader(OpenFastDeck& deck, diag::Diagnostics& diags) : deck_(deck), diags_(diags) {}

    bool read(const std::string& path) {
        auto first = diag::read_text_file(path, diags_);
        if (!first) return false;
        if (looks_like_fst(*first)) {
            deck_.fst = first;
            if (!read_fst()) return false;
        } else {
            deck_.ed = first;
        }
        return read_elastodyn();
    }

private:
    static bool looks_like_fst(const diag::SourceFile& f) {
        for (const DeckEntry& e : scan_deck_entries(f))
            if (canonical(e.key) == "edfile") return true;
        return false;
    }

    bool read_fst() {
        const diag::SourceFile& f = *deck_.fst;
        std::string ed_file;
        for (const DeckEntry& e : scan_deck_entries(f)) {
            const std::string key = canonical(e.key);
            const diag::Location at{deck_.fst, e.line, e.col};
            if (key == "edfile") {
                ed_file = e.value;
            } else if (key == "gravity") {
                deck_.fst_gravity = elastodyn::parse_number(e.value);
                if (!deck_.fst_gravity)
                    diags_.error(Kind::InvalidValue, at, "Gravity must be a number");
            } else if (key == "tmax" || key == "dt") {
                if (auto v = elastodyn::parse_number(e.value))
                    (key == "tmax" ? deck_.tmax : deck_.dt) = v;
                ignore(f, e.key, e.line);
            } else if (key == "modcoupling" || key == "interporder") {
                // The run command's --coupling and --interp-order.
                if (auto v = elastodyn::parse_number(e.value); v && *v == static_cast<int>(*v))
                    (key == "modcoupling" ? deck_.mod_coupling : deck_.interp_order) =
                        static_cast<int>(*v);
                ignore(f, e.key, e.line);
            } else if (key == "airdens") {
                deck_.fst_air_density = elastodyn::parse_number(e.value);
                deck_.fst_air_density_at = file_line(f, e.line);
                ignore(f, e.key, e.line);
            } else if (key == "hydrofile" || key == "seastfile" || key == "mooringfile") {
                (key == "hydrofile"   ? deck_.offshore.hydro_file
                 : key == "seastfile" ? deck_.offshore.sea_state_file
                                      : deck_.offshore.mooring_file) = resolve(e.value, f);
                ignore(f, e.key, e.line);
            } else if (key == "wtrdens" || key == "wtrdpth" || key == "msl2swl") {
                (key == "wtrdens"   ? deck_.offshore.water_density
                 : key == "wtrdpth" ? deck_.offshore.water_depth
                                    : deck_.offshore.msl2swl) = elastodyn::parse_number(e.value);
                ignore(f, e.key, e.line);
            } else if (key == "inflowfile" || key == "aerofile" || key == "servofile") {
                deck_.module_files[e.key] = resolve(e.value, f);
                ignore(f, e.key, e.line);
            } else if (key == "compelast") {
                if (e.value != "1")
                    diags_.warning(Kind::NotSupported, at,
                                   "CompElast = " + e.value +
                                       ": only ElastoDyn is converted; the blades come from the "
                                       "ElastoDyn blade files");
            } else {
                bool module = false;
                for (const auto& [name, what] : fst_modules())
                    if (key == canonical(name)) {
                        module = true;
                        deck_.modules[name] = e;
                        // Wind, rotor aerodynamics and control become the rotor block
                        // (openfast/operation.cpp), which says what it converts.
                        const bool operation =
                            name == "CompInflow" || name == "CompAero" || name == "CompServo";
                        // HydroDyn, and MAP++ or MoorDyn (as quasi-static lines),
                        // become the platform's load blocks.
                        const bool block = (name == "CompHydro" && e.value == "1") ||
                                           (name == "CompMooring" && mooring_as_block(e.value));
                        if (e.value != "0" && !operation && !block)
                            diags_.warning(Kind::NotSupported, at,
                                           name + " = " + e.value + ": " + what +
                                               " are not converted; the model declares the "
                                               "loads as inputs");
                    }
                if (!module) ignore(f, e.key, e.line);
            }
        }
        // The files of modules that are off are not the model's.
        auto module_on = [&](const char* name) {
            const auto it = deck_.modules.find(name);
            return it != deck_.modules.end() && it->second.value == "1";
        };
        if (!module_on("CompHydro")) deck_.offshore.hydro_file = deck_.offshore.sea_state_file = "";
        const auto mooring = deck_.modules.find("CompMooring");
        if (mooring == deck_.modules.end() || !mooring_as_block(mooring->second.value))
            deck_.offshore.mooring_file.clear();
        if (ed_file.empty()) {
            diags_.error(Kind::MissingProperty, {deck_.fst, 0, 0},
                         "the .fst file has no EDFile (the ElastoDyn input file)");
            return false;
        }
        deck_.ed = diag::read_text_file(resolve(ed_file, f), diags_);
        return deck_.ed != nullptr;
    }

    bool read_elastodyn() {
        const diag::SourceFile& f = *deck_.ed;
        deck_.title = std::string(f.line(2));
        while (!deck_.title.empty() && std::isspace(static_cast<unsigned char>(deck_.title.back())))
            deck_.title.pop_back();
        const elastodyn::ElastoDynFile ed(deck_.ed);
        const int errors = diags_.error_count();
        std::set<std::string> seen;
        for (const DeckEntry& e : scan_deck_entries(f)) {
            const std::string key = canonical(e.key);
            if (!seen.insert(key).second) continue; // ElastoDyn reads the first one
            entries_[key] = e;
            deck_.where[key] = file_line(f, e.line);
            auto it = elastodyn_keys().find(key);
            if (it == elastodyn_keys().end()) {
                diags_.warning(Kind::UnknownProperty, {deck_.ed, e.line, e.col},
                               "unknown ElastoDyn entry '" + e.key + "': not converted");
                continue;
            }
            if (it->second == Use::ignored) ignore(f, e.key, e.line);
            if (key == canonical("Method"))
                if (const auto m = elastodyn::parse_number(e.value))
                    deck_.method = static_cast<int>(*m);
            if (it->second == Use::off_by_default) {
                const std::string value = lower(e.value);
                const auto number = elastodyn::parse_number(e.value);
                if (value == "false" || value == "f" || (number && *number == 0))
                    ignore(f, e.key, e.line);
                else
                    diags_.warning(Kind::NotSupported, {deck_.ed, e.line, e.col},
                                   e.key + " = " + e.value + ": not converted (the model has " +
                                       "no pitch DOF, platform reference offset or yaw friction)");
            }
        }
        keep_used_gauges(f);
        for (const std::string& flag : elastodyn_dof_flags()) {
            if (canonical(flag) == "teetdof") continue;
            if (auto v = ed.get_bool(key_of(flag), diags_)) deck_.dofs[flag] = *v;
        }
        auto blades = ed.get_int(key_of("NumBl"), diags_);
        if (blades && (*blades < 1 || *blades > 3))
            diags_.error(Kind::InvalidValue, ed.location(key_of("NumBl")),
                         "NumBl must be 1, 2 or 3");
        if (blades) deck_.blades = std::clamp(*blades, 1, 3);
        for (const auto& [key, use] : elastodyn_keys()) {
            if (use != Use::number && use != Use::optional_number) continue;
            const bool per_blade = key.back() >= '1' && key.back() <= '3' &&
                                   (key.rfind("blpitch", 0) == 0 || key.rfind("precone", 0) == 0 ||
                                    key.rfind("tipmass", 0) == 0);
            if (per_blade && key.back() - '0' > deck_.blades) continue;
            if (use == Use::optional_number && !entries_.count(key)) {
                deck_.num[name_of(key)] = key == "gboxeff" ? 100.0 : 0.0;
                if (key == "gravity") gravity_elsewhere();
                continue;
            }
            if (auto v = ed.get_double(key_of(name_of(key)), diags_)) {
                deck_.num[name_of(key)] = *v;
                deck_.text[name_of(key)] = entries_.count(key) ? entries_[key].value : "";
            }
        }
        if (auto n = ed.get_int(key_of("TwrNodes"), diags_)) deck_.tower_nodes = *n;
        if (auto n = ed.get_int(key_of("BldNodes"), diags_)) deck_.blade_nodes = *n;
        for (const char* key : {"TwrNodes", "BldNodes"}) {
            const int n = canonical(key) == "twrnodes" ? deck_.tower_nodes : deck_.blade_nodes;
            if (n < 3 || n > 10000)
                diags_.error(Kind::InvalidValue, ed.location(key_of(key)),
                             std::string(key) + " must be 3 to 10000 (it is " + std::to_string(n) +
                                 ")");
        }
        if (auto t = ed.get_string(key_of("TwrFile"), diags_)) deck_.tower_file = resolve(*t, f);
        for (int k = 1; k <= deck_.blades; ++k)
            if (auto b = ed.get_string(key_of("BldFile" + std::to_string(k)), diags_))
                deck_.blade_files.push_back(resolve(*b, f));
        report_unsupported(ed);
        return diags_.error_count() == errors;
    }

    /// Newer decks keep gravity in the `.fst` (older ElastoDyn files have their own).
    void gravity_elsewhere() {
        if (deck_.fst_gravity) {
            deck_.num["Gravity"] = *deck_.fst_gravity;
            return;
        }
        deck_.num["Gravity"] = 9.80665;
        diags_.warning(Kind::MissingProperty, {deck_.ed, 0, 0},
                       "no Gravity in the deck: using 9.80665 m/s^2");
    }

    void report_unsupported(const elastodyn::ElastoDynFile& ed) {
        auto warn = [&](const std::string& key, const std::string& message) {
            diags_.warning(Kind::NotSupported, ed.location(key_of(key)), message);
        };
        if (entries_.count("furling")) {
            const std::string v = lower(entries_["furling"].value);
            if (v == "true" || v == "t") warn("Furling", "furling is not converted");
        }
        if (deck_.blades == 2) {
            if (entries_.count("teetdof")) {
                const std::string v = lower(entries_["teetdof"].value);
                if (v == "true" || v == "t")
                    warn("TeetDOF", "the teeter DOF is not converted (the hub is rigid)");
            }
            for (const char* key : {"UndSling", "Delta3", "TeetDefl"})
                if (entries_.count(canonical(key)))
                    if (auto v = elastodyn::parse_number(entries_[canonical(key)].value);
                        v && *v != 0)
                        warn(key, std::string(key) + " of a teetering rotor is not converted");
        } else {
            for (const DeckEntry& e : scan_deck_entries(*deck_.ed)) {
                auto it = elastodyn_keys().find(canonical(e.key));
                if (it != elastodyn_keys().end() && it->second == Use::two_bladed)
                    ignore(*deck_.ed, e.key, e.line);
            }
        }
        if (deck_.num.count("GBoxEff") && deck_.num["GBoxEff"] != 100)
            warn("GBoxEff", "GBoxEff scales the generator torque, an input of the model: give "
                            "gen_torque with the losses included");
    }

    /// Gauges that exist become output channels (compiler/openfast/gauges.hpp): not ignored.
    void keep_used_gauges(const diag::SourceFile& f) {
        const GaugeNodes used = read_gauge_nodes(f);
        std::vector<std::string> keys;
        if (!used.tower.empty()) keys.insert(keys.end(), {"ntwgages:", "twrgagnd:"});
        if (!used.blade.empty()) keys.insert(keys.end(), {"nblgages:", "bldgagnd:"});
        auto& ignored = deck_.ignored;
        ignored.erase(std::remove_if(ignored.begin(), ignored.end(),
                                     [&](const auto& entry) {
                                         const std::string key = lower(entry.second);
                                         for (const std::string& k : keys)
                                             if (key.rfind(k, 0) == 0) return true;
                                         return false;
                                     }),
                      ignored.end());
    }

    void ignore(const diag::SourceFile& f, const std::string& key, int line) {
        deck_.ignored.emplace_back(fs::path(f.path()).filename().string(),
                                   key + ":" + std::to_string(line));
    }

    /// The key as written in the file (for the ElastoDyn reader's messages), or the name.
    std::string key_of(const std::string& name) {
        auto it = entries_.find(canonical(name));
        return it == entries_.end() ? name : it->second.key;
    }

    /// The canonical name used in OpenFastDeck::num: ElastoDyn's spelling without "()".
    static std::string name_of(const std::string& key) {
        static const std::map<std::string, std::string> names = [] {
            std::map<std::string, std::string> n;
            for (const std::string& s : numeric_entries()) n[canonical(s)] = s;
            for (const std::string& s : optional_numeric_entries()) n[canonical(s)] = s;
            return n;
        }();
        auto it = names.find(key);
        return it == names.end() ? key : it->second;
    }

    OpenFastDeck& deck_;
    diag::Diagnostics& diags_;
    std::map<std::string, DeckEntry> entries_; // by canonical key
};

} // namespace

const std::vector<std::string>& elastodyn_dof_flags() {
    static const std::vector<std::string> flags{
        "PtfmSgDOF", "PtfmSwDOF", "PtfmHvDOF", "PtfmRDOF", "PtfmPDOF", "PtfmYDOF",
        "TwFADOF1",  "TwSSDOF1",  "TwFADOF2",  "TwSSDOF2", "YawDOF",   "GenDOF",
        "DrTrDOF",   "FlapDOF1",  "FlapDOF2",  "EdgeDOF",  "TeetDOF"};
    return flags;
}

namespace {

bool any_on(const std::map<std::string, bool>& dofs, const std::vector<std::string>& flags) {
    for (const std::string& f : flags) {
        auto it = dofs.find(f);
        if (it != dofs.end() && it->second) return true;
    }
    return false;
}

} // namespace

bool flexible_tower(const std::map<std::string, bool>& dofs) {
    static const std::vector<std::string> flags{"TwFADOF1", "TwSSDOF1", "TwFADOF2", "TwSSDOF2"};
    return any_on(dofs, flags);
}

bool flexible_blades(const std::map<std::string, bool>& dofs) {
    static const std::vector<std::string> flags{"FlapDOF1", "FlapDOF2", "EdgeDOF"};
    return any_on(dofs, flags);
}

std::vector<DeckEntry> scan_deck_entries(const diag::SourceFile& file) {
    std::vector<DeckEntry> out;
    bool in_outlist = false;
    // Lines 1 and 2 are the file's banner and title.
    for (int line = 3; line <= file.line_count(); ++line) {
        const std::vector<Token> t = tokenize(file.line(line));
        if (t.empty()) continue;
        const std::string first = lower(t[0].text);
        if (in_outlist) {
            if (!t[0].quoted && first.rfind("end", 0) == 0) in_outlist = false;
            continue;
        }
        if (first.rfind("---", 0) == 0 || first.rfind("===", 0) == 0) continue;
        // The key is the first name after the value (a value may be a list: "1, 2  Key").
        std::size_t k = 1;
        // A word followed by a key and its comment is a value ("heavy  NacMass  - ...").
        const bool word_value =
            t.size() >= 2 && is_key(t[1]) && (t.size() == 2 || t[2].text.rfind("-", 0) == 0);
        if (t[0].text.empty() || (is_key(t[0]) && !word_value)) {
            // "OutList  - The next line(s)...": a key without a value.
            if (canonical(t[0].text) == "outlist") {
                out.push_back({t[0].text, "", line, t[0].col});
                in_outlist = true;
            }
            continue;
        }
        while (k < t.size() && !is_key(t[k]) && !t[k].quoted &&
               std::isdigit(static_cast<unsigned char>(t[k].text[0])))
            ++k;
        if (k >= t.size() || !is_key(t[k])) continue;
        out.push_back({t[k].text, t[0].text, line, t[0].col});
        if (canonical(t[k].text) == "outlist") in_outlist = true;
    }
    return out;
}

std::optional<OpenFastDeck> read_openfast_deck(const std::string& path, diag::Diagnostics& diags) {
    OpenFastDeck deck;
    Reader reader(deck, diags);
    if (!reader.read(path)) return std::nullopt;
    return deck;
}

} // namespace yamsc::openfast
