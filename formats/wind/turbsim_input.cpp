#include "wind/turbsim_input.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <locale>
#include <sstream>
#include <stdexcept>

namespace yamsc::wind {

namespace {

/// How each of TurbSim's entries is treated here.
enum class Use {
    read,         // the generator's
    ignored,      // TurbSim does not use it for IECKAI (or it changes no value)
    warn_if_true, // another output file: not written
    warn_if_set,  // a number other than 0, or anything but "default": not supported
    warn_always,  // never supported
};

struct Known {
    const char* key;
    Use use;
};

/// Every entry of TurbSim v2's input file (and "Clockwise" of older ones), in order.
constexpr Known known_entries[] = {
    {"Echo", Use::ignored},
    {"RandSeed1", Use::read},
    {"RandSeed2", Use::warn_always},
    {"WrBHHTP", Use::warn_if_true},
    {"WrFHHTP", Use::warn_if_true},
    {"WrADHH", Use::warn_if_true},
    {"WrADFF", Use::ignored},
    {"WrBLFF", Use::warn_if_true},
    {"WrADTWR", Use::warn_if_true},
    {"WrHAWCFF", Use::warn_if_true},
    {"WrFMTFF", Use::warn_if_true},
    {"WrACT", Use::warn_if_true},
    {"Clockwise", Use::ignored},
    {"ScaleIEC", Use::read},
    {"NumGrid_Z", Use::read},
    {"NumGrid_Y", Use::read},
    {"TimeStep", Use::read},
    {"AnalysisTime", Use::read},
    {"UsableTime", Use::read},
    {"HubHt", Use::read},
    {"GridHeight", Use::read},
    {"GridWidth", Use::read},
    {"VFlowAng", Use::warn_if_set},
    {"HFlowAng", Use::warn_if_set},
    {"TurbModel", Use::read},
    {"UserFile", Use::ignored},
    {"IECstandard", Use::read},
    {"IECturbc", Use::read},
    {"IEC_WindType", Use::read},
    {"ETMc", Use::read},
    {"WindProfileType", Use::read},
    {"ProfileFile", Use::ignored},
    {"RefHt", Use::read},
    {"URef", Use::read},
    {"ZJetMax", Use::ignored},
    {"PLExp", Use::read},
    {"Z0", Use::read},
    {"Latitude", Use::ignored},
    {"RICH_NO", Use::ignored},
    {"UStar", Use::ignored},
    {"ZI", Use::ignored},
    {"PC_UW", Use::ignored},
    {"PC_UV", Use::ignored},
    {"PC_VW", Use::ignored},
    {"SCMod1", Use::warn_if_set},
    {"SCMod2", Use::warn_if_set},
    {"SCMod3", Use::warn_if_set},
    {"InCDec1", Use::warn_if_set},
    {"InCDec2", Use::warn_if_set},
    {"InCDec3", Use::warn_if_set},
    {"CohExp", Use::warn_if_set},
    {"CTEventPath", Use::ignored},
    {"CTEventFile", Use::ignored},
    {"Randomize", Use::ignored},
    {"DistScl", Use::ignored},
    {"CTLy", Use::ignored},
    {"CTLz", Use::ignored},
    {"CTStartTime", Use::ignored},
};

std::string upper(std::string s) {
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

const Known* find_known(const std::string& word) {
    const std::string u = upper(word);
    for (const Known& k : known_entries)
        if (upper(k.key) == u) return &k;
    return nullptr;
}

/// One entry of the file: the words before its key, where each stands.
struct Entry {
    const Known* known = nullptr;
    std::vector<std::string> values;
    std::vector<int> columns;
    int line = 0, key_column = 0;
};

/// The words of a line: blanks and commas separate them, quotes enclose one.
struct Word {
    std::string text;
    int column;
};

std::vector<Word> split(const std::string& line) {
    std::vector<Word> words;
    std::size_t i = 0;
    auto blank = [&](char c) { return std::isspace(static_cast<unsigned char>(c)) || c == ','; };
    while (i < line.size()) {
        if (blank(line[i])) {
            ++i;
            continue;
        }
        const int column = static_cast<int>(i) + 1;
        if (line[i] == '"' || line[i] == '\'') {
            const std::size_t close = line.find(line[i], i + 1);
            const std::size_t end = close == std::string::npos ? line.size() : close;
            words.push_back({line.substr(i + 1, end - i - 1), column});
            i = end + 1;
            continue;
        }
        const std::size_t start = i;
        while (i < line.size() && !blank(line[i])) ++i;
        words.push_back({line.substr(start, i - start), column});
    }
    return words;
}

class Reader {
public:
    explicit Reader(const std::string& source) : source_(source) {}

    std::string at(int line, int column) const {
        return source_ + ":" + std::to_string(line) + ":" + std::to_string(column) + ": ";
    }
    [[noreturn]] void fail(const Entry& e, const std::string& what) const {
        throw std::runtime_error(at(e.line, e.columns.empty() ? e.key_column : e.columns[0]) +
                                 "TurbSim: " + e.known->key + ": " + what);
    }
    void warn(std::vector<std::string>& out, const Entry& e, const std::string& what) const {
        out.push_back(at(e.line, e.columns.empty() ? e.key_column : e.columns[0]) +
                      "warning: TurbSim: " + e.known->key + ": " + what);
    }

    std::vector<Entry> entries;
    int last_line = 0;

    const Entry* find(const char* key) const {
        for (const Entry& e : entries)
            if (upper(e.known->key) == upper(key)) return &e;
        return nullptr;
    }
    const Entry& entry(const char* key) const {
        if (const Entry* e = find(key)) return *e;
        throw std::runtime_error(at(std::max(last_line, 1), 1) + "TurbSim: missing entry " + key);
    }
    std::string text(const char* key) const {
        const Entry& e = entry(key);
        if (e.values.empty()) fail(e, "no value before the key");
        return e.values[0];
    }
    static bool is_default(const std::string& v) { return upper(v) == "DEFAULT"; }
    static bool parse(const std::string& text, double& v) {
        std::istringstream s(text);
        s.imbue(std::locale::classic());
        s >> v;
        return !s.fail() && s.eof() && std::isfinite(v);
    }
    double number(const char* key) const {
        double v = 0;
        if (!parse(text(key), v)) fail(entry(key), "expected a number, not '" + text(key) + "'");
        return v;
    }
    double positive(const char* key) const {
        const double v = number(key);
        if (!(v > 0)) fail(entry(key), "must be positive");
        return v;
    }
    double number_or(const char* key, double fallback) const {
        if (!find(key) || is_default(text(key))) return fallback;
        return number(key);
    }
    long long integer(const char* key, long long lo, long long hi) const {
        const double v = number(key);
        if (v != std::floor(v) || v < static_cast<double>(lo) || v > static_cast<double>(hi))
            fail(entry(key),
                 "expected an integer from " + std::to_string(lo) + " to " + std::to_string(hi));
        return static_cast<long long>(v);
    }

private:
    std::string source_;
};

/// The most lines read: larger files are not TurbSim input files.
constexpr int max_lines = 10000;

void warn_unsupported(const Reader& r, const Entry& e, std::vector<std::string>& warnings) {
    const std::string v = e.values.empty() ? "" : e.values[0];
    const std::string u = upper(v);
    switch (e.known->use) {
    case Use::read:
    case Use::ignored:
        return;
    case Use::warn_always:
        r.warn(warnings, e,
               "not used: yamsc draws its phases with its own generator (the same RandSeed1 "
               "gives another realisation than TurbSim)");
        return;
    case Use::warn_if_true:
        if (u == "TRUE" || u == "T")
            r.warn(warnings, e, "that file is not written (only the .bts, without tower points)");
        return;
    case Use::warn_if_set: {
        double x = 0;
        const bool zero = Reader::parse(v, x) && x == 0;
        if (!Reader::is_default(v) && !zero)
            r.warn(warnings, e,
                   "'" + v +
                       "' not supported: IEC coherence for u and none for v and w, no "
                       "flow angles (TurbSim's defaults for IECKAI)");
        return;
    }
    }
}

} // namespace

TurbSimInput read_turbsim_input(std::istream& in, const std::string& source) {
    Reader r(source);
    TurbSimInput t;
    t.source = source;
    std::string line;
    int n = 0;
    while (std::getline(in, line)) {
        if (++n > max_lines)
            throw std::runtime_error(r.at(n, 1) + "more than " + std::to_string(max_lines) +
                                     " lines: not a TurbSim input file");
        r.last_line = n;
        if (n <= 2) continue; // TurbSim's banner and title
        const std::vector<Word> w = split(line);
        if (w.size() < 2) continue;
        const std::string& first = w[0].text;
        if (first.rfind("---", 0) == 0 || first.rfind("===", 0) == 0 || first[0] == '!') continue;
        std::size_t k = 1;
        while (k < w.size() && !find_known(w[k].text)) ++k;
        if (k == w.size()) {
            t.warnings.push_back(r.at(n, w[1].column) + "warning: TurbSim: unknown entry '" +
                                 w[1].text + "', not read");
            continue;
        }
        Entry e;
        e.known = find_known(w[k].text);
        e.line = n;
        e.key_column = w[k].column;
        for (std::size_t i = 0; i < k; ++i) {
            e.values.push_back(w[i].text);
            e.columns.push_back(w[i].column);
        }
        if (r.find(e.known->key)) r.fail(e, "given twice");
        warn_unsupported(r, e, t.warnings);
        r.entries.push_back(std::move(e));
    }

    const std::string model = upper(r.text("TurbModel"));
    if (model != "IECKAI")
        r.fail(r.entry("TurbModel"),
               "'" + r.text("TurbModel") + "' not supported: yamsc generates IECKAI only");
    const std::string standard = upper(r.text("IECstandard"));
    if (standard != "1" && standard != "1-ED3")
        r.fail(r.entry("IECstandard"), "'" + r.text("IECstandard") +
                                           "' not supported: IEC 61400-1 Ed. 3 only (1 or 1-Ed3)");

    t.seed = r.integer("RandSeed1", std::numeric_limits<std::int32_t>::min(),
                       std::numeric_limits<std::int32_t>::max());
    t.scale_iec = static_cast<int>(r.integer("ScaleIEC", 0, 2));
    t.nz = static_cast<int>(r.integer("NumGrid_Z", 2, 1000));
    t.ny = static_cast<int>(r.integer("NumGrid_Y", 2, 1000));
    t.time_step = r.positive("TimeStep");
    t.analysis_time = r.positive("AnalysisTime");
    if (upper(r.text("UsableTime")) == "ALL") {
        t.periodic = true;
        t.usable_time = t.analysis_time;
    } else {
        t.usable_time = r.positive("UsableTime");
    }
    t.hub_height = r.positive("HubHt");
    t.grid_height = r.positive("GridHeight");
    t.grid_width = r.positive("GridWidth");
    if (t.analysis_time / t.time_step > 1e7)
        r.fail(r.entry("TimeStep"), "more than 1e7 time steps");

    const std::string turbc = upper(r.text("IECturbc"));
    if (turbc == "A" || turbc == "B" || turbc == "C") {
        t.characteristic = turbc == "A"   ? TurbulenceCharacteristic::A
                           : turbc == "B" ? TurbulenceCharacteristic::B
                                          : TurbulenceCharacteristic::C;
    } else {
        t.characteristic = TurbulenceCharacteristic::percent;
        t.intensity_percent = r.positive("IECturbc");
    }

    const std::string type = upper(r.text("IEC_WindType"));
    if (type == "NTM") {
        t.model = IecTurbulenceModel::normal;
    } else if (type.size() == 4 && type.substr(1) == "ETM" && type[0] >= '1' && type[0] <= '3') {
        t.model = IecTurbulenceModel::extreme;
        t.turbine_class = type[0] - '0';
        if (t.characteristic == TurbulenceCharacteristic::percent)
            r.fail(r.entry("IECturbc"), "the extreme turbulence model needs a class A, B or C");
    } else {
        r.fail(r.entry("IEC_WindType"),
               "'" + r.text("IEC_WindType") + "' not supported: NTM or 1ETM, 2ETM, 3ETM");
    }
    t.etm_c = r.number_or("ETMc", 2.0);
    if (!(t.etm_c > 0)) r.fail(r.entry("ETMc"), "must be positive");

    const std::string profile = upper(r.text("WindProfileType"));
    if (profile == "PL")
        t.profile = WindProfile::power_law;
    else if (profile == "LOG")
        t.profile = WindProfile::logarithmic;
    else
        r.fail(r.entry("WindProfileType"),
               "'" + r.text("WindProfileType") + "' not supported: PL or LOG");
    t.ref_height = r.positive("RefHt");
    t.ref_speed = r.positive("URef");
    t.power_law = r.number_or("PLExp", 0.2);
    if (!(std::abs(t.power_law) <= 10)) r.fail(r.entry("PLExp"), "out of range");
    t.roughness = r.number_or("Z0", 0.03);
    if (t.profile == WindProfile::logarithmic &&
        (!(t.roughness > 0) || t.roughness >= std::min(t.ref_height, t.hub_height)))
        r.fail(r.find("Z0") ? r.entry("Z0") : r.entry("RefHt"),
               "the roughness length must be positive and below the heights");
    return t;
}

} // namespace yamsc::wind
