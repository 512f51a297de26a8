#include "yamsc/wind.hpp"

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

} // namespace

double WindSignal::operator()(double t) const {
    if (time.size() == 1 || t <= time.front()) return speed.front();
    if (t >= time.back()) return speed.back();
    const auto it = std::upper_bound(time.begin(), time.end(), t);
    const std::size_t i = static_cast<std::size_t>(it - time.begin()) - 1;
    const double s = (t - time[i]) / (time[i + 1] - time[i]);
    return speed[i] + s * (speed[i + 1] - speed[i]);
}

WindSignal parse_wind(const std::string& spec) {
    double v = 0;
    if (parse_number(spec, v)) return {{0.0}, {v}};
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
        return {{t, t + 1e-9}, {v0, v1}};
    }
    std::ifstream in(spec);
    if (!in)
        throw std::runtime_error("--wind: '" + spec +
                                 "' is neither a speed, a step:V0:V1:t=T nor a readable file");
    wind::Samples samples = wind::read_wind_file(in, spec);
    return {std::move(samples.time), std::move(samples.speed)};
}

} // namespace yamsc::runtime
