// Reference tables, the error measures of --compare, OpenFAST channel naming and the SVG
// writer, on data whose answers are known by hand.
#include "analysis/campbell.hpp"
#include "analysis/svg_plot.hpp"
#include "diag/errors.hpp"
#include "validation_support.hpp"

#include <cmath>
#include <fstream>

using namespace yamsc::analysis;
using yamsc::diag::UserError;

namespace {

std::string write(const std::string& name, const std::string& text) {
    ::mkdir(validation::work_dir.c_str(), 0755);
    const std::string path = validation::work_dir + "/" + name;
    std::ofstream(path) << text;
    return path;
}

Table table(std::vector<std::string> columns, std::vector<std::vector<double>> data) {
    Table t;
    t.columns = std::move(columns);
    t.data = std::move(data);
    return t;
}

} // namespace

TEST_CASE("read_table: CSV, and OpenFAST .out text with a units row and a header") {
    Table csv = read_table(write("a.csv", "Time_[s],Q_TFA1_[m]\n0,1\n0.5,2.5e-1\n1,-1D-1\n"));
    CHECK(csv.columns == std::vector<std::string>{"Time_[s]", "Q_TFA1_[m]"});
    REQUIRE(csv.rows() == 3);
    CHECK(csv.data[1][1] == 0.25);
    CHECK(csv.data[1][2] == -0.1); // Fortran exponent
    Table out = read_table(write("a.out", "Predictions were generated on 23-Nov-2025\n"
                                          "linked with NWTC Subroutine Library\n\n"
                                          "Time\tAzimuth\tQ_TFA1\n(s)\t(deg)\t(m)\n"
                                          "0.0\t0.0\t2.0\n0.01\t0.6\t1.99\n"));
    CHECK(out.columns == std::vector<std::string>{"Time_[s]", "Azimuth_[deg]", "Q_TFA1_[m]"});
    CHECK(out.data[1][1] == 0.6);
    CHECK_THROWS_WITH_AS(read_table(write("b.csv", "t,y\n0,1\n1,2,3\n")),
                         doctest::Contains("b.csv:3: expected 2 numbers"), UserError);
    CHECK_THROWS_WITH_AS(read_table(write("c.csv", "t,y\n0,1\n0,2\n")),
                         doctest::Contains("c.csv:3: time does not rise"), UserError);
}

TEST_CASE("compare: a constant offset is offset/range; R^2 by its definition") {
    // Reference y = sin(2 pi t) on [0, 1] (range 2), the simulation 0.01 higher, sampled
    // twice as densely: interpolated onto the reference times.
    std::vector<double> tr, yr, ts, ys;
    for (int i = 0; i <= 100; ++i) {
        tr.push_back(i * 0.01);
        yr.push_back(std::sin(2 * M_PI * tr.back()));
    }
    for (int i = 0; i <= 200; ++i) {
        ts.push_back(i * 0.005);
        ys.push_back(std::sin(2 * M_PI * ts.back()) + 0.01);
    }
    const Table ref = table({"Time_[s]", "Q_TFA1_[m]", "PtfmPitch_[deg]"}, {tr, yr, yr});
    const Table sim = table({"time", "Q_TFA1", "other"}, {ts, ys, ys});
    const Comparison c = compare_tables(sim, ref);
    REQUIRE(c.channels.size() == 1); // matched by the name without its unit
    CHECK(c.missing == std::vector<std::string>{"PtfmPitch_[deg]"});
    const ChannelScore& s = c.channels[0];
    CHECK(s.matched == "Q_TFA1");
    CHECK(s.samples == 101);
    CHECK(s.range == doctest::Approx(2.0).epsilon(1e-12));
    // Linear interpolation of a sine at its own sample points plus the midpoints: the
    // reference times are sample points of the simulation, so the error is exactly 0.01.
    CHECK(s.mean_rel_error == doctest::Approx(0.005).epsilon(1e-9));
    CHECK(s.max_abs_error == doctest::Approx(0.01).epsilon(1e-9));
    double mean = 0, dev = 0;
    for (double v : yr) mean += v / 101;
    for (double v : yr) dev += (v - mean) * (v - mean);
    CHECK(s.r2 == doctest::Approx(1 - 101 * 1e-4 / dev).epsilon(1e-12));
    CHECK(format_comparison(c, "ref.csv").find("Q_TFA1_[m]" + std::string(12, ' ') + "0.500 %") !=
          std::string::npos);
    const Table late = table({"t", "Q_TFA1"}, {{5, 6}, {0, 0}});
    CHECK_THROWS_AS(compare_tables(late, ref), UserError);
}

TEST_CASE("the azimuth: wrapped at 360 deg like OpenFAST, unwrapped for comparing") {
    CHECK(unwrap({350, 355, 0, 5, 10}, 360) == std::vector<double>{350, 355, 360, 365, 370});
    CHECK(unwrap({10, 5, 0, 355}, 360) == std::vector<double>{10, 5, 0, -5});
    const Table sim = table({"t", "Azimuth"}, {{0, 1, 2, 3}, {340, 350, 360, 370}});
    const Table ref = table({"Time_[s]", "Azimuth_[deg]"}, {{0, 1, 2, 3}, {340, 350, 0, 10}});
    const Comparison c = compare_tables(sim, ref);
    REQUIRE(c.channels.size() == 1);
    CHECK(c.channels[0].mean_rel_error == 0);
    CHECK(openfast_channel("Azimuth")->wrap_360);
    CHECK(std::string(openfast_channel("PtfmPitch")->unit) == "deg");
    CHECK(openfast_channel("q_fa1") == nullptr);
    CHECK(base_name("Q_TFA1_[m]") == "Q_TFA1");
}

TEST_CASE("svg: round ticks, one polyline per curve, escaped text, same bytes every time") {
    CHECK(nice_ticks(0, 7, 8) == std::vector<double>{0, 1, 2, 3, 4, 5, 6, 7});
    CHECK(nice_ticks(-2.1, 2.1, 5) == std::vector<double>{-2, -1, 0, 1, 2});
    const std::vector<double> ticks = nice_ticks(0, 0.0042, 4); // step 0.00105 -> 0.002
    REQUIRE(ticks.size() == 3);
    CHECK(ticks[2] == doctest::Approx(0.004));
    PlotPanel p{"Q_TFA1_[m] <x>",
                {{"sim", {0, 1, 2}, {0, 1, 0}, false}, {"ref", {0, 1, 2}, {0, 0.9, 0}, true}}};
    PlotOptions o;
    o.title = "a & b";
    const std::string svg = svg_plot({p, p}, o);
    CHECK(svg == svg_plot({p, p}, o));
    CHECK(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0) == 0);
    std::size_t polylines = 0;
    for (auto at = svg.find("<polyline"); at != std::string::npos;
         at = svg.find("<polyline", at + 1))
        ++polylines;
    CHECK(polylines == 4);
    CHECK(svg.find("stroke-dasharray") != std::string::npos);
    CHECK(svg.find("a &amp; b") != std::string::npos);
    CHECK(svg.find("Q_TFA1_[m] &lt;x&gt;") != std::string::npos);
    // Where the points go: x from 90 to 880 px over t = 0..2; y over the values
    // 0..1 padded by 5 %, 200 px below the title's 70.
    CHECK(svg.find("points=\"90.00,260.91 485.00,79.09 880.00,260.91\"") != std::string::npos);
    // The time axis's round ticks under the last panel only.
    CHECK(svg.find("text-anchor=\"middle\">1.5</text>") != std::string::npos);
    std::size_t labels = 0;
    for (auto at = svg.find(">1.5</text>"); at != std::string::npos;
         at = svg.find(">1.5</text>", at + 1))
        ++labels;
    CHECK(labels == 1);
}

TEST_CASE("campbell_svg: a curve per mode in each panel, on the plot module's axes") {
    std::vector<CampbellRow> rows(3);
    for (std::size_t i = 0; i < rows.size(); ++i) {
        yamsc::runtime::Mode rigid, flap;
        rigid.rigid_body = true;
        flap.freq_hz = 1 + 0.5 * static_cast<double>(i);
        flap.damping_ratio = 0.01;
        rows[i] = {static_cast<double>(i), {rigid, flap}};
    }
    const std::string svg = campbell_svg("spin & bend", "Omega", rows);
    std::size_t polylines = 0;
    for (auto at = svg.find("<polyline"); at != std::string::npos;
         at = svg.find("<polyline", at + 1))
        ++polylines;
    // Both modes' frequencies; only the flexible mode's damping (a rigid-body
    // mode has none).
    CHECK(polylines == 3);
    for (const char* text : {">spin &amp; bend<", ">frequency [Hz]<", ">damping ratio [-]<",
                             ">Omega<", ">mode 1<", ">mode 2<", ">0.5<", ">1.5<"})
        CHECK_MESSAGE(svg.find(text) != std::string::npos, text);
    CHECK(svg == campbell_svg("spin & bend", "Omega", rows));
}
