#include "analysis/batch_summary.hpp"

#include "analysis/channels.hpp"
#include "diag/errors.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace yamsc::analysis {

const char* const summary_header = "row,id,status,final,message,wall_s";

namespace {

/// The fields of one CSV line (RFC 4180 quoting); false on an open quote.
bool fields_of(const std::string& line, std::vector<std::string>& out) {
    out.clear();
    std::string f;
    bool in_quotes = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (in_quotes) {
            if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
                f += '"';
                ++i;
            } else if (c == '"') {
                in_quotes = false;
            } else {
                f += c;
            }
        } else if (c == '"') {
            in_quotes = true;
        } else if (c == ',') {
            out.push_back(f);
            f.clear();
        } else if (c != '\r') {
            f += c;
        }
    }
    out.push_back(f);
    return !in_quotes;
}

std::string seconds(double s) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4f", s);
    return buf;
}

} // namespace

std::string one_line(const std::string& text) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '\n') {
            out += text[i];
        } else if (i + 1 < text.size()) {
            out += " | ";
        }
    }
    return out;
}

std::string summary_line(const CaseSummary& s) {
    return std::to_string(s.row) + "," + csv_field(s.id) + "," + (s.ok ? "ok" : "error") + "," +
           csv_field(s.final) + "," + csv_field(one_line(s.message)) + "," + seconds(s.wall_s) +
           "\n";
}

std::string summary_text(const std::vector<CaseSummary>& cases) {
    std::string out = std::string(summary_header) + "\n";
    for (const CaseSummary& s : cases) out += summary_line(s);
    return out;
}

std::vector<CaseSummary> read_summary(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw diag::UserError("cannot read the summary '" + path + "'");
    std::vector<CaseSummary> out;
    std::string line;
    int line_no = 0;
    std::vector<std::string> f;
    while (std::getline(in, line)) {
        ++line_no;
        const std::string where = path + ":" + std::to_string(line_no) + ":1: error: ";
        if (line_no == 1) {
            if (line != summary_header)
                throw diag::UserError(where + "not a summary of yamsc batch (header '" +
                                      std::string(summary_header) + "' expected)");
            continue;
        }
        if (!fields_of(line, f) || f.size() != 6 || (f[2] != "ok" && f[2] != "error"))
            throw diag::UserError(where + "malformed summary line");
        CaseSummary s;
        char* end = nullptr;
        s.row = static_cast<int>(std::strtol(f[0].c_str(), &end, 10));
        if (f[0].empty() || *end != '\0' || s.row < 1)
            throw diag::UserError(where + "malformed row number '" + f[0] + "'");
        s.id = f[1];
        s.ok = f[2] == "ok";
        s.final = f[3];
        s.message = f[4];
        s.wall_s = std::strtod(f[5].c_str(), nullptr);
        out.push_back(s);
    }
    if (line_no == 0) throw diag::UserError(path + ": error: an empty summary");
    return out;
}

std::string record_text(const std::string& digest, const CaseSummary& s) {
    return digest + "\n" + s.final + "\n" + seconds(s.wall_s) + "\n";
}

std::optional<CaseSummary> read_record(const std::string& path, const std::string& digest) {
    std::ifstream in(path);
    std::string d, final, wall;
    if (!in || !std::getline(in, d) || !std::getline(in, final) || !std::getline(in, wall) ||
        d != digest)
        return std::nullopt;
    CaseSummary s;
    s.ok = true;
    s.final = final;
    s.wall_s = std::strtod(wall.c_str(), nullptr);
    return s;
}

} // namespace yamsc::analysis
