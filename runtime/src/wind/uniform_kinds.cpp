// InflowWind's WindType 1 (steady) and 2 (uniform wind file): their sections of
// the InflowWind file, checked as InflowWind_ValidateInput checks them.
#include "wind_kinds.hpp"

#include "yamsc/wind/uniform_field.hpp"

#include "wind/wind_file.hpp"

#include <cmath>
#include <fstream>

namespace yamsc::runtime {

namespace {

constexpr double deg = 3.14159265358979323846 / 180;

double positive(const wind::InflowWindFile& f, const char* key, const char* what) {
    const double v = f.number(key);
    if (!(v > 0)) f.fail(f.entry(key), std::string(key) + ": " + what + " must be positive");
    return v;
}

/// The entries common to every kind: the wind's direction and upflow.
void set_axes(const wind::InflowWindFile& f, UniformWindSetup& s) {
    s.propagation_dir = f.number("PropagationDir") * deg;
    s.vertical_flow_angle = f.number_or("VFlowAng", 0.0) * deg;
}

WindInput uniform_input(UniformWindSetup setup) {
    WindInput w;
    const UniformWindSamples& s = setup.samples;
    w.hub.time = s.time;
    for (std::size_t i = 0; i < s.time.size(); ++i) w.hub.speed.push_back(s.speed[i] + s.gust[i]);
    w.field = std::make_shared<UniformField>(std::move(setup));
    return w;
}

} // namespace

WindInput open_steady_wind(wind::InflowWindFile& f) {
    UniformWindSetup s;
    const double speed = positive(f, "HWindSpeed", "the horizontal wind speed");
    s.reference_height = positive(f, "RefHt", "the reference height");
    const double exponent = f.number("PLexp");
    if (exponent < 0)
        f.fail(f.entry("PLexp"), "PLexp: the power-law exponent must not be negative");
    s.samples = steady_wind(speed, exponent);
    set_axes(f, s);
    return uniform_input(std::move(s));
}

WindInput open_uniform_wind(wind::InflowWindFile& f) {
    UniformWindSetup s;
    const std::string path = f.path("FileName_Uni");
    s.reference_height = positive(f, "RefHt_Uni", "the reference height");
    s.reference_length = positive(f, "RefLength", "the reference length");
    set_axes(f, s);
    std::ifstream in(path);
    if (!in) f.fail(f.entry("FileName_Uni"), "cannot read the uniform wind file '" + path + "'");
    const wind::Samples w = wind::read_wind_file(in, path);
    UniformWindSamples& u = s.samples;
    u.time = w.time;
    u.speed = w.speed;
    u.vertical = w.vertical;
    u.horizontal_shear = w.horizontal_shear;
    u.power_law = w.power_law;
    u.linear_vertical_shear = w.linear_vertical_shear;
    u.gust = w.gust;
    for (double d : w.direction) u.direction.push_back(d * deg);
    for (double a : w.upflow) u.upflow.push_back(a * deg);
    if (u.direction.front() != 0 && s.propagation_dir != 0)
        f.warn(f.entry("PropagationDir"),
               "PropagationDir and the uniform wind file's first direction both turn the wind "
               "(InflowWind warns of a double rotation too)");
    WindInput input = uniform_input(std::move(s));
    input.files.push_back(path);
    return input;
}

} // namespace yamsc::runtime
