// InflowWind's full-field wind (yamsc/wind/full_field.hpp): the TurbSim `.bts`
// and HAWC box readers on tiny files written here (values chosen so that every
// interpolation is a hand-computable linear function), and the field against
// InflowWind's own driver sampling a TurbSim file (data/reference/turbulence:
// every run its manifest lists).
#include "test_files.hpp"

#include <yamsc/wind.hpp>
#include <yamsc/wind/full_field.hpp>

#include "wind/hawc_box.hpp"
#include "wind/turbsim_bts.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using Eigen::Vector3d;
using yamsc::runtime::FullField;

const std::string turbulence_dir = std::string(YAMSC_TEST_DATA_DIR) + "/reference/turbulence/";

void put(std::string& s, const void* p, std::size_t n) {
    // The tests run on little-endian hosts (x86-64, arm64), as the files are.
    s.append(static_cast<const char*>(p), n);
}
template <class T> void put(std::string& s, T v) {
    put(s, &v, sizeof v);
}

// The tiny grid: 3 (y) x 2 (z) points, 2 tower points, 3 times; stored integer
// 100 it + 10 iz + iy + 1000 c at the grid, 100 it + 50 + k + 1000 c at tower
// point k; u, v, w = (stored - offset) / slope.
constexpr float slope[3] = {100, 200, 400}, offset[3] = {-1000, 0, 50};

std::string tiny_bts(std::int16_t id, int n_tower = 2) {
    std::string s;
    put(s, id);
    for (std::int32_t v : {2, 3, n_tower, 3}) put(s, v); // nz, ny, tower, nt
    for (float v : {10.f, 5.f, 0.5f, 10.f, 25.f, 20.f}) put(s, v);
    for (int c = 0; c < 3; ++c) {
        put(s, slope[c]);
        put(s, offset[c]);
    }
    put(s, std::int32_t(4));
    s += "tiny";
    for (int it = 0; it < 3; ++it) {
        for (int iz = 0; iz < 2; ++iz)
            for (int iy = 0; iy < 3; ++iy)
                for (int c = 0; c < 3; ++c)
                    put(s, std::int16_t(100 * it + 10 * iz + iy + 1000 * c));
        for (int k = 0; k < n_tower; ++k)
            for (int c = 0; c < 3; ++c) put(s, std::int16_t(100 * it + 50 + k + 1000 * c));
    }
    return s;
}

/// The velocity the tiny grid's stored value `stored` (of component c) decodes to.
Vector3d decoded(double stored) {
    return {(stored - offset[0]) / slope[0], (stored + 1000 - offset[1]) / slope[1],
            (stored + 2000 - offset[2]) / slope[2]};
}

std::string scratch() {
    static const std::string dir = test_support::scratch_dir("aero", "full_field");
    return dir;
}

std::string write(const std::string& name, const std::string& bytes) {
    const std::string path = scratch() + "/" + name;
    test_support::write_file(path, bytes);
    return path;
}

/// An InflowWind file of WindType `type` naming `bts` and the HAWC box `box`
/// (its section's entries given).
std::string inflowwind(int type, const std::string& bts, const std::string& hawc,
                       const std::string& direction = "0") {
    return "------- InflowWind v3.01.* INPUT FILE ------\n"
           "test wind\n"
           "-------------------------------------------\n"
           "False         Echo           - Echo\n"
           "          " +
           std::to_string(type) +
           "   WindType       - type\n"
           "          " +
           direction +
           "   PropagationDir - (deg)\n"
           "          0   VFlowAng       - (deg)\n"
           "False         VelInterpCubic - cubic\n"
           "================== TurbSim ====\n"
           "\"" +
           bts + "\"    FileName_BTS   - file\n" + "================== HAWC ====\n" + hawc +
           "====================== OUTPUT ==================================================\n"
           "False         SumPrint     - Print summary data\n"
           "              OutList      - channels\n"
           "END of input file\n";
}

void check_near(const Vector3d& v, const Vector3d& expected, double tol = 1e-5) {
    CAPTURE(v.transpose());
    CAPTURE(expected.transpose());
    CHECK((v - expected).cwiseAbs().maxCoeff() < tol);
}

std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

const FullField& full(const yamsc::runtime::WindInput& w) {
    const auto* f = dynamic_cast<const FullField*>(w.field.get());
    REQUIRE(f);
    return *f;
}

} // namespace

TEST_CASE("full field: the .bts reader decodes the header, the scaling and the tower points") {
    std::istringstream in(tiny_bts(7));
    const yamsc::wind::FullFieldGrid g = yamsc::wind::read_turbsim_bts(in, "tiny.bts");
    CHECK(g.nz == 2);
    CHECK(g.ny == 3);
    CHECK(g.n_tower == 2);
    CHECK(g.nt == 3);
    CHECK(g.dz == 10);
    CHECK(g.dy == 5);
    CHECK(g.dt == 0.5);
    CHECK(g.u_hub == 10);
    CHECK(g.z_hub == 25);
    CHECK(g.z_bottom == 20);
    CHECK(!g.periodic);
    CHECK(g.description == "tiny");
    // Time 1, row 1, column 2: stored 112, 1112, 2112.
    CHECK(g.at(1, 1, 2, 0) == doctest::Approx(11.12));
    CHECK(g.at(1, 1, 2, 1) == doctest::Approx(5.56));
    CHECK(g.at(1, 1, 2, 2) == doctest::Approx(5.155));
    // Time 2, tower point 1: stored 251, 1251, 2251.
    CHECK(g.tower_at(2, 1, 0) == doctest::Approx(12.51));
    CHECK(g.tower_at(2, 1, 2) == doctest::Approx((2251 - 50) / 400.0));
    std::istringstream periodic(tiny_bts(8, 0));
    const auto p = yamsc::wind::read_turbsim_bts(periodic, "p.bts");
    CHECK(p.periodic);
    CHECK(p.tower.empty());
}

TEST_CASE("full field: a short or impossible .bts is an error at its byte") {
    const std::string whole = tiny_bts(7);
    REQUIRE(whole.size() == 74 + 3 * 48);
    auto error = [](const std::string& bytes) {
        return error_of([&] {
            std::istringstream in(bytes);
            yamsc::wind::read_turbsim_bts(in, "t.bts");
        });
    };
    CHECK(error(whole.substr(0, 200)) ==
          "t.bts: byte 200: the file ends in the velocities (144 bytes declared from byte 74, "
          "126 there)");
    CHECK(error(whole.substr(0, 40)) == "t.bts: byte 40: the file ends in the header");
    // A stream that cannot tell its size: the same byte, found by reading.
    struct Unseekable : std::stringbuf {
        using std::stringbuf::stringbuf;
        pos_type seekoff(off_type, std::ios_base::seekdir, std::ios_base::openmode) override {
            return pos_type(off_type(-1));
        }
    } pipe(whole.substr(0, 200));
    std::istream piped(&pipe);
    CHECK(error_of([&] { yamsc::wind::read_turbsim_bts(piped, "t.bts"); }) ==
          "t.bts: byte 200: the file ends in the velocities");
    std::string bad_id = whole;
    bad_id[0] = 3;
    CHECK(error(bad_id).find("t.bts: byte 0: file id 3") == 0);
    std::string negative = whole;
    const std::int32_t minus = -1;
    std::memcpy(&negative[6], &minus, 4);
    CHECK(error(negative) == "t.bts: byte 6: the grid's points in y: -1 (expected 2 to 16777216)");
    // Counts whose product overflows any size: rejected before any allocation.
    std::string huge = whole;
    const std::int32_t nz = 4096, ny = 4095, times = 268435456;
    std::memcpy(&huge[2], &nz, 4);
    std::memcpy(&huge[6], &ny, 4);
    std::memcpy(&huge[14], &times, 4);
    CHECK(error(huge).find("t.bts: byte 66: 268435456 times of 4095 x 4096 points are too many") ==
          0);
    std::string zero_slope = whole;
    const float zero = 0;
    std::memcpy(&zero_slope[50], &zero, 4);
    CHECK(error(zero_slope).find("t.bts: byte 50: the scaling of v") == 0);
}

TEST_CASE("full field: frozen turbulence, linear in y, z and time, tower points below") {
    const std::string bts = write("tiny.bts", tiny_bts(7));
    const auto w = yamsc::runtime::open_wind(write("tiny.dat", inflowwind(3, "tiny.bts", "")));
    const FullField& f = full(w);
    // Not periodic: the grid's first time reaches x = 0 at -(half width) / MeanWS = -0.5 s,
    // so at t = 0.25 s, x = 0 sees grid time 0.75 s (1.5 steps).
    check_near(f.interpolate(0.25, {0, 2.5, 25}), decoded(150 + 5 + 1.5));
    // 2 m upstream: 0.2 s later in the grid.
    check_near(f.interpolate(0.05, {-2, 2.5, 25}), decoded(150 + 5 + 1.5));
    // Below the grid: tower point 0 (at 20 m) and 1 (10 m), y not used; then to zero.
    check_near(f.interpolate(0.0, {0, 3, 15}), decoded(100 + 50 + 0.5));
    check_near(f.interpolate(0.0, {0, 0, 5}), 0.5 * decoded(100 + 50 + 1));
    check_near(f.interpolate(0.0, {0, 0, 0}), Vector3d::Zero());
    // The last half step holds the last time; then InflowWind blends the last two.
    check_near(f.interpolate(0.65, {0, -5, 20}), decoded(200));
    check_near(f.interpolate(0.9, {0, -5, 20}), decoded(180));
    // Within InflowWind's tolerance of the top row.
    check_near(f.interpolate(0.0, {0, -5, 30.005}), decoded(100 + 10));
    // Beyond: errors.
    CHECK(error_of([&] {
              f.interpolate(1.2, {0, 0, 25});
          }).find("the grid's times are exhausted") != std::string::npos);
    CHECK(error_of([&] {
              f.interpolate(-0.6, {0, 0, 25});
          }).find("exhausted") != std::string::npos);
    CHECK(error_of([&] {
              f.interpolate(0.0, {0, 5.1, 25});
          }).find("y' beyond the grid's [-5, 5] m") != std::string::npos);
    CHECK(error_of([&] {
              f.interpolate(0.0, {0, 0, 31});
          }).find("z' above the grid's top (30 m)") != std::string::npos);
    // The reference speed: the horizontal speed at [0, 0, RefHt], u (1 + 1/4)^(1/2).
    const double u = decoded(156).x();
    CHECK(f.reference_speed(0.25) == doctest::Approx(u * std::sqrt(1.25)).epsilon(1e-6));
    CHECK(w.hub(0.25) == doctest::Approx(u * std::sqrt(1.25)).epsilon(1e-6));
    // A replaced reference speed moves the mean profile (the rows' means over
    // their value at RefHt: 11.01, 11.11 about 11.06), not the fluctuations.
    const Vector3d p(0, 2.5, 20);
    const Vector3d moved = f.velocity(0.25, p, f.reference_speed(0.25) + 1);
    check_near(moved - f.interpolate(0.25, p), Vector3d(11.01 / 11.06, 0, 0));
    check_near(f.velocity(0.25, p, f.reference_speed(0.25)), f.interpolate(0.25, p), 1e-12);
}

TEST_CASE("full field: PropagationDir turns the grid about the hub; velocities() is velocity()") {
    write("tiny.bts", tiny_bts(7));
    const auto w =
        yamsc::runtime::open_wind(write("turned.dat", inflowwind(3, "tiny.bts", "", "90")));
    const FullField& f = full(w);
    // Wind towards -y: the ground point (2.5, 0, 25) is (0, 2.5, 25) in the wind's
    // axes; there (u, v, w), in ground axes (v, -u, w).
    const Vector3d in_wind = decoded(150 + 5 + 1.5);
    check_near(f.interpolate(0.25, {2.5, 0, 25}), Vector3d(in_wind.y(), -in_wind.x(), in_wind.z()));
    const Vector3d points[] = {{2.5, 0, 25}, {-1, 3, 22}, {0, 0, 12}};
    Vector3d out[3];
    const double v = f.reference_speed(0.3) + 0.5;
    f.velocities(0.3, points, 3, v, out);
    for (int i = 0; i < 3; ++i) check_near(out[i], f.velocity(0.3, points[i], v), 1e-15);
}

TEST_CASE("full field: a periodic grid wraps and starts at the rotor; no tower is an error") {
    write("periodic.bts", tiny_bts(8, 0));
    const auto w =
        yamsc::runtime::open_wind(write("periodic.dat", inflowwind(3, "periodic.bts", "")));
    const FullField& f = full(w);
    check_near(f.interpolate(0.25, {0, -5, 20}), decoded(50));
    check_near(f.interpolate(1.75, {0, -5, 20}), decoded(50));
    // After the last time, back to the first: half way between times 2 and 0.
    check_near(f.interpolate(1.25, {0, -5, 20}), decoded(100));
    CHECK(w.hub(1.75) == doctest::Approx(w.hub(0.25)));
    CHECK(error_of([&] {
              f.interpolate(0.0, {0, 0, 15});
          }).find("below the grid's bottom (20 m) and the file has no tower points") !=
          std::string::npos);
}

TEST_CASE("full field: a HAWC box, scaled, its mean removed and its profile added") {
    // 4 planes of 3 (y) x 2 (z): u = ix + 10 iy + 100 iz, v = 2 u, w = 3 u; the
    // file's y from +y down.
    for (int c = 0; c < 3; ++c) {
        std::string s;
        for (int ix = 0; ix < 4; ++ix)
            for (int iyf = 0; iyf < 3; ++iyf)
                for (int iz = 0; iz < 2; ++iz)
                    put(s, float((c + 1) * (ix + 10 * (2 - iyf) + 100 * iz)));
        write(std::string("box_") + "uvw"[c] + ".bin", s);
    }
    auto section = [](const std::string& scale) {
        return "\"box_u.bin\"  FileName_u - u\n\"box_v.bin\"  FileName_v - v\n"
               "\"box_w.bin\"  FileName_w - w\n"
               "4 nx - x\n3 ny - y\n2 nz - z\n2 dx - dx\n5 dy - dy\n10 dz - dz\n"
               "25 RefHt_Hawc - ref\n" +
               scale +
               "8 URef - speed\n2 WindProfile - power law\n0.2 PLExp_Hawc - exponent\n"
               "0.03 Z0 - roughness\n0 XOffset - offset\n";
    };
    const auto direct = yamsc::runtime::open_wind(write(
        "hawc1.dat", inflowwind(5, "none.bts",
                                section("1 ScaleMethod - m\n2 SFx - x\n1 SFy - y\n0.5 SFz - z\n"
                                        "1 SigmaFx - x\n1 SigmaFy - y\n1 SigmaFz - z\n"))));
    const FullField& f = full(direct);
    // Periodic from x = 0 at t = 0, dt = dx / URef = 0.25 s: t = 0.125 s is half
    // way between planes 0 and 1; the grid's bottom is 25 - 5 = 20 m.
    // u: 2 (ix - 1.5) after its mean is removed, plus 8 (z / 25)^0.2; v: 2 (ix + 10 iy
    // + 100 iz); w: 0.5 * 3 (...).
    const double mean = 8 * std::pow(22.0 / 25, 0.2);
    check_near(f.interpolate(0.125, {0, 2.5, 22}),
               Vector3d(2 * (0.5 - 1.5) + mean, 2 * (0.5 + 15 + 20), 1.5 * (35.5)));
    // Below the grid: the bottom row, linearly to zero at the ground, and the profile.
    check_near(
        f.interpolate(0.125, {0, 0, 10}),
        Vector3d(0.5 * 2 * (0.5 - 1.5) + 8 * std::pow(0.4, 0.2), 0.5 * 2 * 10.5, 0.5 * 1.5 * 10.5));
    // ScaleMethod 2: u's standard deviation at the centre point (iy 1, iz 0) becomes SigmaFx.
    const auto sigma = yamsc::runtime::open_wind(write(
        "hawc2.dat", inflowwind(5, "none.bts",
                                section("2 ScaleMethod - m\n2 SFx - x\n1 SFy - y\n0.5 SFz - z\n"
                                        "1 SigmaFx - x\n1 SigmaFy - y\n1 SigmaFz - z\n"))));
    double sum2 = 0;
    for (int ix = 0; ix < 4; ++ix) {
        const double u =
            full(sigma).interpolate(ix * 0.25, {0, 0, 20}).x() - 8 * std::pow(0.8, 0.2);
        sum2 += u * u;
    }
    CHECK(std::sqrt(sum2 / 4) == doctest::Approx(1.0).epsilon(1e-6));
    // A short box file: located at its byte.
    write("box_w.bin", std::string(40, '\0'));
    CHECK(error_of([&] {
              yamsc::runtime::open_wind(
                  write("hawc3.dat", inflowwind(5, "none.bts", section("0 ScaleMethod - m\n"))));
          }).find("box_w.bin: byte 40: the file ends in the box (96 bytes declared") !=
          std::string::npos);
}

TEST_CASE("full field: InflowWind's driver in the TurbSim reference file, to 1e-5 m/s") {
    const std::string dir = turbulence_dir + "inflowwind/";
    std::ifstream manifest(dir + "manifest.txt");
    REQUIRE(manifest);
    int runs = 0;
    for (std::string line; std::getline(manifest, line);) {
        std::istringstream fields(line);
        std::string inflow, velocities;
        if (!(fields >> inflow) || inflow[0] == '#') continue;
        REQUIRE(static_cast<bool>(fields >> velocities));
        CAPTURE(inflow);
        const auto w = yamsc::runtime::open_wind(dir + inflow);
        REQUIRE(w.field);
        std::ifstream in(dir + velocities);
        REQUIRE(in);
        int rows = 0;
        double worst = 0;
        for (std::string row; std::getline(in, row);) {
            std::istringstream values(row);
            double t, x, y, z, u, v, wz;
            if (!(values >> t >> x >> y >> z >> u >> v >> wz)) continue;
            const Vector3d p(x, y, z);
            const Vector3d yamsc_v = w.field->velocity(t, p, w.hub(t));
            worst = std::max(worst, (yamsc_v - Vector3d(u, v, wz)).cwiseAbs().maxCoeff());
            ++rows;
        }
        CAPTURE(worst);
        CHECK(rows > 0);
        CHECK(worst < 1e-5);
        ++runs;
    }
    CHECK(runs >= 1);
}
