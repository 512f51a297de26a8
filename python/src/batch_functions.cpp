#include "batch_functions.hpp"

#include "analysis/batch_summary.hpp"
#include "analysis/commands.hpp"

#include <pybind11/stl.h>

#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace py = pybind11;

namespace yamsc::python {

namespace {

/// (exit status, stdout, stderr) of the command: 1 when a case failed (its
/// located error is in the summary); a failure of the whole run (a manifest
/// without its columns, a folder that cannot be written) throws, as the CLI
/// exits with its message.
std::tuple<int, std::string, std::string> batch(const std::string& manifest,
                                                const std::string& output_dir, int shard,
                                                int shards, int threads, bool quiet,
                                                double case_time_limit) {
    driver::BatchOptions o;
    o.manifest = manifest;
    o.output_dir = output_dir;
    o.shard = shard;
    o.shards = shards;
    o.threads = threads;
    o.quiet = quiet;
    o.case_time_limit = case_time_limit;
    std::ostringstream out, err;
    py::gil_scoped_release released; // the cases run for seconds to hours
    const int status = analysis::batch(o, out, err);
    return {status, out.str(), err.str()};
}

std::tuple<int, std::string, std::string> batch_merge(const std::vector<std::string>& dirs,
                                                      const std::string& output) {
    driver::BatchMergeOptions o;
    o.dirs = dirs;
    o.output = output;
    std::ostringstream out, err;
    const int status = analysis::batch_merge(o, out, err);
    return {status, out.str(), err.str()};
}

/// The lines of a summary file as dicts of its columns (batch_summary.hpp reads it).
py::list read_batch_summary(const std::string& path) {
    py::list rows;
    for (const analysis::CaseSummary& s : analysis::read_summary(path)) {
        py::dict d;
        d["row"] = s.row;
        d["id"] = s.id;
        d["status"] = s.ok ? "ok" : "error";
        d["final"] = s.final;
        d["message"] = s.message;
        d["wall_s"] = s.wall_s;
        rows.append(d);
    }
    return rows;
}

} // namespace

void add_batch_functions(py::module_& mod) {
    mod.def("batch", &batch, py::arg("manifest"), py::arg("output_dir"), py::arg("shard"),
            py::arg("shards"), py::arg("threads"), py::arg("quiet"),
            py::arg("case_time_limit") = 0.0);
    mod.def("batch_merge", &batch_merge, py::arg("dirs"), py::arg("output"));
    mod.def("read_batch_summary", &read_batch_summary, py::arg("path"));
}

} // namespace yamsc::python
