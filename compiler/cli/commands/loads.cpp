// `yamsc loads`: statistics and damage-equivalent loads of time series.
#include "analysis/loads.hpp"
#include "cli/commands/commands.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <glob.h>

namespace yamsc::cli {

namespace {

using analysis::LoadsOptions;

bool is_series(const std::filesystem::path& p) {
    const std::string e = p.extension().string();
    return e == ".csv" || e == ".out" || e == ".outb";
}

/// A --runs or --reference list: files, folders (their .csv, .out and .outb
/// files) and patterns (`openfast/*.outb`, for a shell that would not expand them
/// after an option), in order, each folder's and pattern's files sorted.
std::vector<std::string> expand(const std::string& option, const std::string& list) {
    std::vector<std::string> files;
    for (const std::string& item : comma_list(list)) {
        std::vector<std::string> found;
        if (item.find_first_of("*?[") != std::string::npos) {
            glob_t g{};
            if (::glob(item.c_str(), 0, nullptr, &g) == 0)
                for (std::size_t i = 0; i < g.gl_pathc; ++i) found.emplace_back(g.gl_pathv[i]);
            ::globfree(&g);
            if (found.empty()) throw UsageError(option + ": no file matches '" + item + "'");
        } else if (std::filesystem::is_directory(item)) {
            for (const auto& e : std::filesystem::directory_iterator(item))
                if (e.is_regular_file() && is_series(e.path())) found.push_back(e.path().string());
            if (found.empty())
                throw UsageError(option + ": no .csv, .out or .outb file in '" + item + "'");
        } else {
            found.push_back(item);
        }
        std::sort(found.begin(), found.end());
        files.insert(files.end(), found.begin(), found.end());
    }
    return files;
}

std::vector<double> exponents(const std::string& option, const std::vector<std::string>& items) {
    std::vector<double> ms;
    for (const std::string& s : items) {
        const double m = driver::parse_value(s, option);
        if (!(m > 0) || !std::isfinite(m))
            throw UsageError(option + ": a Wöhler exponent must be > 0, not '" + s + "'");
        ms.push_back(m);
    }
    return ms;
}

analysis::Weibull weibull_of(const Args& a) {
    if (a.has("--class") && a.has("--weibull"))
        throw UsageError("--class and --weibull exclude each other");
    if (a.has("--class"))
        return analysis::iec_weibull(choice(a, "--class", analysis::WindClass::I,
                                            {{"I", analysis::WindClass::I},
                                             {"II", analysis::WindClass::II},
                                             {"III", analysis::WindClass::III}}));
    const auto parts = comma_list(a.get("--weibull"));
    if (parts.size() != 2)
        throw UsageError("--weibull takes A,k (scale [m/s] and shape), not '" + a.get("--weibull") +
                         "'");
    analysis::Weibull w{driver::parse_value(parts[0], "--weibull"),
                        driver::parse_value(parts[1], "--weibull")};
    if (!(w.scale > 0) || !(w.shape > 0) || !std::isfinite(w.scale) || !std::isfinite(w.shape))
        throw UsageError("--weibull: A and k must be > 0");
    return w;
}

LoadsOptions parse_loads(const Args& a) {
    LoadsOptions o;
    o.runs = a.positionals();
    if (a.has("--runs")) {
        const auto more = expand("--runs", a.get("--runs"));
        o.runs.insert(o.runs.end(), more.begin(), more.end());
    }
    if (a.has("--reference")) o.reference = expand("--reference", a.get("--reference"));
    o.batch_dir = a.get("--batch");
    if (o.runs.empty() && o.reference.empty() && o.batch_dir.empty())
        throw UsageError("no run given (files, --runs, or --batch DIR)");
    o.channels = comma_list(a.get("--channels"));
    if (a.has("--wohler")) o.wohler = exponents("--wohler", comma_list(a.get("--wohler")));
    for (const std::string& item : comma_list(a.get("--del"))) {
        const auto colon = item.rfind(':');
        if (colon == std::string::npos || colon == 0)
            throw UsageError("--del takes NAME:m,... (e.g. TwrBsMyt:4,RootMyc1:10), not '" + item +
                             "'");
        o.del.emplace_back(item.substr(0, colon),
                           exponents("--del", {item.substr(colon + 1)}).front());
    }
    if (!a.has("--wohler") && !a.has("--del")) o.wohler = {4, 10};
    if (a.has("--from")) o.from = a.number("--from", 0);
    if (a.has("--to")) o.to = a.number("--to", 0);
    if (o.from && o.to && !(*o.to > *o.from)) throw UsageError("--to must be later than --from");
    const double bins = a.number("--bins", 100);
    if (bins != std::floor(bins) || bins < 0 || bins > 1e6)
        throw UsageError("--bins must be a whole number >= 0");
    o.bins = static_cast<int>(bins);
    o.counting =
        choice(a, "--counting", analysis::Counting::astm,
               {{"astm", analysis::Counting::astm}, {"windap", analysis::Counting::windap}});
    o.frequency = a.number("--frequency", 1.0);
    if (!(o.frequency > 0) || !std::isfinite(o.frequency))
        throw UsageError("--frequency must be > 0");
    if (a.has("--class") || a.has("--weibull")) o.weibull = weibull_of(a);
    o.life_years = a.number("--life", 20);
    if (!(o.life_years > 0) || !std::isfinite(o.life_years))
        throw UsageError("--life must be > 0 years");
    o.life_cycles = a.number("--life-cycles", 0);
    if (!(o.life_cycles >= 0) || !std::isfinite(o.life_cycles))
        throw UsageError("--life-cycles must be > 0");
    if ((a.has("--life") || a.has("--life-cycles")) && !o.weibull)
        throw UsageError("--life and --life-cycles need --class or --weibull (the lifetime DELs)");
    o.wind_channel = a.get("--wind-channel");
    o.speeds = a.get("--speeds");
    o.csv = a.get("-o");
    o.json = a.get("--json");
    o.plot = a.get("--plot");
    return o;
}

} // namespace

Command loads_command() {
    return make_command(
        "loads", "statistics, rainflow counts and damage-equivalent loads of time series",
        "yamsc loads RUN.csv|RUN.out|RUN.outb... [--runs LIST] [--reference LIST] [--batch DIR]\n"
        "             [--channels NAMES] [--wohler M,...] [--del NAME:M,...] [--from T] [--to T]\n"
        "             [--bins N] [--frequency F] [--counting astm|windap] [--class I|II|III | "
        "--weibull A,k] [--life "
        "YEARS]\n"
        "             [--life-cycles N] [--wind-channel NAME] [--speeds FILE] [-o OUT.csv]\n"
        "             [--json OUT.json] [--plot OUT.svg]",
        R"(  RUN...              time series: yamsc's CSV, OpenFAST's .out or binary .outb (docs/loads.md)
  --runs LIST         more runs: files, folders (their .csv/.out/.outb) or quoted patterns,
                      comma-separated or as separate arguments up to the next option
  --reference LIST    a second set compared with the runs (OpenFAST's beside yamsc's), as --runs
  --batch DIR         the cases a `yamsc batch` finished in DIR (its summary.csv and <id>.csv)
  --channels NAMES    channels, comma-separated, by name or name without unit (default: all)
  --wohler M,...      Wöhler exponents of every channel's DELs (default: 4,10)
  --del NAME:M,...    DELs of these channels at these exponents (others take --wohler's, if given)
  --from T, --to T    the window [s], both ends included (e.g. --from 60: no start-up transient)
  --bins N            rainflow ranges in N bins, each at its mean range (default 100, as
                      openfast_toolbox; 0: every range as counted)
  --frequency F       the DELs' equivalent frequency [Hz] (default 1)
  --counting astm|windap  ASTM E1049 rainflow counting (default), or openfast_toolbox's default
                      `rainflow_windap` (the signal rounded to 255 levels first) to compare with it
  --class I|II|III    lifetime DELs, the speeds Rayleigh-distributed with mean 0.2 V_ref (IEC 61400-1)
  --weibull A,k       lifetime DELs with this Weibull distribution of the mean speed
  --life YEARS        the life of the lifetime DELs (default 20)
  --life-cycles N     the lifetime DELs' equivalent cycles (default: F x the life in seconds)
  --wind-channel NAME the channel whose mean is a run's wind speed (default: Wind1VelX, else RtVAvgxh)
  --speeds FILE       each run's wind speed from a CSV with columns id and speed (or wind: a
                      batch manifest), id = the run's file name without extension; a run
                      without a row takes its wind channel's mean
  -o OUT.csv          the table as CSV: one row per run and channel, lifetime rows last
  --json OUT.json     the same as JSON
  --plot OUT.svg      statistics and DELs against the mean wind speed, the reference dashed
)",
        {{"--runs",         "--reference", "--batch",   "--channels", "--wohler",
          "--del",          "--from",      "--to",      "--bins",     "--frequency",
          "--counting",     "--class",     "--weibull", "--life",     "--life-cycles",
          "--wind-channel", "--speeds",    "-o",        "--json",     "--plot"},
         {},
         {"--runs", "--reference"}},
        parse_loads, analysis::loads);
}

} // namespace yamsc::cli
