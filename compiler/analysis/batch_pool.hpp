#pragma once
// The threads of `yamsc batch`: how many, the jobs handed out in manifest
// order, and a stop on SIGINT/SIGTERM after the cases in progress.
#include "analysis/batch_jobs.hpp"

#include <csignal>
#include <cstddef>
#include <functional>
#include <vector>

namespace yamsc::analysis {

/// `requested` threads (0: the cores this process may run on, a Slurm task's
/// share, not the machine's), at most one per job, at least one.
std::size_t thread_count(int requested, std::size_t jobs);

/// While alive (and enabled), SIGINT and SIGTERM ask the batch to stop after
/// the cases in progress (each then has its result and record, or none); a
/// signal the process ignores (a background job's SIGINT) stays ignored.
class StopOnSignal {
public:
    explicit StopOnSignal(bool enabled);
    ~StopOnSignal();
    StopOnSignal(const StopOnSignal&) = delete;
    StopOnSignal& operator=(const StopOnSignal&) = delete;
    bool stopped() const;

private:
    bool enabled_;
    const int signals_[2] = {SIGINT, SIGTERM};
    void (*old_[2])(int) = {SIG_DFL, SIG_DFL};
};

/// Runs `run(job, model)` for each of `jobs` on `threads` threads (this one
/// among them) until all ran or `stop` is set. Each thread works on its own
/// copy of each model (made once, not per case): the compiled library is
/// shared, the bound parameters are not.
void run_on_threads(const std::vector<Job*>& jobs, std::size_t threads, const StopOnSignal& stop,
                    const std::function<void(Job&, Loaded&)>& run);

} // namespace yamsc::analysis
