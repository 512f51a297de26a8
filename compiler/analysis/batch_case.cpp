#include "analysis/batch_case.hpp"

#include "analysis/batch_files.hpp"
#include "analysis/sim_case.hpp"
#include "diag/diagnostics.hpp"

#include <yamsc/atomic_file.hpp>
#include <yamsc/csv.hpp>

#include <algorithm>
#include <chrono>
#include <sstream>

namespace yamsc::analysis {

namespace {

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

/// Simulates the case on `l` and writes its result file (complete once
/// renamed into place): its summary, without row, id and time.
CaseSummary run_case(const BatchCase& c, Loaded& l, const std::string& result_path) {
    check_names(c, l);
    try {
        bind_parameters(l, c.sim.set);
    } catch (const std::exception& e) {
        throw CaseError(c.row_at, e.what());
    }
    std::ostringstream quiet;
    SimRun run;
    // The controller names its own files after the result, as `sim -o` has it.
    driver::SimOptions sim = c.sim;
    sim.output = result_path;
    try {
        run = simulate_case(l, sim, quiet, quiet);
    } catch (const CaseError&) {
        throw;
    } catch (const std::exception& e) {
        throw CaseError(c.row_at, e.what());
    }
    write_sim_csv(run, c.sim.channels, result_path);
    CaseSummary s;
    s.ok = true;
    const runtime::SimulationResult& r = run.result;
    if (r.rows() > 0)
        for (std::size_t j = 0; j < r.column_count(); ++j)
            s.final += (j ? "," : "") + r.columns[j] + "=" +
                       runtime::format_csv_value(r.value(r.rows() - 1, j));
    return s;
}

} // namespace

void run_job(Job& job, Loaded& model, const std::string& dir) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    const auto seconds = [&] {
        return std::chrono::duration<double>(Clock::now() - start).count();
    };
    try {
        CaseSummary s = run_case(*job.c, model, dir + "/" + job.c->id + ".csv");
        s.row = job.summary.row;
        s.id = job.summary.id;
        s.wall_s = seconds();
        // The record last: a case killed before it is run again.
        runtime::write_file_atomically(dir + "/.records/" + job.c->id, record_text(job.digest, s));
        job.summary = s;
    } catch (const std::exception& e) {
        job.summary.ok = false;
        job.summary.message = e.what();
        job.summary.wall_s = seconds();
        forget(dir, job.c->id);
    }
}

} // namespace yamsc::analysis
