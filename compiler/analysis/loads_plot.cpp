// Statistics and DELs against wind speed as SVG (loads.hpp).
#include "analysis/channels.hpp"
#include "analysis/loads.hpp"
#include "analysis/svg_plot.hpp"
#include "diag/errors.hpp"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <map>
#include <optional>
#include <set>

namespace yamsc::analysis {

namespace {

constexpr std::size_t max_channels = 8; // more panels than a page holds are unreadable

using Quantity = std::function<std::optional<double>(const ChannelLoads&)>;

/// One curve of a set: the quantity averaged over the runs (seeds) at each speed.
PlotSeries curve(const LoadsReport& r, RunSet set, const std::string& channel, const Quantity& q) {
    std::map<double, std::pair<double, int>> at; // speed -> (sum, runs)
    for (const RunLoads& run : r.runs)
        if (run.set == set && run.wind_speed)
            for (const ChannelLoads& c : run.channels)
                if (base_name(c.channel) == channel)
                    if (const auto v = q(c)) {
                        at[*run.wind_speed].first += *v;
                        at[*run.wind_speed].second += 1;
                    }
    PlotSeries s;
    s.label = set == RunSet::runs ? "runs" : "reference";
    s.dashed = set == RunSet::reference;
    for (const auto& [speed, sum] : at) {
        s.t.push_back(speed);
        s.y.push_back(sum.first / sum.second);
    }
    return s;
}

} // namespace

std::string loads_svg(const LoadsReport& r) {
    std::set<double> speeds;
    std::vector<std::string> channels; // base names, in the order of the first run
    std::set<double> ms;
    for (const RunLoads& run : r.runs) {
        if (run.wind_speed) speeds.insert(*run.wind_speed);
        for (const ChannelLoads& c : run.channels) {
            const std::string name = base_name(c.channel);
            if (std::find(channels.begin(), channels.end(), name) == channels.end())
                channels.push_back(name);
            for (const auto& d : c.dels) ms.insert(d.first);
        }
    }
    if (speeds.size() < 2)
        throw diag::UserError("--plot draws against the mean wind speed: the runs have " +
                              std::to_string(speeds.size()) +
                              " distinct speed(s), two or more are needed");
    if (channels.size() > max_channels) channels.resize(max_channels);
    std::vector<std::pair<std::string, Quantity>> quantities = {
        {"mean", [](const ChannelLoads& c) { return std::optional<double>(c.statistics.mean); }},
        {"std", [](const ChannelLoads& c) { return std::optional<double>(c.statistics.std_dev); }},
    };
    for (double m : ms) {
        char label[32];
        std::snprintf(label, sizeof label, "DEL m=%g", m);
        quantities.emplace_back(label, [m](const ChannelLoads& c) {
            for (const auto& [dm, del] : c.dels)
                if (dm == m) return std::optional<double>(del);
            return std::optional<double>();
        });
    }
    std::vector<PlotPanel> panels;
    for (const std::string& channel : channels)
        for (const auto& [label, q] : quantities) {
            PlotPanel p{label + " " + channel, {}};
            for (RunSet set : {RunSet::runs, RunSet::reference}) {
                PlotSeries s = curve(r, set, channel, q);
                if (!s.t.empty()) p.series.push_back(std::move(s));
            }
            if (!p.series.empty()) panels.push_back(std::move(p));
        }
    PlotOptions options;
    options.title =
        "statistics and DELs against the mean wind speed (mean over the runs at each speed)";
    options.x_label = "mean wind speed [m/s]";
    options.panel_height = 160;
    return svg_plot(panels, options);
}

} // namespace yamsc::analysis
