// `yamsc loads`: reading the runs, reducing each, the lifetime DELs (loads.hpp).
#include "analysis/loads.hpp"

#include "analysis/channels.hpp"
#include "analysis/loads_inputs.hpp"
#include "analysis/rainflow.hpp"
#include "diag/errors.hpp"
#include "driver/outputs.hpp"
#include "table/table.hpp"

#include <yamsc/atomic_file.hpp>

#include <algorithm>
#include <filesystem>
#include <map>
#include <ostream>
#include <sstream>

namespace yamsc::analysis {

using diag::UserError;

namespace {

constexpr double seconds_per_year = 365.25 * 24 * 3600;

/// The column of `t` named `name` (exactly, or by base name), or -1.
int find_channel(const table::Table& t, const std::string& name) {
    for (std::size_t j = 1; j < t.columns.size(); ++j)
        if (t.columns[j] == name) return static_cast<int>(j);
    for (std::size_t j = 1; j < t.columns.size(); ++j)
        if (base_name(t.columns[j]) == base_name(name)) return static_cast<int>(j);
    return -1;
}

/// The Wöhler exponents asked for a channel: --del's for it, else --wohler's.
std::vector<double> exponents_of(const LoadsOptions& o, const std::string& column) {
    std::vector<double> ms;
    for (const auto& [name, m] : o.del)
        if (name == column || base_name(name) == base_name(column)) ms.push_back(m);
    return ms.empty() ? o.wohler : ms;
}

struct Window {
    std::size_t first = 0, last = 0; // rows, both included
};

Window window_of(const std::vector<double>& time, const LoadsOptions& o, const std::string& path) {
    Window w{time.size(), 0};
    for (std::size_t i = 0; i < time.size(); ++i) {
        if ((o.from && time[i] < *o.from) || (o.to && time[i] > *o.to)) continue;
        w.first = std::min(w.first, i);
        w.last = i;
    }
    if (w.first >= time.size() || w.last <= w.first)
        throw UserError(path + ": fewer than two samples between --from and --to (the file spans " +
                        std::to_string(time.front()) + " .. " + std::to_string(time.back()) +
                        " s)");
    return w;
}

std::string stem(const std::string& path) {
    return std::filesystem::path(path).stem().string();
}

RunLoads reduce_run(const std::string& path, RunSet set, const LoadsOptions& o,
                    const std::map<std::string, double>& speeds) {
    const table::Table t = table::read_time_series(path);
    RunLoads r;
    r.path = path;
    r.name = stem(path);
    r.set = set;
    const Window w = window_of(t.data[0], o, path);
    r.t_begin = t.data[0][w.first];
    r.t_end = t.data[0][w.last];
    auto rows = [&](std::size_t column) {
        return std::vector<double>(t.data[column].begin() + static_cast<std::ptrdiff_t>(w.first),
                                   t.data[column].begin() + static_cast<std::ptrdiff_t>(w.last) +
                                       1);
    };
    // The run's row in --speeds, else the mean of its wind channel (a reference
    // set named otherwise than the manifest's ids still has its Wind1VelX).
    if (const auto it = speeds.find(r.name); it != speeds.end()) {
        r.wind_speed = it->second;
    } else {
        const std::vector<std::string> candidates =
            o.wind_channel.empty() ? std::vector<std::string>{"Wind1VelX", "RtVAvgxh"}
                                   : std::vector<std::string>{o.wind_channel};
        for (const std::string& c : candidates)
            if (const int j = find_channel(t, c); j > 0 && !r.wind_speed)
                r.wind_speed = channel_statistics(rows(static_cast<std::size_t>(j))).mean;
        if (!o.wind_channel.empty() && !r.wind_speed)
            throw UserError(
                path + ": no channel '" + o.wind_channel + "' (--wind-channel)" +
                (o.speeds.empty() ? "" : " and no row '" + r.name + "' in " + o.speeds));
    }
    std::vector<std::size_t> columns;
    if (o.channels.empty()) {
        for (std::size_t j = 1; j < t.columns.size(); ++j) columns.push_back(j);
    } else {
        for (const std::string& name : o.channels) {
            const int j = find_channel(t, name);
            if (j < 1) throw UserError(path + ": no channel '" + name + "'");
            columns.push_back(static_cast<std::size_t>(j));
        }
    }
    const EquivalentLoadOptions del_options{o.frequency, o.bins};
    const double duration = r.t_end - r.t_begin;
    for (std::size_t j : columns) {
        const std::vector<double> y = rows(j);
        ChannelLoads c;
        c.channel = t.columns[j];
        c.statistics = channel_statistics(y);
        const std::vector<double> ms = exponents_of(o, c.channel);
        if (!ms.empty()) {
            const std::vector<Cycle> cycles =
                o.counting == Counting::windap ? rainflow_windap(y) : rainflow(y);
            for (double m : ms)
                c.dels.emplace_back(m, equivalent_load(cycles, m, duration, del_options));
        }
        r.channels.push_back(std::move(c));
    }
    return r;
}

/// Lifetime DELs of one set: per channel (base name) and exponent, over every run
/// of the set that has it.
void add_lifetime(LoadsReport& report, RunSet set, const Weibull& w, const LoadsOptions& o) {
    std::vector<const RunLoads*> runs;
    std::vector<double> speeds;
    for (const RunLoads& r : report.runs)
        if (r.set == set) {
            if (!r.wind_speed)
                throw UserError(
                    r.path +
                    ": no mean wind speed for the lifetime DELs (no Wind1VelX or "
                    "RtVAvgxh channel, no row in --speeds: give --wind-channel or --speeds)");
            runs.push_back(&r);
            speeds.push_back(*r.wind_speed);
        }
    if (runs.empty()) return;
    const std::vector<double> p = run_probabilities(speeds, w);
    std::map<std::pair<std::string, double>, std::pair<std::vector<double>, std::vector<double>>>
        by_key;
    std::vector<std::pair<std::string, double>> order;
    for (std::size_t i = 0; i < runs.size(); ++i)
        for (const ChannelLoads& c : runs[i]->channels)
            for (const auto& [m, del] : c.dels) {
                const auto key = std::make_pair(base_name(c.channel), m);
                if (!by_key.count(key)) order.push_back(key);
                by_key[key].first.push_back(del);
                by_key[key].second.push_back(p[i]);
            }
    for (const auto& key : order) {
        const auto& [dels, probabilities] = by_key[key];
        report.lifetime.push_back({set, key.first, key.second,
                                   lifetime_equivalent_load(dels, probabilities, key.second,
                                                            o.life_years * seconds_per_year,
                                                            o.frequency, o.life_cycles)});
    }
}

std::vector<driver::NamedFile> named(const std::vector<std::string>& paths,
                                     const std::string& role) {
    std::vector<driver::NamedFile> files;
    for (const std::string& p : paths) files.push_back({role, p});
    return files;
}

} // namespace

LoadsReport reduce_loads(const LoadsOptions& o) {
    LoadsReport report;
    report.options = o;
    const std::map<std::string, double> speeds =
        o.speeds.empty() ? std::map<std::string, double>{} : read_speeds(o.speeds);
    for (const std::string& p : o.runs)
        report.runs.push_back(reduce_run(p, RunSet::runs, o, speeds));
    for (const std::string& p : o.reference)
        report.runs.push_back(reduce_run(p, RunSet::reference, o, speeds));
    if (o.weibull) {
        add_lifetime(report, RunSet::runs, *o.weibull, o);
        add_lifetime(report, RunSet::reference, *o.weibull, o);
    }
    return report;
}

int loads(const LoadsOptions& options, std::ostream& out, std::ostream& err) {
    LoadsOptions o = options;
    std::vector<std::string> inputs = o.runs;
    if (!o.batch_dir.empty()) {
        const BatchRuns b = batch_runs(o.batch_dir);
        for (const std::string& s : b.skipped)
            err << "yamsc loads: skipped the failed case " << s << "\n";
        o.runs.insert(o.runs.end(), b.files.begin(), b.files.end());
        inputs.push_back(b.summary);
        inputs.insert(inputs.end(), b.files.begin(), b.files.end());
    }
    if (o.runs.empty() && o.reference.empty()) throw diag::UsageError("no run given");
    inputs.insert(inputs.end(), o.reference.begin(), o.reference.end());
    if (!o.speeds.empty()) inputs.push_back(o.speeds);
    driver::check_outputs(named(inputs, "a run"),
                          {{"-o", o.csv}, {"--json", o.json}, {"--plot", o.plot}});

    const LoadsReport report = reduce_loads(o);
    // Every output is made before any is written: a failure leaves none half done.
    std::vector<std::pair<std::string, std::string>> files;
    if (!o.csv.empty()) {
        std::ostringstream csv;
        write_loads_csv(report, csv);
        files.emplace_back(o.csv, csv.str());
    }
    if (!o.json.empty()) files.emplace_back(o.json, loads_json(report));
    if (!o.plot.empty()) files.emplace_back(o.plot, loads_svg(report));
    runtime::write_files_atomically(files);
    out << loads_text(report);
    return 0;
}

} // namespace yamsc::analysis
