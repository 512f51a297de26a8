#pragma once
// The cases of one `yamsc batch` run: the manifest rows of this shard, each
// with its model, and those finished by an earlier run (their result and
// record match the row's content) set apart from those still to run.
#include "analysis/batch_manifest.hpp"
#include "analysis/batch_summary.hpp"
#include "analysis/loaded_model.hpp"

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace yamsc::analysis {

class BatchModels;

/// A case of this run: its row, what it runs, and how it ended.
struct Job {
    const ManifestRow* row = nullptr;
    std::optional<BatchCase> c;
    const Loaded* model = nullptr;
    std::string digest;
    CaseSummary summary;
    bool done = false; // finished before (its record matches) or failed before running
};

/// The jobs of shard `shard` of `shards`: the rows whose index mod N is k - 1.
/// Every row is read, so duplicate ids are found across shards alike; a
/// malformed row is a job done, failed with its located error.
std::vector<Job> shard_jobs(const Manifest& m, int shard, int shards);

/// What no result may replace: the manifest and the models, wind files,
/// rotor tables, controller libraries and their input files of the jobs (real paths).
std::set<std::string> batch_inputs(const std::string& manifest, const std::vector<Job>& jobs);

/// Gives each job its model; fails the jobs whose model has errors or whose
/// result would replace one of `inputs`; marks done the jobs whose result in
/// `dir` and record match the row, its model and the files it reads.
void prepare_jobs(std::vector<Job>& jobs, BatchModels& models, const std::string& dir,
                  const std::set<std::string>& inputs);

/// The jobs not done, in manifest order.
std::vector<Job*> pending_jobs(std::vector<Job>& jobs);

} // namespace yamsc::analysis
