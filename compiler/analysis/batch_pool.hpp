#pragma once
// How many cases `yamsc batch` runs at a time, and its stop on SIGINT/SIGTERM
// after the cases in progress.
#include "analysis/batch_jobs.hpp"

#include <csignal>
#include <cstddef>
#include <functional>
#include <vector>

namespace yamsc::analysis {

/// `requested` cases at a time (0: the cores this process may run on, a Slurm task's
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

} // namespace yamsc::analysis
