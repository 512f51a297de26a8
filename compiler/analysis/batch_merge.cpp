// `yamsc batch merge DIR...`: the summaries of the shards of one manifest
// (`summary-K-of-N.csv`, written by `yamsc batch --shard K/N`) as one summary,
// in manifest order: the same file a single run writes.
#include "analysis/batch_summary.hpp"
#include "analysis/commands.hpp"

#include <yamsc/atomic_file.hpp>

#include <algorithm>
#include <cstdio>
#include <dirent.h>
#include <map>
#include <ostream>
#include <set>

namespace yamsc::analysis {

using diag::UsageError;
using driver::BatchMergeOptions;

namespace {

/// The shard summaries in `dir`: (N, K) -> path.
std::map<std::pair<int, int>, std::string> shard_summaries(const std::string& dir) {
    std::map<std::pair<int, int>, std::string> out;
    DIR* d = ::opendir(dir.c_str());
    if (!d) throw diag::UserError("cannot read the folder '" + dir + "'");
    while (const dirent* e = ::readdir(d)) {
        int k = 0, n = 0;
        char tail[8] = {};
        if (std::sscanf(e->d_name, "summary-%d-of-%d.cs%1s", &k, &n, tail) == 3 &&
            std::string(tail) == "v" &&
            std::string(e->d_name) ==
                "summary-" + std::to_string(k) + "-of-" + std::to_string(n) + ".csv")
            out[{n, k}] = dir + "/" + e->d_name;
    }
    ::closedir(d);
    return out;
}

} // namespace

int batch_merge(const BatchMergeOptions& o, std::ostream& out, std::ostream& err) {
    if (o.dirs.empty()) throw UsageError("batch merge needs the shards' output folders");
    std::map<std::pair<int, int>, std::string> found;
    for (const std::string& dir : o.dirs)
        for (const auto& [key, path] : shard_summaries(dir))
            if (!found.emplace(key, path).second)
                throw diag::UserError("shard " + std::to_string(key.second) + "/" +
                                      std::to_string(key.first) +
                                      " has two summaries: " + found[key] + " and " + path);
    std::set<int> counts;
    for (const auto& entry : found) counts.insert(entry.first.first);
    if (counts.empty()) throw diag::UserError("no shard summaries (summary-K-of-N.csv) found");
    if (counts.size() > 1)
        throw diag::UserError("summaries of different shard counts (--shard k/N with several N)");
    const int n = *counts.begin();
    std::string missing;
    for (int k = 1; k <= n; ++k)
        if (!found.count({n, k}))
            missing += (missing.empty() ? "" : ", ") + std::to_string(k) + "/" + std::to_string(n);
    if (!missing.empty()) throw diag::UserError("missing shards: " + missing);

    std::vector<CaseSummary> all;
    std::map<int, std::string> row_from;
    for (const auto& [key, path] : found)
        for (const CaseSummary& s : read_summary(path)) {
            if (!row_from.emplace(s.row, path).second)
                throw diag::UserError("row " + std::to_string(s.row) + " is in " + row_from[s.row] +
                                      " and " + path);
            all.push_back(s);
        }
    std::sort(all.begin(), all.end(),
              [](const CaseSummary& a, const CaseSummary& b) { return a.row < b.row; });
    const std::string output = o.output.empty() ? o.dirs.front() + "/summary.csv" : o.output;
    runtime::write_file_atomically(output, summary_text(all));
    const auto failed =
        std::count_if(all.begin(), all.end(), [](const CaseSummary& s) { return !s.ok; });
    for (const CaseSummary& s : all)
        if (!s.ok) err << s.message << "\n";
    out << "batch merge: " << n << " shards, " << all.size() << " cases, " << all.size() - failed
        << " ok, " << failed << " failed; wrote " << output << "\n";
    return failed ? 1 : 0;
}

} // namespace yamsc::analysis
