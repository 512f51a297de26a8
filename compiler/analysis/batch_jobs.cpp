#include "analysis/batch_jobs.hpp"
#include "analysis/load_blocks.hpp"

#include "analysis/batch_files.hpp"
#include "analysis/batch_models.hpp"
#include "driver/files.hpp"

#include <map>
#include <unistd.h>

namespace yamsc::analysis {

namespace {

/// What the record of a finished job must match: the row, the model's digest
/// and the content of the files the row reads (`file_digests` caches them).
std::string job_digest(const Job& job, std::map<std::string, std::string>& file_digests) {
    std::string content = job.c->text + "model-content=" + job.model->digest + "\n";
    for (const std::string& file : job.c->files) {
        auto [it, fresh] = file_digests.emplace(file, "");
        if (fresh) it->second = driver::digest(read_all(file));
        content += "file-content=" + it->second + "\n";
    }
    return driver::digest(content);
}

/// Marks `job` done with its earlier summary when its result and a matching record exist.
void reuse_finished(Job& job, const std::string& dir) {
    if (::access((dir + "/" + job.c->id + ".csv").c_str(), R_OK) != 0) return;
    if (auto rec = read_record(dir + "/.records/" + job.c->id, job.digest)) {
        job.summary.ok = true;
        job.summary.final = rec->final;
        job.summary.wall_s = rec->wall_s;
        job.done = true;
    }
}

} // namespace

std::vector<Job> shard_jobs(const Manifest& m, int shard, int shards) {
    std::vector<Job> jobs;
    std::map<std::string, std::string> first_row_of_id;
    for (const ManifestRow& row : m.rows) {
        std::optional<BatchCase> c;
        std::string error;
        try {
            c = case_of(m, row);
            const ManifestField* id = m.field(row, "id");
            auto [it, fresh] = first_row_of_id.emplace(c->id, m.where(row.line, 1));
            if (!fresh)
                throw CaseError(m.where(id->line, id->col),
                                "the id '" + c->id + "' is already used at " + it->second);
        } catch (const std::exception& e) {
            error = e.what();
        }
        if (row.index % shards != shard - 1) continue;
        Job job;
        job.row = &row;
        job.summary.row = row.index + 1;
        const ManifestField* id = m.field(row, "id");
        job.summary.id = id ? id->text : "";
        if (error.empty()) {
            job.c = std::move(c);
        } else {
            job.summary.message = error;
            job.done = true;
        }
        jobs.push_back(std::move(job));
    }
    return jobs;
}

std::set<std::string> batch_inputs(const std::string& manifest, const std::vector<Job>& jobs) {
    std::set<std::string> inputs{real_path(manifest)};
    for (const Job& job : jobs)
        if (job.c) {
            inputs.insert(real_path(job.c->sim.model));
            if (!job.c->sim.wind.empty()) inputs.insert(real_path(job.c->sim.wind));
            for (const std::string& file : job.c->files) inputs.insert(real_path(file));
            for (const driver::NamedFile& f : block_files(block_options(job.c->sim)))
                inputs.insert(real_path(f.path));
        }
    return inputs;
}

void prepare_jobs(std::vector<Job>& jobs, BatchModels& models, const std::string& dir,
                  const std::set<std::string>& inputs) {
    const std::string real_dir = real_path(dir);
    std::map<std::string, std::string> file_digests; // wind files and rotor tables
    for (Job& job : jobs) {
        if (job.done) continue;
        std::string error;
        const Loaded* model = models.model_of(job.c->sim, error);
        if (!model) {
            job.summary.message = job.c->model_at + ": error: " + error;
            job.done = true;
            forget(dir, job.c->id);
            continue;
        }
        if (const std::string input = replaced_input(real_dir, job.c->id, inputs); !input.empty()) {
            job.summary.message = job.c->row_at + ": error: the result " + dir + "/" + job.c->id +
                                  ".csv would replace " + input + ", an input of the batch";
            job.done = true;
            continue;
        }
        job.model = model;
        job.digest = job_digest(job, file_digests);
        reuse_finished(job, dir);
    }
}

std::vector<Job*> pending_jobs(std::vector<Job>& jobs) {
    std::vector<Job*> pending;
    for (Job& job : jobs)
        if (!job.done) pending.push_back(&job);
    return pending;
}

} // namespace yamsc::analysis
