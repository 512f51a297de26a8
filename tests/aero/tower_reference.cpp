#include "tower_reference.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tower_reference {

using yamsc::table::Table;

std::vector<yamsc::aero::TowerNode> five_mw_tower_table() {
    const double elevation[] = {0,      8.5261, 17.053, 25.579, 34.105, 42.633,
                                51.158, 59.685, 68.211, 76.738, 85.268, 87.6};
    const double diameter[] = {6,     5.787, 5.574, 5.361, 5.148, 4.935,
                               4.722, 4.509, 4.296, 4.083, 3.87,  3.87};
    std::vector<yamsc::aero::TowerNode> table;
    for (int j = 0; j < 12; ++j) table.push_back({elevation[j], diameter[j], 1.0, 0.1});
    return table;
}

namespace {

const std::vector<double>& column(const Table& run, const std::string& name) {
    for (std::size_t c = 0; c < run.columns.size(); ++c)
        if (run.columns[c] == name) return run.data[c];
    throw std::runtime_error("no column " + name);
}

} // namespace

Statistics statistics(const Table& run, const std::string& name, double from, double to) {
    const std::vector<double>& time = run.data.front();
    const std::vector<double>& value = column(run, name);
    double sum = 0, squares = 0;
    int count = 0;
    for (std::size_t i = 0; i < time.size(); ++i)
        if (time[i] >= from && time[i] < to) {
            sum += value[i];
            ++count;
        }
    if (count == 0) throw std::runtime_error("no rows after the start of the window");
    Statistics s;
    s.mean = sum / count;
    for (std::size_t i = 0; i < time.size(); ++i)
        if (time[i] >= from && time[i] < to) squares += (value[i] - s.mean) * (value[i] - s.mean);
    s.deviation = std::sqrt(squares / count);
    return s;
}

std::vector<double> azimuth_profile(const Table& run, const std::string& name, double from,
                                    int bins) {
    const std::vector<double>& time = run.data.front();
    const std::vector<double>& value = column(run, name);
    const std::vector<double>& azimuth = column(run, "Azimuth_[deg]");
    std::vector<double> sum(bins, 0.0), count(bins, 0.0);
    for (std::size_t i = 0; i < time.size(); ++i) {
        if (time[i] < from) continue;
        const double a = std::fmod(std::fmod(azimuth[i], 360.0) + 360.0, 360.0);
        const int b = std::min(bins - 1, static_cast<int>(a / (360.0 / bins)));
        sum[b] += value[i];
        count[b] += 1;
    }
    for (int b = 0; b < bins; ++b) sum[b] = count[b] > 0 ? sum[b] / count[b] : std::nan("");
    return sum;
}

double change_spread(const Table& without, const Table& with, const std::string& column,
                     const std::vector<double>& bounds) {
    auto change = [&](double from, double to) {
        return statistics(with, column, from, to).mean - statistics(without, column, from, to).mean;
    };
    const double whole = change(bounds.front(), bounds.back());
    double spread = 0;
    for (std::size_t i = 0; i + 1 < bounds.size(); ++i)
        spread = std::max(spread, std::abs(change(bounds[i], bounds[i + 1]) - whole));
    return spread;
}

Effect effect(const Table& without, const Table& with, double from) {
    auto change = [&](const char* name) {
        return statistics(with, name, from).mean - statistics(without, name, from).mean;
    };
    Effect e;
    e.thrust_change = change("RotThrust_[kN]");
    e.power_change = change("RtFldPwr_[W]");
    e.tower_base_moment_change = change("TwrBsMyt_[kN-m]");
    e.tower_top_change = change("TTDspFA_[m]");
    e.root_flap_change = change("RootMyc1_[kN-m]");
    e.rotor_wind_change = change("RtVAvgxh_[m/s]");
    e.thrust_deviation_without = statistics(without, "RotThrust_[kN]", from).deviation;
    e.thrust_deviation_with = statistics(with, "RotThrust_[kN]", from).deviation;
    const int bins = 12; // 30 degrees: bin 6 is 180-210
    e.root_flap_dip = azimuth_profile(with, "RootMyc1_[kN-m]", from, bins)[6] -
                      azimuth_profile(without, "RootMyc1_[kN-m]", from, bins)[6];
    return e;
}

Effect effect(const std::string& without_csv, const std::string& with_csv, double from) {
    return effect(yamsc::table::read_table(without_csv), yamsc::table::read_table(with_csv), from);
}

} // namespace tower_reference
