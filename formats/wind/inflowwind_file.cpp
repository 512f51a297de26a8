#include "wind/inflowwind_file.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace yamsc::wind {

namespace {

/// Every entry of InflowWind's primary file (OpenFAST v4/v5), in its order.
const char* const known_keys[] = {"Echo",
                                  "WindType",
                                  "PropagationDir",
                                  "VFlowAng",
                                  "VelInterpCubic",
                                  "NWindVel",
                                  "WindVxiList",
                                  "WindVyiList",
                                  "WindVziList",
                                  "HWindSpeed",
                                  "RefHt",
                                  "PLexp",
                                  "FileName_Uni",
                                  "RefHt_Uni",
                                  "RefLength",
                                  "FileName_BTS",
                                  "FileNameRoot",
                                  "TowerFile",
                                  "FileName_u",
                                  "FileName_v",
                                  "FileName_w",
                                  "nx",
                                  "ny",
                                  "nz",
                                  "dx",
                                  "dy",
                                  "dz",
                                  "RefHt_Hawc",
                                  "ScaleMethod",
                                  "SFx",
                                  "SFy",
                                  "SFz",
                                  "SigmaFx",
                                  "SigmaFy",
                                  "SigmaFz",
                                  "URef",
                                  "WindProfile",
                                  "PLExp_Hawc",
                                  "Z0",
                                  "XOffset",
                                  "SensorType",
                                  "NumPulseGate",
                                  "PulseSpacing",
                                  "NumBeam",
                                  "FocalDistanceX",
                                  "FocalDistanceY",
                                  "FocalDistanceZ",
                                  "RotorApexOffsetPos",
                                  "URefLid",
                                  "MeasurementInterval",
                                  "LidRadialVel",
                                  "ConsiderHubMotion",
                                  "SumPrint",
                                  "OutList"};

bool same(const std::string& a, const std::string& b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) ==
                      std::tolower(static_cast<unsigned char>(y));
           });
}

const char* known(const std::string& token) {
    for (const char* k : known_keys)
        if (same(token, k)) return k;
    return nullptr;
}

struct Token {
    std::string text;
    int column = 0;
    bool quoted = false;
};

/// Whitespace-separated tokens; "..." or '...' one token without its quotes.
std::vector<Token> tokens(const std::string& line) {
    std::vector<Token> out;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        if (i >= line.size()) break;
        Token t;
        t.column = static_cast<int>(i) + 1;
        if (line[i] == '"' || line[i] == '\'') {
            const char q = line[i];
            const std::size_t end = line.find(q, i + 1);
            t.quoted = true;
            t.text = line.substr(i + 1, (end == std::string::npos ? line.size() : end) - i - 1);
            i = end == std::string::npos ? line.size() : end + 1;
        } else {
            const std::size_t start = i;
            while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
            t.text = line.substr(start, i - start);
        }
        out.push_back(std::move(t));
    }
    return out;
}

bool section_or_comment(const std::vector<Token>& t) {
    if (t.empty()) return true;
    const std::string& s = t.front().text;
    if (t.front().quoted) return false;
    return s.rfind("---", 0) == 0 || s.rfind("===", 0) == 0 || s[0] == '!' || s[0] == '#';
}

std::string at(const std::string& source, int line, int column) {
    return source + ":" + std::to_string(line) + ":" + std::to_string(column) + ": ";
}

bool parse_double(const std::string& text, double& v) {
    std::istringstream s(text);
    s.imbue(std::locale::classic());
    s >> v;
    return !s.fail() && s.eof() && std::isfinite(v);
}

/// The most lines read: larger files are not InflowWind input files.
constexpr int max_lines = 100000;

} // namespace

const InflowWindEntry* InflowWindFile::find(const std::string& key) const {
    for (const InflowWindEntry& e : entries)
        if (same(e.key, key)) return &e;
    return nullptr;
}

const InflowWindEntry& InflowWindFile::entry(const std::string& key) const {
    if (const InflowWindEntry* e = find(key)) return *e;
    throw std::runtime_error(at(source, std::max(last_line, 1), 1) + "InflowWind: missing entry " +
                             key);
}

void InflowWindFile::fail(const InflowWindEntry& e, const std::string& what) const {
    throw std::runtime_error(
        at(source, e.line, e.columns.empty() ? e.key_column : e.columns.front()) + what);
}

void InflowWindFile::warn(const InflowWindEntry& e, const std::string& what) {
    warnings.push_back(at(source, e.line, e.columns.empty() ? e.key_column : e.columns.front()) +
                       "warning: " + what);
}

std::string InflowWindFile::text(const std::string& key) const {
    const InflowWindEntry& e = entry(key);
    if (e.values.size() != 1) fail(e, e.key + ": expected one value before the key");
    return e.values.front();
}

double InflowWindFile::number(const std::string& key) const {
    const InflowWindEntry& e = entry(key);
    double v = 0;
    if (e.values.size() != 1 || !parse_double(e.values.front(), v))
        fail(e, e.key + ": expected a number");
    return v;
}

double InflowWindFile::number_or(const std::string& key, double fallback) const {
    const InflowWindEntry* e = find(key);
    if (!e || (e->values.size() == 1 && same(e->values.front(), "default"))) return fallback;
    return number(key);
}

int InflowWindFile::integer(const std::string& key) const {
    const InflowWindEntry& e = entry(key);
    const double v = number(key);
    if (v != std::floor(v) || std::abs(v) > 1e9) fail(e, e.key + ": expected an integer");
    return static_cast<int>(v);
}

bool InflowWindFile::flag(const std::string& key) const {
    const InflowWindEntry& e = entry(key);
    const std::string v = text(key);
    if (same(v, "true") || same(v, "t") || v == "1") return true;
    if (same(v, "false") || same(v, "f") || v == "0") return false;
    fail(e, e.key + ": expected True or False");
}

std::string InflowWindFile::path(const std::string& key) const {
    std::string p = text(key);
    if (p.empty() || p.front() == '/') return p;
    const std::size_t slash = source.find_last_of('/');
    return slash == std::string::npos ? p : source.substr(0, slash + 1) + p;
}

bool looks_like_inflowwind(std::istream& in) {
    std::string line;
    for (int n = 0; n < 12 && std::getline(in, line); ++n) {
        const std::vector<Token> t = tokens(line);
        if (t.size() >= 2 && same(t[1].text, "WindType")) return true;
    }
    return false;
}

InflowWindFile read_inflowwind_file(std::istream& in, const std::string& source) {
    InflowWindFile f;
    f.source = source;
    std::string line;
    int n = 0;
    bool in_out_list = false;
    while (std::getline(in, line)) {
        if (++n > max_lines)
            throw std::runtime_error(at(source, n, 1) + "more than " + std::to_string(max_lines) +
                                     " lines: not an InflowWind input file");
        f.last_line = n;
        if (n <= 3) continue; // the banner, the title and a section line
        const std::vector<Token> t = tokens(line);
        if (in_out_list) {
            if (!t.empty() && !t.front().quoted && same(t.front().text.substr(0, 3), "END")) {
                in_out_list = false;
                break; // the rest of the file is not read (as OpenFAST reads it)
            }
            if (section_or_comment(t)) continue;
            f.out_list.push_back({t.front().text, {}, {}, n, t.front().column});
            continue;
        }
        if (section_or_comment(t)) continue;
        // The key: the first token InflowWind knows after at least one value (or at
        // the start for OutList), else the second token.
        std::size_t k = t.size();
        for (std::size_t i = 0; i < t.size(); ++i)
            if (!t[i].quoted && known(t[i].text) && (i > 0 || same(t[i].text, "OutList"))) {
                k = i;
                break;
            }
        InflowWindEntry e;
        e.line = n;
        const bool is_known = k < t.size();
        if (!is_known) k = t.size() >= 2 ? 1 : 0;
        e.key = is_known ? known(t[k].text) : t[k].text;
        e.key_column = t[k].column;
        for (std::size_t i = 0; i < k; ++i) {
            e.values.push_back(t[i].text);
            e.columns.push_back(t[i].column);
        }
        if (!is_known) {
            f.warn(e, "InflowWind: unknown entry '" + e.key + "', not read");
            continue;
        }
        if (f.find(e.key)) f.fail(e, "InflowWind: " + e.key + " given twice");
        if (e.key == std::string("OutList")) in_out_list = true;
        f.entries.push_back(std::move(e));
    }
    if (!f.find("WindType"))
        throw std::runtime_error(at(source, std::max(n, 1), 1) +
                                 "InflowWind: no WindType entry (not an InflowWind input file?)");
    return f;
}

} // namespace yamsc::wind
