// `yamsc batch`: the rows of a manifest run as `yamsc sim` runs them
// (sim_case.hpp), on a pool of threads in one process. Each distinct model
// is loaded once and its compiled library shared by every thread: the
// generated routines keep no state of their own (pure functions of their
// arguments), and each thread binds each case's parameters in its own copy.
#include "analysis/batch_manifest.hpp"
#include "analysis/batch_summary.hpp"
#include "analysis/load_blocks.hpp"
#include "analysis/loaded_model.hpp"
#include "analysis/sim_case.hpp"
#include "diag/diagnostics.hpp"
#include "driver/commands.hpp"
#include "driver/files.hpp"

#include <yamsc/atomic_file.hpp>
#include <yamsc/csv.hpp>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <climits>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <dirent.h>
#include <fstream>
#include <map>
#include <mutex>
#include <ostream>
#include <sched.h>
#include <set>
#include <sstream>
#include <streambuf>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>

namespace yamsc::driver {

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

void make_dirs(const std::string& path) {
    for (std::size_t pos = 1; pos <= path.size(); ++pos)
        if (pos == path.size() || path[pos] == '/')
            if (::mkdir(path.substr(0, pos).c_str(), 0755) != 0 && errno != EEXIST)
                throw diag::UserError("cannot create the folder '" + path.substr(0, pos) + "'");
}

std::string default_output_dir(const std::string& manifest) {
    const bool csv = manifest.size() > 4 && manifest.compare(manifest.size() - 4, 4, ".csv") == 0;
    return (csv ? manifest.substr(0, manifest.size() - 4) : manifest) + ".out";
}

/// A case of this run: its row, what it runs, and how it ended.
struct Job {
    const ManifestRow* row = nullptr;
    std::optional<BatchCase> c;
    const Loaded* model = nullptr;
    std::string digest;
    CaseSummary summary;
    bool done = false; // finished before (its record matches) or failed before running
};

/// The error of a name in --set/--ic/--u that the model does not have, at its place.
void check_names(const BatchCase& c, const Loaded& l) {
    auto check = [](const std::map<std::string, std::string>& given,
                    const std::vector<std::string>& names, const std::string& what, bool rates) {
        for (const auto& [name, where] : given) {
            std::string base = name;
            int primes = 0;
            while (!base.empty() && base.back() == '\'') {
                base.pop_back();
                ++primes;
            }
            if (std::find(names.begin(), names.end(), rates ? base : name) == names.end() ||
                primes > (rates ? 1 : 0))
                throw CaseError(where, "unknown " + what + " '" + name + "'" +
                                           diag::did_you_mean(base, names));
        }
    };
    check(c.set_at, l.library->param_names(), "parameter", false);
    check(c.ic_at, l.library->dof_names(), "DOF", true);
    check(c.u_at, l.library->input_names(), "input", false);
}

/// Runs one case on `l`, this thread's copy of the case's model (the library
/// shared, the parameters rebound here); its result file is complete once
/// renamed into place.
CaseSummary run_case(const Job& job, Loaded& l, const std::string& result_path) {
    const BatchCase& c = *job.c;
    check_names(c, l);
    try {
        bind_parameters(l, c.sim.set);
    } catch (const std::exception& e) {
        throw CaseError(c.row_at, e.what());
    }
    std::ostringstream quiet;
    SimRun run;
    try {
        run = simulate_case(l, c.sim, quiet, quiet);
    } catch (const CaseError&) {
        throw;
    } catch (const std::exception& e) {
        throw CaseError(c.row_at, e.what());
    }
    write_sim_csv(run, Channels::all, result_path);
    CaseSummary s;
    s.ok = true;
    const runtime::SimulationResult& r = run.result;
    if (r.rows() > 0)
        for (std::size_t j = 0; j < r.column_count(); ++j)
            s.final += (j ? "," : "") + r.columns[j] + "=" +
                       runtime::format_csv_value(r.value(r.rows() - 1, j));
    return s;
}

/// Progress on stderr: at most one line a second, and the last.
class Progress {
public:
    Progress(std::ostream& err, std::size_t total, bool quiet)
        : err_(err), total_(total), quiet_(quiet), start_(Clock::now()), last_(start_) {}
    void finished(bool ok) {
        std::lock_guard<std::mutex> lock(mutex_);
        ++done_;
        if (!ok) ++failed_;
        if (quiet_ || (done_ < total_ && since(last_) < 1.0)) return;
        last_ = Clock::now();
        const double elapsed = since(start_);
        const double eta =
            elapsed / static_cast<double>(done_) * static_cast<double>(total_ - done_);
        char line[160];
        std::snprintf(line, sizeof line,
                      "yamsc: batch: %zu/%zu done, %zu failed, %.1f s elapsed, ETA %.0f s\n", done_,
                      total_, failed_, elapsed, eta);
        err_ << line << std::flush;
    }
    std::size_t done() {
        std::lock_guard<std::mutex> lock(mutex_);
        return done_;
    }

private:
    std::ostream& err_;
    std::mutex mutex_;
    std::size_t total_, done_ = 0, failed_ = 0;
    bool quiet_;
    Clock::time_point start_, last_;
};

/// Removes the temporary files a killed run left of the cases about to run
/// (`<id>.csv.tmp.<pid>`, `.records/<id>.tmp.<pid>`); another shard's are
/// not touched, since its cases have other ids.
void remove_leftovers(const std::string& dir, const std::vector<std::string>& ids) {
    const std::set<std::string> pending(ids.begin(), ids.end());
    for (const auto& [folder, suffix] :
         {std::pair<std::string, std::string>{dir, ".csv.tmp."}, {dir + "/.records", ".tmp."}}) {
        DIR* d = ::opendir(folder.c_str());
        if (!d) continue;
        std::vector<std::string> names;
        while (const dirent* e = ::readdir(d)) {
            const std::string name = e->d_name;
            const std::size_t at = name.find(suffix);
            if (at != std::string::npos && pending.count(name.substr(0, at)))
                names.push_back(folder + "/" + name);
        }
        ::closedir(d);
        for (const std::string& n : names) std::remove(n.c_str());
    }
}

std::string read_all(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// The lines of rendered diagnostics that state an error (not the source
/// lines and carets), as one line.
std::string error_lines(const std::string& diagnostics) {
    std::istringstream in(diagnostics);
    std::string out;
    for (std::string line; std::getline(in, line);)
        if (line.find("error: ") != std::string::npos) out += (out.empty() ? "" : " | ") + line;
    return out;
}

/// A stream buffer writing to two others.
class Tee : public std::streambuf {
public:
    Tee(std::streambuf* a, std::streambuf* b) : a_(a), b_(b) {}

protected:
    int overflow(int c) override {
        if (c == traits_type::eof()) return traits_type::not_eof(c);
        a_->sputc(static_cast<char>(c));
        b_->sputc(static_cast<char>(c));
        return c;
    }
    std::streamsize xsputn(const char* s, std::streamsize n) override {
        a_->sputn(s, n);
        return b_->sputn(s, n);
    }
    int sync() override { return a_->pubsync() | b_->pubsync(); }

private:
    std::streambuf *a_, *b_;
};

/// A failed case leaves no result: a file from an earlier run of the row
/// would look like its result.
void forget(const std::string& dir, const std::string& id) {
    std::remove((dir + "/" + id + ".csv").c_str());
    std::remove((dir + "/.records/" + id).c_str());
}

/// The path with links and dots resolved; as given when it does not exist.
std::string real_path(const std::string& path) {
    char buf[PATH_MAX];
    return ::realpath(path.c_str(), buf) ? std::string(buf) : path;
}

/// The input that the result of `id` would replace, or "".
std::string replaced_input(const std::string& real_dir, const std::string& id,
                           const std::set<std::string>& inputs) {
    const std::string result = real_dir + "/" + id + ".csv";
    return inputs.count(result) ? result : "";
}

/// The cores this process may run on (a Slurm task's share, not the machine's).
std::size_t usable_cores() {
    cpu_set_t set;
    if (::sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) > 0)
        return static_cast<std::size_t>(CPU_COUNT(&set));
    return std::max(1u, std::thread::hardware_concurrency());
}

std::string join(const std::vector<std::string>& v) {
    std::string out;
    for (const std::string& s : v) out += (out.empty() ? "" : ",") + s;
    return out;
}

} // namespace

namespace {

volatile std::sig_atomic_t stop_requested = 0;
extern "C" void request_stop(int) {
    stop_requested = 1;
}

/// While alive, SIGINT and SIGTERM ask the batch to stop after the cases in
/// progress (each then has its result and record, or none); a signal the
/// process ignores (a background job's SIGINT) stays ignored.
class StopOnSignal {
public:
    explicit StopOnSignal(bool enabled) : enabled_(enabled) {
        stop_requested = 0;
        if (!enabled_) return;
        for (int i = 0; i < 2; ++i) {
            old_[i] = std::signal(signals_[i], request_stop);
            if (old_[i] == SIG_IGN) std::signal(signals_[i], SIG_IGN);
        }
    }
    ~StopOnSignal() {
        if (enabled_)
            for (int i = 0; i < 2; ++i) std::signal(signals_[i], old_[i]);
    }
    StopOnSignal(const StopOnSignal&) = delete;
    StopOnSignal& operator=(const StopOnSignal&) = delete;
    bool stopped() const { return stop_requested != 0; }

private:
    bool enabled_;
    const int signals_[2] = {SIGINT, SIGTERM};
    void (*old_[2])(int) = {SIG_DFL, SIG_DFL};
};

} // namespace

int batch(const BatchOptions& o, std::ostream& out, std::ostream& err) {
    if (o.shards < 1 || o.shard < 1 || o.shard > o.shards)
        throw UsageError("--shard takes k/N with 1 <= k <= N");
    const Manifest m = read_manifest(o.manifest);
    const std::string dir = o.output_dir.empty() ? default_output_dir(o.manifest) : o.output_dir;
    make_dirs(dir + "/.records");

    // Every row is read (duplicate ids are found across shards alike); this
    // shard runs the rows whose index mod N is k - 1.
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
        if (row.index % o.shards != o.shard - 1) continue;
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

    // A result must not replace an input (the manifest, a model, a wind file).
    const std::string real_dir = real_path(dir);
    std::set<std::string> inputs{real_path(o.manifest)};
    for (const Job& job : jobs)
        if (job.c) {
            inputs.insert(real_path(job.c->sim.model));
            if (!job.c->sim.wind.empty()) inputs.insert(real_path(job.c->sim.wind));
            for (const NamedFile& f : block_files(block_options(job.c->sim)))
                inputs.insert(real_path(f.path));
        }

    // Each distinct model (and set of routines) loaded once: from the JIT cache
    // when compiled before.
    std::map<std::string, std::optional<Loaded>> models;
    std::map<std::string, std::string> model_errors;
    std::map<std::string, std::string> file_digests; // wind files and rotor tables
    for (Job& job : jobs) {
        if (job.done) continue;
        const std::vector<std::string> routines = sim_routines(job.c->sim);
        const std::string key = job.c->sim.model + "\n" + join(routines);
        if (!models.count(key)) {
            // Diagnostics and the compile notice on stderr as they come, and
            // kept for the summary of the rows that use the model.
            std::ostringstream diags;
            Tee tee(err.rdbuf(), diags.rdbuf());
            std::ostream both(&tee);
            try {
                models[key] = load_unbound(job.c->sim.model, "", false, both, {}, routines);
            } catch (const std::exception& e) {
                both << "yamsc: error: " << e.what() << "\n";
                models[key] = std::nullopt;
            }
            both.flush();
            if (!models[key]) {
                model_errors[key] =
                    "the model '" + job.c->sim.model + "' has errors: " + error_lines(diags.str());
            }
        }
        if (!models[key]) {
            job.summary.message = job.c->model_at + ": error: " + model_errors[key];
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
        job.model = &*models[key];
        std::string content = job.c->text + "model-content=" + job.model->digest + "\n";
        for (const std::string& file : job.c->files) {
            auto [it, fresh] = file_digests.emplace(file, "");
            if (fresh) it->second = digest(read_all(file));
            content += "file-content=" + it->second + "\n";
        }
        job.digest = digest(content);
        if (::access((dir + "/" + job.c->id + ".csv").c_str(), R_OK) == 0)
            if (auto rec = read_record(dir + "/.records/" + job.c->id, job.digest)) {
                job.summary.ok = true;
                job.summary.final = rec->final;
                job.summary.wall_s = rec->wall_s;
                job.done = true;
            }
    }

    std::vector<Job*> pending;
    std::size_t reused = 0;
    for (Job& job : jobs) {
        if (!job.done)
            pending.push_back(&job);
        else if (job.summary.ok)
            ++reused;
    }
    std::vector<std::string> ids;
    for (const Job* job : pending) ids.push_back(job->c->id);
    remove_leftovers(dir, ids);
    const std::size_t cores = usable_cores();
    const std::size_t threads = std::max<std::size_t>(
        1, std::min<std::size_t>(o.threads > 0 ? static_cast<std::size_t>(o.threads) : cores,
                                 pending.size()));
    if (!o.quiet)
        err << "yamsc: batch: " << jobs.size() << " cases"
            << (o.shards > 1
                    ? " (shard " + std::to_string(o.shard) + "/" + std::to_string(o.shards) +
                          " of " + std::to_string(m.rows.size()) + " rows)"
                    : std::string())
            << ", " << reused << " done before, " << pending.size() << " to run on " << threads
            << (threads == 1 ? " thread\n" : " threads\n");

    Progress progress(err, pending.size(), o.quiet);
    const StopOnSignal signals(o.stop_on_signal);
    std::atomic<std::size_t> next{0};
    auto worker = [&]() {
        // Each thread's own copy of each model (copied once, not per case).
        std::map<const Loaded*, Loaded> mine;
        for (std::size_t i = next++; i < pending.size() && !signals.stopped(); i = next++) {
            Job& job = *pending[i];
            auto model = mine.find(job.model);
            if (model == mine.end()) model = mine.emplace(job.model, *job.model).first;
            const auto start = Clock::now();
            const std::string result = dir + "/" + job.c->id + ".csv";
            try {
                CaseSummary s = run_case(job, model->second, result);
                s.row = job.summary.row;
                s.id = job.summary.id;
                s.wall_s = since(start);
                // The record last: a case killed before it is run again.
                runtime::write_file_atomically(dir + "/.records/" + job.c->id,
                                               record_text(job.digest, s));
                job.summary = s;
            } catch (const std::exception& e) {
                job.summary.ok = false;
                job.summary.message = e.what();
                job.summary.wall_s = since(start);
                forget(dir, job.c->id);
            }
            progress.finished(job.summary.ok);
        }
    };
    std::vector<std::thread> pool;
    for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
    for (std::thread& t : pool) t.join();
    if (signals.stopped()) {
        // The summary is written by the run that finishes; the results and
        // records written so far are kept for it.
        err << "yamsc: batch interrupted after " << progress.done() << " of " << pending.size()
            << " cases to run; run the same command again to finish\n";
        return 130;
    }

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

} // namespace yamsc::driver
