#include "analysis/dlc_table.hpp"

#include "diag/errors.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace yamsc::analysis {

namespace {

std::string speed_text(double v) {
    char s[32];
    std::snprintf(s, sizeof s, "U%04.1f", v);
    return s;
}

std::string yaw_text(double yaw) {
    char s[32];
    std::snprintf(s, sizeof s, yaw > 0 ? "y+%g" : "y%g", yaw);
    return s;
}

/// The operating speeds: the centres of the bins of width `bin` from cut-in to
/// cut-out (IEC 61400-1 Ed. 3, 7.4.1: bins of at most 2 m/s), or those given.
std::vector<double> operating_speeds(const DlcOptions& o) {
    if (!o.speeds.empty()) return o.speeds;
    if (!(o.bin > 0) || !(o.cut_out > o.cut_in) || !(o.cut_in >= 0))
        throw diag::UsageError("dlc: the speeds need 0 <= --cut-in < --cut-out and --bin > 0");
    std::vector<double> speeds;
    const int bins = static_cast<int>(std::floor((o.cut_out - o.cut_in) / o.bin + 1e-9));
    for (int i = 0; i < bins; ++i) speeds.push_back(o.cut_in + (i + 0.5) * o.bin);
    if (speeds.empty())
        throw diag::UsageError("dlc: no bin of width --bin fits between --cut-in and --cut-out");
    return speeds;
}

/// The yaw misalignments of each DLC.
std::vector<double> yaws_of(const DlcOptions& o, DesignLoadCase c) {
    switch (c) {
    case DesignLoadCase::dlc6_1:
        return {-o.parked_yaw, o.parked_yaw};
    case DesignLoadCase::dlc6_2: {
        if (!(o.yaw_step > 0) || o.yaw_step > 360)
            throw diag::UsageError("dlc: --yaw-step must be in (0, 360] degrees");
        std::vector<double> yaws;
        for (int i = 0; - 180 + i * o.yaw_step < 180 - 1e-9; ++i)
            yaws.push_back(-180 + i * o.yaw_step);
        return yaws;
    }
    default:
        return o.yaw;
    }
}

} // namespace

std::string dlc_name(DesignLoadCase c) {
    switch (c) {
    case DesignLoadCase::dlc1_1:
        return "1.1";
    case DesignLoadCase::dlc1_2:
        return "1.2";
    case DesignLoadCase::dlc1_3:
        return "1.3";
    case DesignLoadCase::dlc6_1:
        return "6.1";
    case DesignLoadCase::dlc6_2:
        return "6.2";
    }
    return "";
}

std::string wind_model_name(DlcWindModel m) {
    return m == DlcWindModel::ntm ? "NTM" : m == DlcWindModel::etm ? "ETM" : "EWM50";
}

double reference_speed(TurbineClass c) {
    return c == TurbineClass::I ? 50.0 : c == TurbineClass::II ? 42.5 : 37.5;
}

std::string class_name(const DlcOptions& o) {
    const char* roman = o.turbine_class == TurbineClass::I    ? "I"
                        : o.turbine_class == TurbineClass::II ? "II"
                                                              : "III";
    const char* letter = o.turbulence == TurbulenceCategory::A   ? "A"
                         : o.turbulence == TurbulenceCategory::B ? "B"
                                                                 : "C";
    return std::string(roman) + letter;
}

double grid_size(const DlcOptions& o) {
    return o.grid_size > 0 ? o.grid_size : std::ceil(1.15 * o.rotor_diameter);
}

DlcTable dlc_table(const DlcOptions& o) {
    if (!(o.hub_height > 0) || !(o.rotor_diameter > 0))
        throw diag::UsageError("dlc needs --hub-height and --rotor-diameter [m]");
    if (o.seeds < 1 || o.seeds > 100) throw diag::UsageError("dlc: --seeds must be 1 .. 100");
    if (grid_size(o) < o.rotor_diameter)
        throw diag::UsageError("dlc: the wind grid (--grid-size) must cover the rotor");
    if (!(o.hub_height > grid_size(o) / 2))
        throw diag::UsageError("dlc: the wind grid reaches the ground: its size must be less "
                               "than twice the hub height (TurbSim's rule)");
    const std::vector<double> speeds = operating_speeds(o);
    DlcTable t;
    std::map<std::string, std::size_t> wind_index;
    for (DesignLoadCase c : o.cases) {
        const bool parked = c == DesignLoadCase::dlc6_1 || c == DesignLoadCase::dlc6_2;
        const DlcWindModel model = parked                        ? DlcWindModel::ewm50
                                   : c == DesignLoadCase::dlc1_3 ? DlcWindModel::etm
                                                                 : DlcWindModel::ntm;
        // Parked: the 50-year wind's 10-minute mean at the hub, V_ref (IEC (16)).
        const std::vector<double> case_speeds =
            parked ? std::vector<double>{reference_speed(o.turbine_class)} : speeds;
        for (std::size_t si = 0; si < case_speeds.size(); ++si)
            for (int seed = 1; seed <= o.seeds; ++seed) {
                DlcWind w;
                w.model = model;
                w.speed = case_speeds[si];
                w.seed = seed;
                w.name = wind_model_name(model) + "_" + speed_text(w.speed) + "_s" +
                         std::to_string(seed);
                // Distinct for every model, speed and seed (docs/dlc.md).
                w.rand_seed = o.seed_base + 100000 * static_cast<int>(model) +
                              100 * static_cast<std::int64_t>(si) + (seed - 1);
                auto [it, fresh] = wind_index.emplace(w.name, t.winds.size());
                if (fresh) t.winds.push_back(w);
                for (double yaw : yaws_of(o, c)) {
                    DlcCase k;
                    k.dlc = c;
                    k.wind = it->second;
                    k.yaw = yaw;
                    k.parked = parked;
                    k.inflow = w.name + "_" + yaw_text(yaw);
                    k.id = "dlc" + dlc_name(c) + "_" + speed_text(w.speed) + "_s" +
                           std::to_string(seed) + "_" + yaw_text(yaw);
                    t.cases.push_back(k);
                }
            }
    }
    return t;
}

} // namespace yamsc::analysis
