// `yamsc view` on a run in the layout `sim --vtk` writes (formats/vtk): a double
// pendulum moved by closed forms, written with the scene's own writer. The page
// must hold the kept frames' points exactly as float32, the channels chosen, and
// refuse what it must. Its page is what tests/view/browser_test.mjs opens.
#include "analysis/view_page.hpp"
#include "test_files.hpp"
#include "vtk/scene.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace yamsc;
using test_support::read_file;
using test_support::write_file;

namespace {

constexpr double pi = 3.14159265358979323846;

// The pendulum at time t: pivot, elbow, tip, then a thin plate along each link.
std::vector<double> pendulum_points(double t) {
    const double a = 0.8 * std::cos(pi * t), b = a + 0.6 * std::sin(2 * pi * t);
    const double x1 = std::sin(a), z1 = -std::cos(a), x2 = x1 + 0.8 * std::sin(b),
                 z2 = z1 - 0.8 * std::cos(b), w = 0.05;
    return {0,  0,  0,  x1, 0, z1, x2, 0, z2,              // pivot, elbow, tip
            0,  -w, 0,  0,  w, 0,  x1, w, z1, x1, -w, z1,  // plate of link 1
            x1, -w, z1, x1, w, z1, x2, w, z2, x2, -w, z2}; // plate of link 2
}

vtk::Topology pendulum_topology() {
    vtk::Topology t;
    t.part_names = {"link1", "link2"};
    t.points = 11;
    t.verts = {{2}, {1}, {1}, {vtk::CellKind::point_marker}};
    t.lines = {{0, 1, 1, 2}, {2, 4}, {0, 1}, {vtk::CellKind::line, vtk::CellKind::line}};
    t.polys = {{3, 4, 5, 6, 7, 8, 9, 10}, {4, 8}, {0, 1}, {vtk::CellKind::box, vtk::CellKind::box}};
    return t;
}

// A run of 4 s every 0.01 s: 401 steps, the CSV with two angles and a constant.
std::string write_pendulum_run(const std::string& dir) {
    const vtk::Topology topology = pendulum_topology();
    std::vector<vtk::Entry> entries;
    std::string csv = "t,theta1,theta2,length\n";
    for (int row = 0; row <= 400; ++row) {
        const double t = row * 0.01;
        write_file(dir + "/" + vtk::vtp_name("pendulum", row),
                   vtk::write_vtp(topology, pendulum_points(t)));
        entries.push_back({t, vtk::vtp_name("pendulum", row)});
        char line[128];
        std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g,1\n", t, 0.8 * std::cos(pi * t),
                      0.6 * std::sin(2 * pi * t));
        csv += line;
    }
    write_file(dir + "/" + vtk::pvd_name("pendulum"), vtk::write_pvd(entries));
    write_file(dir + "/" + vtk::csv_name("pendulum"), csv);
    return dir;
}

std::vector<unsigned char> from_base64(const std::string& s) {
    std::vector<unsigned char> out;
    unsigned v = 0;
    int bits = 0;
    for (const char c : s) {
        const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
        const char* at = std::strchr(alphabet, c);
        if (c == '=' || !at) break;
        v = (v << 6) | static_cast<unsigned>(at - alphabet);
        if ((bits += 6) >= 8) out.push_back(static_cast<unsigned char>(v >> (bits -= 8)));
    }
    return out;
}

// The base64 text of the JSON field `key` (its first occurrence after `from`).
std::string field(const std::string& html, const std::string& key, std::size_t from = 0) {
    const auto at = html.find("\"" + key + "\":\"", from);
    REQUIRE(at != std::string::npos);
    const auto begin = at + key.size() + 4;
    return html.substr(begin, html.find('"', begin) - begin);
}

template <class T> std::vector<T> decoded(const std::string& b64) {
    const std::vector<unsigned char> bytes = from_base64(b64);
    REQUIRE(bytes.size() % sizeof(T) == 0);
    std::vector<T> v(bytes.size() / sizeof(T));
    std::memcpy(v.data(), bytes.data(), bytes.size());
    return v;
}

struct Result {
    int status;
    std::string output;
};

Result run_yamsc(const std::string& args, const std::string& dir) {
    const std::string log = dir + "/yamsc.log";
    const int status =
        test_support::exit_status(std::string(YAMSC_EXE) + " " + args + " > " + log + " 2>&1");
    return {status, read_file(log)};
}

} // namespace

TEST_CASE("base64 is RFC 4648's") {
    CHECK(analysis::base64("", 0).empty());
    CHECK(analysis::base64("f", 1) == "Zg==");
    CHECK(analysis::base64("fo", 2) == "Zm8=");
    CHECK(analysis::base64("foo", 3) == "Zm9v");
    CHECK(analysis::base64("foobar", 6) == "Zm9vYmFy");
    const unsigned char high[] = {0xff, 0xfe, 0x80};
    CHECK(analysis::base64(high, 3) == "//6A");
}

TEST_CASE("no name in the data can close its <script> element") {
    analysis::ViewPage page;
    page.title = "</script><b>";
    page.scene.part_names = {"a</script>"};
    page.channels.push_back({"x<y", "m&s", {}});
    const std::string data = analysis::view_page_data(page);
    CHECK(data.find('<') == std::string::npos);
    CHECK(data.find("\\u003c/script\\u003e") != std::string::npos);
    CHECK_THROWS_AS(
        [] {
            analysis::ViewPage bad;
            bad.scene.point_count = 2;
            bad.scene.times = {0};
            return analysis::view_page_data(bad);
        }(),
        std::invalid_argument);
}

TEST_CASE("yamsc view: the page holds the run's kept frames exactly, and its channels") {
    if (!analysis::view_page_available()) {
        MESSAGE("skipped: this yamsc was built without the page (no node and npm at build time)");
        return;
    }
    const std::string dir = write_pendulum_run(test_support::scratch_dir("view", "pendulum"));
    const Result r = run_yamsc("view " + dir + " --fps 25 --title 'Double pendulum'", dir);
    REQUIRE_MESSAGE(r.status == 0, r.output);
    CHECK(r.output.find("101 of 401 steps, 11 points") != std::string::npos);
    CHECK(r.output.find("2 channels: theta1, theta2") != std::string::npos);
    const std::string html = read_file(dir + "/pendulum.html");
    CHECK(html.find("<title>Double pendulum</title>") != std::string::npos);
    CHECK(html.find("Three.js Authors") != std::string::npos); // three.js's licence notice

    // Every 0.04 s (25 per second), the first and last steps included.
    const auto times = decoded<double>(field(html, "times"));
    REQUIRE(times.size() == 101);
    const auto positions = decoded<float>(field(html, "positions"));
    REQUIRE(positions.size() == 101 * 11 * 3);
    for (std::size_t f = 0; f < times.size(); ++f) {
        CHECK(times[f] == 4 * static_cast<int>(f) * 0.01);
        const std::vector<double> p = pendulum_points(times[f]);
        for (std::size_t i = 0; i < p.size(); ++i)
            REQUIRE(positions[f * 33 + i] == static_cast<float>(p[i]));
    }
    const auto connectivity = decoded<std::int32_t>(field(html, "connectivity"));
    CHECK(connectivity == std::vector<std::int32_t>{2, 0, 1, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
    const auto offsets = decoded<std::int32_t>(field(html, "offsets"));
    CHECK(offsets == std::vector<std::int32_t>{1, 3, 5, 9, 13});
    const auto type = decoded<std::uint8_t>(field(html, "type"));
    CHECK(type == std::vector<std::uint8_t>{0, 1, 1, 2, 2});

    // The channels at every row of the CSV, in float32.
    const auto series_at = html.find("\"series\"");
    const auto channel_times = decoded<double>(field(html, "times", html.find("\"channels\"")));
    REQUIRE(channel_times.size() == 401);
    const auto theta2 = decoded<float>(field(html, "values", html.find("theta2", series_at)));
    REQUIRE(theta2.size() == 401);
    for (std::size_t i = 0; i < 401; i += 37)
        CHECK(theta2[i] == static_cast<float>(0.6 * std::sin(2 * pi * channel_times[i])));

    // --channels chooses, a name not in the CSV is located and suggested.
    const Result chosen = run_yamsc(
        "view " + dir + "/pendulum.pvd -o " + dir + "/chosen.html --channels length", dir);
    REQUIRE_MESSAGE(chosen.status == 0, chosen.output);
    CHECK(chosen.output.find("1 channels: length") != std::string::npos);
    const Result unknown =
        run_yamsc("view " + dir + " -o " + dir + "/x.html --channels theta_1", dir);
    CHECK(unknown.status == 1);
    CHECK(
        unknown.output.find(dir + "/pendulum.csv: no channel 'theta_1' (did you mean 'theta1'?)") !=
        std::string::npos);
}

TEST_CASE("yamsc view refuses to write over the run, and locates a broken step") {
    if (!analysis::view_page_available()) return;
    const std::string dir = write_pendulum_run(test_support::scratch_dir("view", "refusals"));
    const std::string pvd = read_file(dir + "/pendulum.pvd");
    const Result over_pvd = run_yamsc("view " + dir + " -o " + dir + "/pendulum.pvd", dir);
    CHECK(over_pvd.status == 2);
    CHECK(read_file(dir + "/pendulum.pvd") == pvd);
    const Result over_csv = run_yamsc("view " + dir + " -o " + dir + "/pendulum.csv", dir);
    CHECK(over_csv.status == 2);
    const Result no_run = run_yamsc("view " + dir + "/none.pvd", dir);
    CHECK(no_run.status == 1);

    const std::string step = dir + "/" + vtk::vtp_name("pendulum", 7);
    write_file(step, test_support::replace_all(read_file(step), "</Points>", "</Pointz>"));
    const Result broken = run_yamsc("view " + dir + " -o " + dir + "/page.html", dir);
    CHECK(broken.status == 1);
    CHECK(broken.output.find(step + ":") != std::string::npos);
    CHECK(test_support::temporaries(dir).empty());
    CHECK(read_file(dir + "/page.html").empty()); // nothing written
}
