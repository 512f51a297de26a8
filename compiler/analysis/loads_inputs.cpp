// The runs of a batch folder and a table of wind speeds (loads_inputs.hpp).
#include "analysis/loads_inputs.hpp"

#include "analysis/batch_summary.hpp"
#include "diag/errors.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace yamsc::analysis {

using diag::UserError;

namespace {

/// The fields of a CSV line (RFC 4180 quotes, as batch manifests use them).
std::vector<std::string> csv_fields(const std::string& line) {
    std::vector<std::string> fields(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted) {
            if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
                fields.back() += '"';
                ++i;
            } else if (c == '"') {
                quoted = false;
            } else {
                fields.back() += c;
            }
        } else if (c == '"') {
            quoted = true;
        } else if (c == ',') {
            fields.emplace_back();
        } else if (c != '\r') {
            fields.back() += c;
        }
    }
    for (std::string& f : fields) {
        const auto b = f.find_first_not_of(" \t"), e = f.find_last_not_of(" \t");
        f = b == std::string::npos ? std::string() : f.substr(b, e - b + 1);
    }
    return fields;
}

} // namespace

BatchRuns batch_runs(const std::string& dir) {
    BatchRuns b;
    b.summary = (std::filesystem::path(dir) / "summary.csv").string();
    if (!std::filesystem::is_regular_file(b.summary))
        throw UserError(dir +
                        ": no summary.csv (a batch run in shards: `yamsc batch merge` them first)");
    for (const CaseSummary& c : read_summary(b.summary)) {
        if (c.ok)
            b.files.push_back((std::filesystem::path(dir) / (c.id + ".csv")).string());
        else
            b.skipped.push_back(c.id + ": " + c.message);
    }
    if (b.files.empty()) throw UserError(b.summary + ": no case finished");
    return b;
}

std::map<std::string, double> read_speeds(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw UserError("cannot read '" + path + "'");
    std::string line;
    int line_no = 0;
    std::vector<std::string> header;
    while (header.empty() && std::getline(in, line)) {
        ++line_no;
        if (line.find_first_not_of(" \t\r") != std::string::npos) header = csv_fields(line);
    }
    int id_col = -1, speed_col = -1;
    for (std::size_t j = 0; j < header.size(); ++j) {
        if (header[j] == "id") id_col = static_cast<int>(j);
        if (speed_col < 0 && (header[j] == "speed" || header[j] == "wind"))
            speed_col = static_cast<int>(j);
    }
    if (id_col < 0 || speed_col < 0)
        throw UserError(path + ":" + std::to_string(line_no) +
                        ": expected the columns id and speed (or wind)");
    std::map<std::string, double> speeds;
    while (std::getline(in, line)) {
        ++line_no;
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        const auto fields = csv_fields(line);
        const auto j = static_cast<std::size_t>(speed_col);
        if (fields.size() <= std::max(j, static_cast<std::size_t>(id_col)))
            throw UserError(path + ":" + std::to_string(line_no) + ": " +
                            std::to_string(fields.size()) + " fields, the header has " +
                            std::to_string(header.size()));
        char* end = nullptr;
        const double v = std::strtod(fields[j].c_str(), &end);
        if (fields[j].empty() || *end != '\0' || !std::isfinite(v))
            throw UserError(path + ":" + std::to_string(line_no) + ": the speed '" + fields[j] +
                            "' is not a number");
        speeds[fields[static_cast<std::size_t>(id_col)]] = v;
    }
    return speeds;
}

} // namespace yamsc::analysis
