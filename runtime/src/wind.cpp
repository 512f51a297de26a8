#include "yamsc/wind.hpp"

#include "wind/wind_kinds.hpp"

#include "wind/inflowwind_file.hpp"
#include "wind/wind_file.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace yamsc::runtime {
namespace {

bool parse_number(const std::string& text, double& value) {
    std::istringstream s(text);
    s.imbue(std::locale::classic());
    s >> value;
    return !s.fail() && s.eof() && std::isfinite(value);
}

/// Entries every kind reads alike but yamsc does not act on: warned at their line.
void warn_unused(wind::InflowWindFile& f) {
    auto on = [&](const char* key) {
        const wind::InflowWindEntry* e = f.find(key);
        return e && e->values.size() == 1 && f.flag(key) ? e : nullptr;
    };
    if (const auto* e = on("Echo")) f.warn(*e, "Echo: no echo file is written");
    if (const auto* e = on("VelInterpCubic"))
        f.warn(*e, "VelInterpCubic: the wind is interpolated linearly in time");
    if (const auto* e = on("SumPrint")) f.warn(*e, "SumPrint: no summary file is written");
    if (const auto* e = f.find("NWindVel"); e && f.integer("NWindVel") > 0)
        f.warn(*e, "NWindVel: the wind at the WindV*List points is not an output");
    if (const auto* e = f.find("SensorType"); e && f.integer("SensorType") != 0)
        f.warn(*e, "SensorType: no lidar is modelled");
    if (!f.out_list.empty())
        f.warn(f.out_list.front(), "OutList: InflowWind's channels are not outputs");
}

WindInput open_inflowwind(std::istream& in, const std::string& path) {
    wind::InflowWindFile f = wind::read_inflowwind_file(in, path);
    const int type = f.integer("WindType");
    const WindKind* kind = wind_kind(type);
    if (!kind)
        f.fail(f.entry("WindType"), "WindType " + std::to_string(type) +
                                        " is not supported; supported: " + supported_wind_types());
    warn_unused(f);
    WindInput w = kind->open(f);
    w.warnings = std::move(f.warnings);
    return w;
}

/// A wind file of samples: V_wind only; its direction, shear, gust and upflow
/// columns need an InflowWind file's reference height and length.
WindInput open_samples(std::istream& in, const std::string& path) {
    wind::Samples s = wind::read_wind_file(in, path);
    for (const auto* c : {&s.direction, &s.vertical, &s.horizontal_shear, &s.power_law,
                          &s.linear_vertical_shear, &s.gust, &s.upflow})
        if (std::any_of(c->begin(), c->end(), [](double v) { return v != 0; })) {
            throw std::runtime_error(path + ": a uniform wind file with direction, vertical "
                                            "speed, shear, gust or upflow: name it in an "
                                            "InflowWind file (WindType 2, with RefHt_Uni and "
                                            "RefLength) and give --wind that file");
        }
    WindInput w;
    w.hub = {std::move(s.time), std::move(s.speed)};
    return w;
}

} // namespace

double WindSignal::operator()(double t) const {
    if (period > 0) t -= std::floor((t - time.front()) / period) * period;
    if (time.size() == 1 || t <= time.front()) return speed.front();
    if (t >= time.back()) return speed.back();
    const auto it = std::upper_bound(time.begin(), time.end(), t);
    const std::size_t i = static_cast<std::size_t>(it - time.begin()) - 1;
    const double s = (t - time[i]) / (time[i + 1] - time[i]);
    return speed[i] + s * (speed[i + 1] - speed[i]);
}

WindInput open_wind(const std::string& spec) {
    double v = 0;
    if (parse_number(spec, v)) return {{{0.0}, {v}}, nullptr, {}, {}};
    if (spec.rfind("step:", 0) == 0) {
        // step:V0:V1:t=T
        std::vector<std::string> parts;
        std::stringstream s(spec.substr(5));
        for (std::string p; std::getline(s, p, ':');) parts.push_back(p);
        double v0 = 0, v1 = 0, t = 0;
        if (parts.size() != 3 || !parse_number(parts[0], v0) || !parse_number(parts[1], v1) ||
            parts[2].rfind("t=", 0) != 0 || !parse_number(parts[2].substr(2), t))
            throw std::invalid_argument("--wind: expected step:V0:V1:t=T, got '" + spec + "'");
        // A step: V0 up to T, V1 after (the linear interpolation between two
        // samples 1e-9 s apart).
        return {{{t, t + 1e-9}, {v0, v1}}, nullptr, {}, {}};
    }
    std::ifstream in(spec);
    if (!in)
        throw std::runtime_error("--wind: '" + spec +
                                 "' is neither a speed, a step:V0:V1:t=T nor a readable file");
    const bool inflowwind = wind::looks_like_inflowwind(in);
    in.clear();
    in.seekg(0);
    WindInput w = inflowwind ? open_inflowwind(in, spec) : open_samples(in, spec);
    w.files.insert(w.files.begin(), spec);
    return w;
}

WindSignal parse_wind(const std::string& spec) {
    return open_wind(spec).hub;
}

} // namespace yamsc::runtime
