// The outputs of `yamsc loads`: a text table, CSV and JSON (loads.hpp).
#include "analysis/channels.hpp"
#include "analysis/loads.hpp"
#include "driver/json.hpp"

#include <yamsc/csv.hpp>

#include <algorithm>
#include <cstdio>
#include <ostream>
#include <set>
#include <sstream>

namespace yamsc::analysis {

namespace {

const char* set_name(RunSet s) {
    return s == RunSet::runs ? "runs" : "reference";
}

/// A number as the CSV writer writes it (%.10g, whatever the C locale).
std::string g(double v) {
    return runtime::format_csv_value(v);
}

std::string exponent(double m) {
    char b[32];
    std::snprintf(b, sizeof b, "%g", m);
    return b;
}

/// Every Wöhler exponent of the report, ascending: the DEL columns.
std::vector<double> exponents(const LoadsReport& r) {
    std::set<double> ms;
    for (const RunLoads& run : r.runs)
        for (const ChannelLoads& c : run.channels)
            for (const auto& d : c.dels) ms.insert(d.first);
    return {ms.begin(), ms.end()};
}

std::string del_cells(const std::vector<std::pair<double, double>>& dels,
                      const std::vector<double>& ms) {
    std::string cells;
    for (double m : ms) {
        cells += ",";
        for (const auto& [dm, del] : dels)
            if (dm == m) cells += g(del);
    }
    return cells;
}

} // namespace

std::string loads_text(const LoadsReport& r) {
    std::ostringstream out;
    char line[512];
    const std::vector<double> ms = exponents(r);
    std::size_t width = 7;
    for (const RunLoads& run : r.runs)
        for (const ChannelLoads& c : run.channels) width = std::max(width, c.channel.size());
    const int w = static_cast<int>(width);
    for (const RunLoads& run : r.runs) {
        out << run.path << (run.set == RunSet::reference ? " (reference)" : "")
            << ": t = " << g(run.t_begin) << " .. " << g(run.t_end) << " s";
        if (run.wind_speed) out << ", mean wind speed " << g(*run.wind_speed) << " m/s";
        out << "\n";
        std::snprintf(line, sizeof line, "  %-*s %12s %12s %12s %12s %9s %9s", w, "channel", "mean",
                      "std", "min", "max", "skewness", "kurtosis");
        out << line;
        for (double m : ms) {
            std::snprintf(line, sizeof line, " %12s", ("DEL m=" + exponent(m)).c_str());
            out << line;
        }
        out << "\n";
        for (const ChannelLoads& c : run.channels) {
            const ChannelStatistics& s = c.statistics;
            std::snprintf(line, sizeof line, "  %-*s %12.5g %12.5g %12.5g %12.5g %9.4f %9.4f", w,
                          c.channel.c_str(), s.mean, s.std_dev, s.min, s.max, s.skewness,
                          s.kurtosis);
            out << line;
            for (double m : ms) {
                std::string cell;
                for (const auto& [dm, del] : c.dels)
                    if (dm == m) {
                        std::snprintf(line, sizeof line, "%.5g", del);
                        cell = line;
                    }
                std::snprintf(line, sizeof line, " %12s", cell.c_str());
                out << line;
            }
            out << "\n";
        }
    }
    if (!r.lifetime.empty()) {
        std::snprintf(
            line, sizeof line,
            "lifetime DELs: Weibull A = %.4g m/s, k = %.4g; %g years; %s equivalent cycles\n",
            r.options.weibull->scale, r.options.weibull->shape, r.options.life_years,
            r.options.life_cycles > 0
                ? g(r.options.life_cycles).c_str()
                : ("f_eq T_life = " + g(r.options.frequency) + " Hz x life").c_str());
        out << line;
        for (const LifetimeLoad& l : r.lifetime) {
            std::snprintf(line, sizeof line, "  %-9s %-*s m=%-4s %12.5g\n", set_name(l.set), w,
                          l.channel.c_str(), exponent(l.m).c_str(), l.del);
            out << line;
        }
    }
    out << "(std: population; kurtosis: Pearson's, 3 for a normal distribution; DEL at "
        << g(r.options.frequency) << " Hz, "
        << (r.options.counting == Counting::windap ? "windap" : "ASTM E1049") << " counting, "
        << (r.options.bins > 0 ? std::to_string(r.options.bins) + " range bins"
                               : std::string("no range bins"))
        << "; docs/loads.md)\n";
    return out.str();
}

void write_loads_csv(const LoadsReport& r, std::ostream& out) {
    const std::vector<double> ms = exponents(r);
    out << "set,run,file,wind_speed,t_begin,t_end,channel,mean,std,min,max,skewness,kurtosis";
    for (double m : ms) out << ",DEL_m" << exponent(m);
    out << "\n";
    for (const RunLoads& run : r.runs)
        for (const ChannelLoads& c : run.channels) {
            const ChannelStatistics& s = c.statistics;
            out << set_name(run.set) << "," << csv_field(run.name) << "," << csv_field(run.path)
                << "," << (run.wind_speed ? g(*run.wind_speed) : "") << "," << g(run.t_begin) << ","
                << g(run.t_end) << "," << csv_field(c.channel) << "," << g(s.mean) << ","
                << g(s.std_dev) << "," << g(s.min) << "," << g(s.max) << "," << g(s.skewness) << ","
                << g(s.kurtosis) << del_cells(c.dels, ms) << "\n";
        }
    // Lifetime DELs: one row per set and channel, the statistics left empty.
    std::vector<std::pair<RunSet, std::string>> keys;
    for (const LifetimeLoad& l : r.lifetime)
        if (std::find(keys.begin(), keys.end(), std::make_pair(l.set, l.channel)) == keys.end())
            keys.emplace_back(l.set, l.channel);
    for (const auto& [set, channel] : keys) {
        std::vector<std::pair<double, double>> dels;
        for (const LifetimeLoad& l : r.lifetime)
            if (l.set == set && l.channel == channel) dels.emplace_back(l.m, l.del);
        out << set_name(set) << ",lifetime,,,,," << csv_field(channel) << ",,,,,,"
            << del_cells(dels, ms) << "\n";
    }
}

std::string loads_json(const LoadsReport& r) {
    using driver::json::number;
    using driver::json::quote;
    std::ostringstream out;
    out << "{\n  \"frequency\": " << number(r.options.frequency)
        << ",\n  \"bins\": " << r.options.bins << ",\n  \"counting\": "
        << quote(r.options.counting == Counting::windap ? "windap" : "astm") << ",\n  \"runs\": [";
    for (std::size_t i = 0; i < r.runs.size(); ++i) {
        const RunLoads& run = r.runs[i];
        out << (i ? "," : "") << "\n    {\"set\": " << quote(set_name(run.set))
            << ", \"run\": " << quote(run.name) << ", \"file\": " << quote(run.path)
            << ", \"t_begin\": " << number(run.t_begin) << ", \"t_end\": " << number(run.t_end)
            << ", \"wind_speed\": " << (run.wind_speed ? number(*run.wind_speed) : "null")
            << ", \"channels\": [";
        for (std::size_t j = 0; j < run.channels.size(); ++j) {
            const ChannelLoads& c = run.channels[j];
            const ChannelStatistics& s = c.statistics;
            out << (j ? "," : "") << "\n      {\"channel\": " << quote(c.channel)
                << ", \"mean\": " << number(s.mean) << ", \"std\": " << number(s.std_dev)
                << ", \"min\": " << number(s.min) << ", \"max\": " << number(s.max)
                << ", \"skewness\": " << number(s.skewness)
                << ", \"kurtosis\": " << number(s.kurtosis) << ", \"dels\": [";
            for (std::size_t k = 0; k < c.dels.size(); ++k)
                out << (k ? ", " : "") << "{\"m\": " << number(c.dels[k].first)
                    << ", \"del\": " << number(c.dels[k].second) << "}";
            out << "]}";
        }
        out << "]}";
    }
    out << "\n  ],\n  \"lifetime\": [";
    for (std::size_t i = 0; i < r.lifetime.size(); ++i) {
        const LifetimeLoad& l = r.lifetime[i];
        out << (i ? "," : "") << "\n    {\"set\": " << quote(set_name(l.set))
            << ", \"channel\": " << quote(l.channel) << ", \"m\": " << number(l.m)
            << ", \"del\": " << number(l.del) << "}";
    }
    out << "\n  ]";
    if (r.options.weibull)
        out << ",\n  \"weibull\": {\"A\": " << number(r.options.weibull->scale)
            << ", \"k\": " << number(r.options.weibull->shape)
            << "},\n  \"life_years\": " << number(r.options.life_years);
    out << "\n}\n";
    return out.str();
}

} // namespace yamsc::analysis
