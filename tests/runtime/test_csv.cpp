// CSV output: number format, header and value round trip, atomic replacement
// and what a failed write leaves behind (nothing), and the text summary.
#include "runtime/test_models.hpp"

#include "yamsc/atomic_file.hpp"
#include "yamsc/csv.hpp"

#include <doctest/doctest.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace yamsc::runtime;
namespace fs = std::filesystem;

namespace {

// A fresh, empty directory for one test case.
fs::path scratch_dir(const std::string& name) {
    const fs::path dir = fs::path(YAMSC_TEST_BINARY_DIR) / "runtime_csv" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string read_file(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> fields;
    std::stringstream s(line);
    std::string field;
    while (std::getline(s, field, ',')) fields.push_back(field);
    return fields;
}

SimulationResult oscillator_run() {
    SimulationOptions o;
    o.t_end = 1.0;
    o.dt = 0.01;
    o.x0 = {0.1, -0.5};
    o.u = {1.0};
    return simulate(from_generated<test_oscillator::Model>({}), o);
}

std::size_t leftover_temporaries(const fs::path& dir) {
    std::size_t n = 0;
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.path().filename().string().find(".tmp.") != std::string::npos) ++n;
    return n;
}

} // namespace

TEST_CASE("the fast CSV number formatting equals std::to_chars with 10 digits") {
    // Random bit patterns (every exponent) and values of simulation size,
    // ties and carries (9.9999999995) included.
    std::mt19937_64 rng(2026);
    std::uniform_real_distribution<double> mantissa(-10.0, 10.0);
    std::uniform_int_distribution<int> exponent(-30, 30);
    std::vector<double> values{
        9.9999999995, 9.9999999994999, 0.00099999999995,       1e-5,  1e-4, 123456789.05,
        1234567890.5, 5e-324,          1.7976931348623157e308, -1e22, 1e23, 0.5,
        2.5e-5,       999999999.95};
    for (int i = 0; i < 300000; ++i) {
        std::uint64_t bits = rng();
        double v;
        std::memcpy(&v, &bits, sizeof v);
        values.push_back(v);
        values.push_back(mantissa(rng) * std::pow(10.0, exponent(rng)));
        values.push_back(std::round(mantissa(rng) * 1e6) / 1e6 * std::pow(10.0, exponent(rng)));
    }
    int differ = 0;
    for (double v : values) {
        char expected[64];
        const auto end =
            std::to_chars(expected, expected + sizeof expected, v, std::chars_format::general, 10)
                .ptr;
        if (std::isnan(v)) continue;
        if (format_csv_value(v) != std::string(expected, end) && ++differ < 10)
            CHECK(format_csv_value(v) == std::string(expected, end));
    }
    CHECK(differ == 0);
    std::string appended = "x";
    append_csv_value(appended, -1.25e-7);
    CHECK(appended == "x-1.25e-07");
}

TEST_CASE("CSV numbers are %.10g, whatever the locale") {
    for (double v : {0.0, 0.1, -2.5, 1.0 / 3.0, 1e-20, 6.02214076e23, 123456789012.0, -0.0}) {
        char expected[64];
        std::snprintf(expected, sizeof expected, "%.10g", v);
        CHECK(format_csv_value(v) == expected);
    }
}

TEST_CASE("CSV header and values round trip") {
    const SimulationResult r = oscillator_run();
    const fs::path path = scratch_dir("roundtrip") / "out.csv";
    write_csv(r, path.string());

    std::ifstream in(path);
    std::string line;
    REQUIRE(std::getline(in, line));
    CHECK(line == "time,x,x',spring_force,kinetic_energy");
    std::size_t row = 0;
    while (std::getline(in, line)) {
        const auto fields = split(line);
        REQUIRE(fields.size() == 5);
        REQUIRE(row < r.rows());
        for (std::size_t j = 0; j < 5; ++j) {
            const double written = std::strtod(fields[j].c_str(), nullptr);
            const double original = r.value(row, j);
            CHECK(std::abs(written - original) <= 5e-10 * std::abs(original));
        }
        ++row;
    }
    CHECK(row == r.rows());
    CHECK(leftover_temporaries(path.parent_path()) == 0);
}

TEST_CASE("writing is deterministic and replaces an existing file") {
    const SimulationResult r = oscillator_run();
    const fs::path dir = scratch_dir("replace");
    const fs::path path = dir / "out.csv";
    { std::ofstream(path) << "old content\n"; }
    write_csv(r, path.string());
    const std::string first = read_file(path);
    write_csv(r, path.string());
    CHECK(read_file(path) == first);
    CHECK(first.rfind("time,", 0) == 0);
    CHECK(leftover_temporaries(dir) == 0);
}

TEST_CASE("a failed write leaves the target untouched and no temporary file") {
    const SimulationResult r = oscillator_run();
    const fs::path dir = scratch_dir("failure");

    SUBCASE("the directory does not exist") {
        const fs::path path = dir / "missing" / "out.csv";
        CHECK_THROWS_WITH_AS(write_csv(r, path.string()), doctest::Contains(path.string().c_str()),
                             std::runtime_error);
        CHECK_FALSE(fs::exists(path));
    }
    SUBCASE("the target is a directory, so the final rename fails") {
        const fs::path path = dir / "taken";
        fs::create_directory(path);
        { std::ofstream(path / "inside.txt") << "keep\n"; }
        CHECK_THROWS_AS(write_csv(r, path.string()), std::runtime_error);
        CHECK(fs::is_directory(path));
        CHECK(read_file(path / "inside.txt") == "keep\n");
    }
    SUBCASE("the writer fails half way") {
        const fs::path path = dir / "out.csv";
        { std::ofstream(path) << "old content\n"; }
        CHECK_THROWS_WITH_AS(write_file_atomically(path.string(),
                                                   [](std::ostream& out) {
                                                       out << "time,x\n0,1\n";
                                                       throw std::runtime_error("disk full");
                                                   }),
                             "disk full", std::runtime_error);
        CHECK(read_file(path) == "old content\n");
    }
    CHECK(leftover_temporaries(dir) == 0);
}

TEST_CASE("the summary gives min, max and final of every channel") {
    SimulationResult r;
    r.columns = {"time", "a", "a'", "y"};
    r.nx = 2;
    r.ny = 1;
    r.time = {0.0, 0.5, 1.0};
    r.states = {1.0, 0.0, -2.0, 3.0, 0.5, -1.0};
    r.outputs = {10.0, 30.0, 20.0};
    const auto channels = summarize(r);
    REQUIRE(channels.size() == 3);
    CHECK(channels[0].name == "a");
    CHECK(channels[0].min == -2.0);
    CHECK(channels[0].max == 1.0);
    CHECK(channels[0].final == 0.5);
    CHECK(channels[1].min == -1.0);
    CHECK(channels[1].max == 3.0);
    CHECK(channels[2].max == 30.0);
    CHECK(channels[2].final == 20.0);

    const std::string text = format_summary(r);
    MESSAGE(text);
    CHECK(text.find("3 samples, t = 0 .. 1 s") != std::string::npos);
    CHECK(text.find("a'") != std::string::npos);
    CHECK(summarize(SimulationResult{}).empty());
}
