// InflowWind's WindType 3 (a TurbSim `.bts`) and 5 (a HAWC box): their sections
// of the InflowWind file, checked as InflowWind_ValidateInput and
// Grid3D_ValidateInput check them, the data prepared as IfW_TurbSim_Init and
// IfW_HAWC_Init prepare it.
#include "wind_kinds.hpp"

#include "yamsc/wind/full_field.hpp"

#include "wind/hawc_box.hpp"
#include "wind/turbsim_bts.hpp"

#include <cmath>
#include <fstream>
#include <stdexcept>

namespace yamsc::runtime {

namespace {

constexpr double deg = 3.14159265358979323846 / 180;

double positive(const wind::InflowWindFile& f, const char* key) {
    const double v = f.number(key);
    if (!(v > 0)) f.fail(f.entry(key), std::string(key) + ": must be positive");
    return v;
}

/// The wind's direction and upflow (InflowWind keeps PropagationDir in [-pi, pi]).
void set_axes(const wind::InflowWindFile& f, FullFieldSetup& s) {
    s.propagation_dir = std::remainder(f.number("PropagationDir") * deg, 360 * deg);
    s.vertical_flow_angle = f.number_or("VFlowAng", 0.0) * deg;
}

std::ifstream open_binary(const wind::InflowWindFile& f, const char* key, const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) f.fail(f.entry(key), std::string(key) + ": cannot read '" + path + "'");
    return in;
}

/// The field of `s`, its errors located at `key`'s entry.
WindInput field_input(const wind::InflowWindFile& f, const char* key, FullFieldSetup s) {
    WindInput w;
    try {
        auto field = std::make_shared<FullField>(std::move(s));
        w.hub = field->hub();
        w.field = std::move(field);
    } catch (const std::invalid_argument& e) {
        f.fail(f.entry(key), e.what());
    } catch (const std::runtime_error& e) {
        f.fail(f.entry(key), e.what());
    }
    return w;
}

/// Grid3D_ScaleTurbulence, then (when scaled) the time mean of u removed at
/// every point, as IfW_HAWC_Init does: in single precision where InflowWind is.
void scale_box(const wind::InflowWindFile& f, FullFieldSetup& s) {
    const int method = f.integer("ScaleMethod");
    if (method < 0 || method > 2)
        f.fail(f.entry("ScaleMethod"),
               "ScaleMethod: 0 (none), 1 (scaling factors SFx/y/z) or 2 (standard deviations "
               "SigmaFx/y/z)");
    if (method == 0) return;
    const std::size_t nt = std::size_t(s.nt), points = std::size_t(s.ny) * s.nz;
    auto value = [&](std::size_t it, std::size_t point, int c) -> float& {
        return s.grid[(it * points + point) * 3 + c];
    };
    double factor[3];
    const char* keys[2][3] = {{"SFx", "SFy", "SFz"}, {"SigmaFx", "SigmaFy", "SigmaFz"}};
    for (int c = 0; c < 3; ++c) {
        const char* key = keys[method - 1][c];
        const double given = f.number(key);
        if (given < 0) f.fail(f.entry(key), std::string(key) + ": must not be negative");
        if (method == 1) {
            factor[c] = given;
            continue;
        }
        // The standard deviation at the grid's centre point (the lower middle
        // when a count is even), over the box's planes.
        const std::size_t centre = std::size_t((s.nz + 1) / 2 - 1) * s.ny + (s.ny + 1) / 2 - 1;
        double sum = 0, sum2 = 0;
        for (std::size_t it = 0; it < nt; ++it) {
            const double v = value(it, centre, c);
            sum += v;
            sum2 += v * v;
        }
        const double mean = sum / nt;
        const double sigma = std::sqrt(std::abs(sum2 / nt - mean * mean));
        if (sigma == 0 && given != 0)
            f.fail(f.entry(key),
                   std::string(key) + ": the box's standard deviation at its centre is zero");
        factor[c] = sigma == 0 ? 0 : given / sigma;
    }
    for (std::size_t i = 0; i < s.grid.size(); ++i)
        s.grid[i] = static_cast<float>(factor[i % 3] * s.grid[i]);
    for (std::size_t point = 0; point < points; ++point) {
        float sum = 0;
        for (std::size_t it = 0; it < nt; ++it) sum += value(it, point, 0);
        const double mean = double(sum) / nt;
        for (std::size_t it = 0; it < nt; ++it)
            value(it, point, 0) = static_cast<float>(value(it, point, 0) - mean);
    }
}

} // namespace

WindInput open_turbsim_wind(wind::InflowWindFile& f) {
    const std::string path = f.path("FileName_BTS");
    std::ifstream in = open_binary(f, "FileName_BTS", path);
    wind::FullFieldGrid g = wind::read_turbsim_bts(in, path);
    FullFieldSetup s;
    s.source = path;
    s.ny = g.ny, s.nz = g.nz, s.n_tower = g.n_tower, s.nt = g.nt;
    s.dy = g.dy, s.dz = g.dz, s.dt = g.dt;
    s.mean_speed = g.u_hub;
    s.reference_height = g.z_hub;
    s.z_bottom = g.z_bottom;
    s.periodic = g.periodic;
    // A periodic grid starts at the rotor; another half its width upstream of it.
    s.init_x = g.periodic ? 0.0 : 0.5 * (g.ny - 1) * g.dy;
    s.grid = std::move(g.grid);
    s.tower = std::move(g.tower);
    set_axes(f, s);
    WindInput w = field_input(f, "FileName_BTS", std::move(s));
    w.files.push_back(path);
    return w;
}

WindInput open_hawc_wind(wind::InflowWindFile& f) {
    FullFieldSetup s;
    const int nx = f.integer("nx"), ny = f.integer("ny"), nz = f.integer("nz");
    for (const char* key : {"nx", "ny", "nz"})
        if (f.integer(key) < 2 || f.integer(key) > (1 << 24))
            f.fail(f.entry(key), std::string(key) + ": expected 2 to 16777216 points");
    if (static_cast<long long>(nx) * ny * nz > wind::max_hawc_points)
        f.fail(f.entry("nx"), "nx, ny, nz: a box of more than " +
                                  std::to_string(wind::max_hawc_points) + " points");
    const double dx = positive(f, "dx");
    s.dy = positive(f, "dy");
    s.dz = positive(f, "dz");
    s.reference_height = positive(f, "RefHt_Hawc");
    s.mean_speed = positive(f, "URef");
    const int profile = f.integer("WindProfile");
    if (profile < 0 || profile > 2)
        f.fail(f.entry("WindProfile"),
               "WindProfile: 0 (constant), 1 (logarithmic) or 2 (power law)");
    s.profile = static_cast<MeanProfile>(profile);
    if (s.profile == MeanProfile::power_law) s.power_law = f.number("PLExp_Hawc");
    if (s.profile == MeanProfile::logarithmic) s.roughness = positive(f, "Z0");
    s.init_x = f.number_or("XOffset", 0.0);
    s.ny = ny, s.nz = nz, s.nt = nx;
    s.dt = dx / s.mean_speed;
    s.periodic = true;
    s.to_ground = true;
    s.z_bottom = s.reference_height - 0.5 * s.dz * (nz - 1);
    s.grid.assign(std::size_t(nx) * ny * nz * 3, 0.0f);
    WindInput w;
    const char* keys[] = {"FileName_u", "FileName_v", "FileName_w"};
    for (int c = 0; c < 3; ++c) {
        const std::string path = f.path(keys[c]);
        std::ifstream in = open_binary(f, keys[c], path);
        wind::read_hawc_component(in, path, nx, ny, nz, c, s.grid);
        w.files.push_back(path);
    }
    s.source = w.files.front();
    scale_box(f, s);
    set_axes(f, s);
    WindInput field = field_input(f, "FileName_u", std::move(s));
    field.files = std::move(w.files);
    return field;
}

} // namespace yamsc::runtime
