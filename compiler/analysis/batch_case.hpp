#pragma once
// One case of `yamsc batch`, run as `yamsc sim` runs it (sim_case.hpp) and
// kept apart from the others: its errors end in its summary, not the batch.
#include "analysis/batch_jobs.hpp"

#include <string>

namespace yamsc::analysis {

/// Runs `job` on `model`, this thread's copy of the job's model (the library
/// shared, the parameters rebound here), writing `dir/<id>.csv` and then its
/// record; a failed job leaves neither, its located error in its summary.
void run_job(Job& job, Loaded& model, const std::string& dir);

} // namespace yamsc::analysis
