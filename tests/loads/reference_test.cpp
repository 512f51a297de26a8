// OpenFAST's binary outputs read as openfast_toolbox reads them, and DELs equal
// to openfast_toolbox's `equivalent_load` on its own example file
// (tests/data/reference/loads/README.md: the file, the command, the numbers).
#include "analysis/loads_statistics.hpp"
#include "analysis/rainflow.hpp"
#include "diag/errors.hpp"
#include "table/openfast_binary.hpp"

#include <doctest/doctest.h>

#include <cstdint>
#include <cstring>
#include <string>

using namespace yamsc;

namespace {

const std::string data_dir = std::string(YAMSC_TEST_DATA_DIR) + "/reference/loads/";

const std::vector<double>& column(const table::Table& t, const std::string& name) {
    for (std::size_t j = 0; j < t.columns.size(); ++j)
        if (t.columns[j] == name) return t.data[j];
    FAIL("no column " << name);
    throw 0;
}

template <class T> void put(std::string& bytes, T v) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    bytes.append(b, sizeof(T));
}

void put_names(std::string& bytes, const std::vector<std::string>& names, std::size_t width) {
    for (std::string n : names) {
        n.resize(width, ' ');
        bytes += n;
    }
}

std::string error_of(const std::string& bytes) {
    try {
        table::parse_openfast_binary(bytes, "f.outb");
    } catch (const diag::UserError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST_CASE("outb format 4 (OpenFAST's default): openfast_toolbox's fastout_allnodes.outb") {
    const table::Table t = table::read_time_series(data_dir + "fastout_allnodes.outb");
    REQUIRE(t.columns.size() == 259);
    CHECK(t.columns[0] == "Time_[s]");
    CHECK(t.columns[1] == "Wind1VelX_[m/s]");
    const auto& time = t.data[0];
    REQUIRE(time.size() == 101);
    CHECK(time.front() == 0.0);
    CHECK(time.back() == doctest::Approx(10.0).epsilon(1e-15));
    // openfast_toolbox's FASTOutputFile(...).toDataFrame() values.
    const auto& root = column(t, "RootMyc1_[kN-m]");
    CHECK(root[0] == doctest::Approx(47.372042690202086).epsilon(1e-14));
    CHECK(root[50] == doctest::Approx(834.0880583207172).epsilon(1e-14));
    CHECK(root[100] == doctest::Approx(595.1988164395838).epsilon(1e-14));
    const auto& tower = column(t, "TwrBsMyt_[kN-m]");
    CHECK(tower[0] == doctest::Approx(-321.786346139041).epsilon(1e-14));
    CHECK(tower[50] == doctest::Approx(5989.982235447705).epsilon(1e-14));
}

TEST_CASE("outb format 2 (10-character names): openfast_toolbox's FASTOutBin.outb") {
    const table::Table t = table::read_time_series(data_dir + "FASTOutBin.outb");
    REQUIRE(t.columns.size() == 11);
    REQUIRE(t.data[0].size() == 201);
    CHECK(t.columns[1] == "Wind1VelX_[m/s]");
    CHECK(t.columns[10] == "GenPwr_[kW]");
    CHECK(t.data[0][3] == doctest::Approx(0.015).epsilon(1e-14));
    CHECK(t.data[2][3] == doctest::Approx(-0.18579814193763172).epsilon(1e-14));
    CHECK(t.data[10][200] == doctest::Approx(40.57663190807828).epsilon(1e-14));
}

TEST_CASE("statistics of the example equal NumPy/SciPy's (pCrunch's definitions)") {
    const table::Table t = table::read_time_series(data_dir + "fastout_allnodes.outb");
    const auto s = analysis::channel_statistics(column(t, "RootMyc1_[kN-m]"));
    CHECK(s.mean == doctest::Approx(667.9999700714634).epsilon(1e-12));
    CHECK(s.std_dev == doctest::Approx(156.51329423709697).epsilon(1e-12));
    CHECK(s.min == doctest::Approx(47.372042690202086).epsilon(1e-14));
    CHECK(s.max == doctest::Approx(1041.4419180270536).epsilon(1e-14));
    CHECK(s.skewness == doctest::Approx(-0.5317765789563532).epsilon(1e-10));
    CHECK(s.kurtosis == doctest::Approx(4.908080396429721).epsilon(1e-10));
    const auto w = analysis::channel_statistics(column(t, "TwrBsMyt_[kN-m]"));
    CHECK(w.std_dev == doctest::Approx(2158.9891375801976).epsilon(1e-12));
    CHECK(w.skewness == doctest::Approx(0.24788616033562572).epsilon(1e-10));
    CHECK(w.kurtosis == doctest::Approx(1.8394853297568037).epsilon(1e-10));
}

TEST_CASE("DELs equal openfast_toolbox's equivalent_load (100 bins) on its example to 1e-6") {
    const table::Table t = table::read_time_series(data_dir + "fastout_allnodes.outb");
    const double duration = t.data[0].back() - t.data[0].front();
    using analysis::Counting;
    struct Case {
        Counting counting; // method='rainflow_astm', or its default 'rainflow_windap'
        const char* channel;
        double m, del;
    };
    const Case cases[] = {
        {Counting::astm, "RootMyc1_[kN-m]", 1, 290.56692034737466},
        {Counting::astm, "RootMyc1_[kN-m]", 4, 532.169622909679},
        {Counting::astm, "RootMyc1_[kN-m]", 10, 739.7556067736921},
        {Counting::astm, "TwrBsMyt_[kN-m]", 1, 2451.8488502939313},
        {Counting::astm, "TwrBsMyt_[kN-m]", 4, 5201.75000230205},
        {Counting::astm, "TwrBsMyt_[kN-m]", 10, 6554.008921831211},
        {Counting::astm, "RotSpeed_[rpm]", 1, 0.024859132629905845},
        // Example_EquivalentLoad.py's own number, 284.30398 at m = 1.
        {Counting::windap, "RootMyc1_[kN-m]", 1, 284.30398434633946},
        {Counting::windap, "RootMyc1_[kN-m]", 4, 533.765971012729},
        {Counting::windap, "RootMyc1_[kN-m]", 10, 740.005713625985},
        {Counting::windap, "TwrBsMyt_[kN-m]", 1, 2412.735699247691},
        {Counting::windap, "TwrBsMyt_[kN-m]", 4, 5214.199900144531},
        {Counting::windap, "TwrBsMyt_[kN-m]", 10, 6560.850860802779},
        {Counting::windap, "RotSpeed_[rpm]", 1, 0.0244231055678117},
    };
    for (const Case& c : cases) {
        CAPTURE(c.channel);
        CAPTURE(c.m);
        CAPTURE(c.counting == Counting::astm);
        const std::vector<double>& y = column(t, c.channel);
        const auto cycles =
            c.counting == Counting::astm ? analysis::rainflow(y) : analysis::rainflow_windap(y);
        CHECK(analysis::equivalent_load(cycles, c.m, duration, {}) ==
              doctest::Approx(c.del).epsilon(1e-6));
    }
}

TEST_CASE("outb formats 1 and 3, and located errors") {
    // Format 3: float64 samples; 2 channels, 3 steps from t = 1 s every 0.5 s.
    std::string f3;
    put<std::int16_t>(f3, 3);
    put<std::int32_t>(f3, 2);
    put<std::int32_t>(f3, 3);
    put(f3, 1.0);
    put(f3, 0.5);
    put<std::int32_t>(f3, 4);
    f3 += "desc";
    put_names(f3, {"Time", "A", "B"}, 10);
    put_names(f3, {"(s)", "(m)", "(-)"}, 10);
    for (double v : {1.0, -1.0, 2.0, -2.0, 3.0, -3.0}) put(f3, v);
    const table::Table t3 = table::parse_openfast_binary(f3, "f3.outb");
    CHECK(t3.columns == std::vector<std::string>{"Time_[s]", "A_[m]", "B_[-]"});
    CHECK(t3.data[0] == std::vector<double>{1.0, 1.5, 2.0});
    CHECK(t3.data[2] == std::vector<double>{-1.0, -2.0, -3.0});

    // Format 1: packed times (slope 100, offset 0) and int16 channels (v - 10) / 2.
    std::string f1;
    put<std::int16_t>(f1, 1);
    put<std::int32_t>(f1, 1);
    put<std::int32_t>(f1, 2);
    put(f1, 100.0);
    put(f1, 0.0);
    put(f1, 2.0f);
    put(f1, 10.0f);
    put<std::int32_t>(f1, 0);
    put_names(f1, {"Time", "X"}, 10);
    put_names(f1, {"(s)", "(N)"}, 10);
    put<std::int32_t>(f1, 0);
    put<std::int32_t>(f1, 5);
    put<std::int16_t>(f1, 14);
    put<std::int16_t>(f1, -20);
    const table::Table t1 = table::parse_openfast_binary(f1, "f1.outb");
    CHECK(t1.data[0] == std::vector<double>{0.0, 0.05});
    CHECK(t1.data[1] == std::vector<double>{2.0, -15.0});

    CHECK(error_of("") == "f.outb: byte 0: the file ends in the format id");
    CHECK(error_of(std::string("\x07\x00", 2)).find("f.outb: byte 0: format id 7") == 0);
    CHECK(error_of(f3.substr(0, f3.size() - 3))
              .find("f.outb: byte 94: the file ends in the channel data") == 0);
    // Bytes after the samples are ignored (OpenFAST's reader and openfast_toolbox's do).
    CHECK(table::parse_openfast_binary(f3 + "xyz", "f3.outb").data == t3.data);
    std::string backwards = f1;
    backwards[backwards.size() - 8] = 0; // the second packed time: 5 -> 0
    CHECK(error_of(backwards).find("f.outb: byte 82: time does not rise at step 2") == 0);
    std::string huge = f3;
    huge[9] = '\x7f'; // about 2^31 steps
    CHECK(error_of(huge).find("the file ends in the channel data") != std::string::npos);
}
