#pragma once
// Each case of `yamsc batch` in a process of its own, forked from the batch
// after its models are loaded: a controller or user function that crashes,
// calls exit() or never returns ends its case alone, which is recorded as
// failed with the reason while the other cases run on.
//
// Forked, not `yamsc sim` executed: the child inherits the loaded models (the
// compiled library mapped once, the front end's work done), so a case costs
// a fork (about a millisecond) instead of a process start and a model load
// (10-15 ms per case for the small models). The batch's own process runs no
// thread while children run, so a child never inherits a lock held by another
// thread. A DISCON library keeps global state: in its own process each case
// has its own copy of it, so controllers run side by side.
#include "analysis/batch_jobs.hpp"
#include "analysis/batch_pool.hpp"

#include <functional>
#include <string>
#include <vector>

namespace yamsc::analysis {

/// Runs `run(job, model)` for each of `jobs` in a child process, at most
/// `at_once` at a time, starting no new one once `stop` is set. A child that
/// dies before reporting (a signal, an exit of its own) or exceeds its time
/// limit (the job's time_limit, else `default_limit`; 0: none) is killed and
/// its job failed with the reason, its result and record removed. `finished`
/// is called in this process as each job ends.
void run_isolated(const std::vector<Job*>& jobs, std::size_t at_once, double default_limit,
                  const std::string& dir, const StopOnSignal& stop,
                  const std::function<void(Job&, Loaded&)>& run,
                  const std::function<void(const Job&)>& finished);

/// "SIGSEGV" for SIGSEGV: the name of a signal, as a user reads it in a message.
std::string signal_name(int signal);

} // namespace yamsc::analysis
