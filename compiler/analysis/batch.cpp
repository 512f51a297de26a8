// `yamsc batch`: the rows of a manifest run as `yamsc sim` runs them
// (sim_case.hpp), each in a process forked from this one (batch_isolation.hpp),
// N at a time. Each distinct model is loaded once, before any case starts, and
// its compiled library inherited by every case; each binds its parameters in
// its own copy. The jobs (batch_jobs.hpp), their models (batch_models.hpp),
// one case (batch_case.hpp), the processes (batch_isolation.hpp), the stop on
// a signal (batch_pool.hpp), the progress
// (batch_progress.hpp) and the output folder (batch_files.hpp) each have
// their file; this one runs them in order and writes the summary.
#include "analysis/batch_case.hpp"
#include "analysis/batch_files.hpp"
#include "analysis/batch_isolation.hpp"
#include "analysis/batch_jobs.hpp"
#include "analysis/batch_models.hpp"
#include "analysis/batch_pool.hpp"
#include "analysis/batch_progress.hpp"
#include "analysis/commands.hpp"

#include <yamsc/atomic_file.hpp>

#include <ostream>

namespace yamsc::analysis {

using diag::UsageError;
using driver::BatchOptions;

namespace {

/// What this run will do, on stderr.
void announce(const BatchOptions& o, std::size_t rows, const std::vector<Job>& jobs,
              std::size_t pending, std::size_t threads, std::ostream& err) {
    std::size_t reused = 0;
    for (const Job& job : jobs)
        if (job.done && job.summary.ok) ++reused;
    err << "yamsc: batch: " << jobs.size() << " cases"
        << (o.shards > 1 ? " (shard " + std::to_string(o.shard) + "/" + std::to_string(o.shards) +
                               " of " + std::to_string(rows) + " rows)"
                         : std::string())
        << ", " << reused << " done before, " << pending << " to run on " << threads
        << (threads == 1 ? " thread\n" : " threads\n");
}

/// The summary of every job (the failed ones' errors on stderr too): the
/// exit status.
int write_summary(const BatchOptions& o, const std::string& dir, const std::vector<Job>& jobs,
                  std::ostream& out, std::ostream& err) {
    std::vector<CaseSummary> summaries;
    std::size_t failed = 0;
    for (const Job& job : jobs) {
        summaries.push_back(job.summary);
        if (!job.summary.ok) {
            ++failed;
            err << one_line(job.summary.message) << "\n";
        }
    }
    const std::string summary = dir + "/" +
                                (o.shards > 1 ? "summary-" + std::to_string(o.shard) + "-of-" +
                                                    std::to_string(o.shards) + ".csv"
                                              : std::string("summary.csv"));
    runtime::write_file_atomically(summary, summary_text(summaries));
    out << "batch: " << jobs.size() << " cases, " << jobs.size() - failed << " ok, " << failed
        << " failed; wrote " << summary << "\n";
    return failed ? 1 : 0;
}

} // namespace

int batch(const BatchOptions& o, std::ostream& out, std::ostream& err) {
    if (o.shards < 1 || o.shard < 1 || o.shard > o.shards)
        throw UsageError("--shard takes k/N with 1 <= k <= N");
    const Manifest m = read_manifest(o.manifest);
    const std::string dir = o.output_dir.empty() ? default_output_dir(o.manifest) : o.output_dir;
    make_dirs(dir + "/.records");

    std::vector<Job> jobs = shard_jobs(m, o.shard, o.shards);
    BatchModels models(err);
    prepare_jobs(jobs, models, dir, batch_inputs(o.manifest, jobs));
    const std::vector<Job*> pending = pending_jobs(jobs);
    std::vector<std::string> ids;
    for (const Job* job : pending) ids.push_back(job->c->id);
    remove_leftovers(dir, ids);
    const std::size_t threads = thread_count(o.threads, pending.size());
    if (!o.quiet) announce(o, m.rows.size(), jobs, pending.size(), threads, err);

    Progress progress(err, pending.size(), o.quiet);
    const StopOnSignal signals(o.stop_on_signal);
    run_isolated(
        pending, threads, o.case_time_limit, dir, signals,
        [&](Job& job, Loaded& model) { run_job(job, model, dir); },
        [&](const Job& job) { progress.finished(job.summary.ok); });
    if (signals.stopped()) {
        // The summary is written by the run that finishes; the results and
        // records written so far are kept for it.
        err << "yamsc: batch interrupted after " << progress.done() << " of " << pending.size()
            << " cases to run; run the same command again to finish\n";
        return 130;
    }
    return write_summary(o, dir, jobs, out, err);
}

} // namespace yamsc::analysis
