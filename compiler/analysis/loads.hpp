#pragma once
// `yamsc loads`: time series (yamsc's CSV, OpenFAST's .out and .outb) reduced to
// statistics and damage-equivalent loads per channel, and lifetime DELs over runs
// at several wind speeds (docs/loads.md). The numerics are loads_statistics.hpp,
// rainflow.hpp and loads_lifetime.hpp; the outputs loads_report.cpp and
// loads_plot.cpp.
#include "analysis/loads_lifetime.hpp"
#include "analysis/loads_statistics.hpp"
#include "analysis/rainflow.hpp"

#include <iosfwd>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace yamsc::analysis {

/// Which side a run is on when two sets are compared (yamsc's and OpenFAST's).
enum class RunSet { runs, reference };

struct LoadsOptions {
    std::vector<std::string> runs;                   ///< files
    std::vector<std::string> reference;              ///< --reference: files of the other set
    std::string batch_dir;                           ///< --batch: a `yamsc batch` output folder
    std::vector<std::string> channels;               ///< --channels; empty: every channel but time
    std::vector<double> wohler;                      ///< --wohler: exponents for every channel
    std::vector<std::pair<std::string, double>> del; ///< --del NAME:m
    std::optional<double> from, to;                  ///< the window [s], both ends included
    int bins = 100;                                  ///< --bins; 0: no binning
    Counting counting = Counting::astm;              ///< --counting
    double frequency = 1.0;                          ///< --frequency f_eq [Hz]
    std::optional<Weibull> weibull;                  ///< --class or --weibull: lifetime DELs
    double life_years = 20;                          ///< --life
    double life_cycles = 0;                          ///< --life-cycles; 0: f_eq T_life
    std::string wind_channel;                        ///< --wind-channel; empty: Wind1VelX, RtVAvgxh
    std::string speeds;          ///< --speeds: a CSV of id, speed (before the wind channel)
    std::string csv, json, plot; ///< -o, --json, --plot
};

struct ChannelLoads {
    std::string channel; ///< the column's name in its file
    ChannelStatistics statistics;
    std::vector<std::pair<double, double>> dels; ///< (m, DEL)
};

struct RunLoads {
    std::string path, name; ///< name: the file name without folder and extension
    RunSet set = RunSet::runs;
    double t_begin = 0, t_end = 0;
    std::optional<double> wind_speed; ///< [m/s]
    std::vector<ChannelLoads> channels;
};

struct LifetimeLoad {
    RunSet set = RunSet::runs;
    std::string channel; ///< base name
    double m = 0, del = 0;
};

struct LoadsReport {
    std::vector<RunLoads> runs;
    std::vector<LifetimeLoad> lifetime;
    LoadsOptions options; ///< what the runs were reduced with
};

/// The reduction of every run (a located UserError on a bad file or an unknown channel).
LoadsReport reduce_loads(const LoadsOptions& o);

std::string loads_text(const LoadsReport& r);
void write_loads_csv(const LoadsReport& r, std::ostream& out);
std::string loads_json(const LoadsReport& r);
/// Statistics and DELs against wind speed (the runs' mean per speed), the
/// reference dashed beside; throws UserError without two speeds.
std::string loads_svg(const LoadsReport& r);

/// The command: the text table on `out`, the files asked for.
int loads(const LoadsOptions& o, std::ostream& out, std::ostream& err);

} // namespace yamsc::analysis
