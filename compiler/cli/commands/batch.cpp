// `yamsc batch` and `yamsc batch merge`: many simulations from a manifest.
#include "analysis/commands.hpp"
#include "cli/commands/commands.hpp"

#include <cmath>
#include <stdexcept>

namespace yamsc::cli {

namespace {

using driver::BatchMergeOptions;
using driver::BatchOptions;

/// --shard k/N into o.shard and o.shards.
void parse_shard(const std::string& s, BatchOptions& o) {
    const auto slash = s.find('/');
    std::size_t k_end = 0, n_end = 0;
    try {
        if (slash == std::string::npos) throw std::invalid_argument(s);
        o.shard = std::stoi(s.substr(0, slash), &k_end);
        o.shards = std::stoi(s.substr(slash + 1), &n_end);
    } catch (const std::exception&) {
        k_end = 0;
    }
    if (k_end != slash || slash + 1 + n_end != s.size() || o.shards < 1 || o.shard < 1 ||
        o.shard > o.shards)
        throw UsageError("--shard takes k/N with 1 <= k <= N (e.g. 2/8), not '" + s + "'");
}

BatchOptions parse_batch(const Args& a) {
    BatchOptions o;
    o.manifest = a.model();
    o.output_dir = a.get("-o");
    const double threads = a.number("--threads", 0);
    if (threads != std::floor(threads) || threads < 1 || threads > 4096)
        if (a.has("--threads")) throw UsageError("--threads must be a whole number >= 1");
    o.threads = static_cast<int>(threads);
    if (a.has("--shard")) parse_shard(a.get("--shard"), o);
    o.case_time_limit = a.number("--case-time-limit", 0);
    if (a.has("--case-time-limit") && !(o.case_time_limit > 0))
        throw UsageError("--case-time-limit must be positive [s]");
    o.quiet = a.has("-q");
    o.stop_on_signal = true;
    return o;
}

BatchMergeOptions parse_batch_merge(const Args& a) {
    BatchMergeOptions o;
    o.dirs = a.positionals();
    o.output = a.get("-o");
    return o;
}

} // namespace

Command batch_command() {
    return make_command(
        "batch", "one sim per row of a manifest, each case in its own process, restartable",
        "yamsc batch CASES.csv [-o OUTDIR] [--threads N] [--shard k/N] [--case-time-limit S] [-q]",
        R"(  CASES.csv           columns id,model,tmax,dt and optionally method,rtol,atol,set,ic,u,
                      wind,aero,dt_out,channels,controller,controller_input,coupling,
                      interp_order,time_limit,mooring,hydro,sea_state,set:NAME,ic:NAME,
                      u:NAME (docs/batch.md)
  -o OUTDIR           where <id>.csv and summary.csv go (default: CASES.out)
  --threads N         cases at a time (default: one per core)
  --case-time-limit S a case still running after S seconds is stopped and failed
  --shard k/N         only the rows whose index mod N is k - 1 (yamsc batch merge --help)
  -q                  no progress on stderr
A rerun runs only the cases not finished yet (or edited).
)",
        {{"-o", "--threads", "--shard", "--case-time-limit"}, {"-q"}}, parse_batch,
        analysis::batch);
}

Command batch_merge_command() {
    return make_command("batch merge", "the summaries of batch shards as one",
                        "yamsc batch merge OUTDIR... [-o summary.csv]",
                        R"(  OUTDIR...           the output folders of the shards
  -o FILE             the merged summary (default: summary.csv in the first folder)
)",
                        {{"-o"}, {}}, parse_batch_merge, analysis::batch_merge);
}

} // namespace yamsc::cli
