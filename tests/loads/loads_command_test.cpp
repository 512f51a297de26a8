// `yamsc loads` from the command line: the outputs, a batch folder, the lifetime
// DELs, the plot, and what it refuses.
#include "analysis/batch_summary.hpp"
#include "test_files.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <sstream>

using namespace test_support;

namespace {

const std::string example =
    std::string(YAMSC_TEST_DATA_DIR) + "/reference/loads/fastout_allnodes.outb";

int run_loads(const std::string& dir, const std::string& args) {
    return exit_status("cd '" + dir + "' && '" + YAMSC_EXE + "' loads " + args +
                       " >out.txt 2>err.txt");
}

/// A yamsc-like CSV: a cosine of amplitude `a` and period 2 s over 20 s, and a
/// constant wind `v`.
void write_run(const std::string& path, double a, double v) {
    std::ostringstream s;
    s << "Time_[s],Wind1VelX_[m/s],TwrBsMyt_[kN-m]\n";
    for (int i = 0; i <= 400; ++i)
        s << i * 0.05 << "," << v << "," << a * std::cos(M_PI * i * 0.05) << "\n";
    write_file(path, s.str());
}

} // namespace

TEST_CASE("yamsc loads: OpenFAST's .outb to CSV, JSON and text") {
    const std::string dir = scratch_dir("loads", "outb");
    REQUIRE(
        run_loads(dir, "'" + example +
                           "' --channels RootMyc1,TwrBsMyt --wohler 4 --del RootMyc1:10 -o t.csv "
                           "--json t.json") == 0);
    const std::string csv = read_file(dir + "/t.csv");
    CHECK(csv.find("set,run,file,wind_speed,t_begin,t_end,channel,mean,std,min,max,skewness,"
                   "kurtosis,DEL_m4,DEL_m10\n") == 0);
    // RootMyc1 takes --del's exponent only, TwrBsMyt --wohler's; the run's wind from Wind1VelX.
    CHECK(csv.find(",RootMyc1_[kN-m],667.9999701,156.5132942,47.37204269,1041.441918,-0.531776579,"
                   "4.908080396,,739.7556068\n") != std::string::npos);
    CHECK(csv.find(",TwrBsMyt_[kN-m],3267.993867,2158.989138,") != std::string::npos);
    CHECK(csv.find(",5201.750002,\n") != std::string::npos);
    const std::string json = read_file(dir + "/t.json");
    CHECK(json.find("\"del\": 739.75560677369") != std::string::npos);
    const std::string text = read_file(dir + "/out.txt");
    CHECK(text.find("RootMyc1_[kN-m]") != std::string::npos);
    CHECK(text.find("DEL m=10") != std::string::npos);

    // --from/--to: the window's ends included.
    REQUIRE(run_loads(dir, "'" + example + "' --channels RootMyc1 --from 2 --to 8 -o w.csv") == 0);
    CHECK(read_file(dir + "/w.csv").find(",2,8,RootMyc1_[kN-m],") != std::string::npos);
}

TEST_CASE("yamsc loads: refusals leave nothing written") {
    const std::string dir = scratch_dir("loads", "refusals");
    write_run(dir + "/a.csv", 1, 8);
    const std::string before = read_file(dir + "/a.csv");
    CHECK(run_loads(dir, "a.csv -o a.csv") == 2); // an output replacing an input
    CHECK(read_file(dir + "/a.csv") == before);
    CHECK(run_loads(dir, "a.csv --channels NoSuch -o x.csv --json x.json") == 1);
    CHECK(read_file(dir + "/err.txt").find("a.csv: no channel 'NoSuch'") != std::string::npos);
    CHECK(!std::filesystem::exists(dir + "/x.csv"));
    CHECK(!std::filesystem::exists(dir + "/x.json"));
    CHECK(run_loads(dir, "a.csv --plot p.svg") == 1); // one wind speed: nothing to plot against
    CHECK(!std::filesystem::exists(dir + "/p.svg"));
    CHECK(run_loads(dir, "a.csv --wohler 0") == 2);
    CHECK(run_loads(dir, "a.csv --class IV") == 2);
    CHECK(run_loads(dir, "a.csv --life 10") == 2);
    write_file(dir + "/bad.outb", std::string("\x04\x00\x05\x00", 4));
    CHECK(run_loads(dir, "bad.outb") == 1);
    CHECK(read_file(dir + "/err.txt")
              .find("bad.outb: byte 4: the file ends in the number of channels") !=
          std::string::npos);
    CHECK(temporaries(dir).empty());
}

TEST_CASE("yamsc loads --batch: a batch folder's finished cases, lifetime DELs, the plot beside a "
          "reference") {
    const std::string dir = scratch_dir("loads", "batch");
    const std::string out = dir + "/cases.out";
    std::filesystem::create_directories(out);
    write_run(out + "/v8.csv", 1, 8);
    write_run(out + "/v12.csv", 2, 12);
    yamsc::analysis::CaseSummary ok8{1, "v8", true, "", "", 0.1}, ok12{2, "v12", true, "", "", 0.1},
        failed{3, "v16", false, "", "cases.csv:4:1: error: it broke", 0.0};
    write_file(out + "/summary.csv", yamsc::analysis::summary_text({ok8, ok12, failed}));
    std::filesystem::create_directories(dir + "/openfast");
    write_run(dir + "/openfast/of8.csv", 1.1, 8);
    write_run(dir + "/openfast/of12.csv", 2.1, 12);

    REQUIRE(
        run_loads(dir,
                  "--batch cases.out --reference openfast --channels TwrBsMyt --wohler 4 --bins 0 "
                  "--weibull 10,2 -o t.csv --plot p.svg") == 0);
    CHECK(read_file(dir + "/err.txt")
              .find("skipped the failed case v16: cases.csv:4:1: error: it broke") !=
          std::string::npos);
    const std::string csv = read_file(dir + "/t.csv");
    // 10 cycles of range 2A over 20 s: DEL = 2A (10/20)^(1/4).
    const double d8 = 2 * std::pow(0.5, 0.25), d12 = 4 * std::pow(0.5, 0.25);
    char expected[128];
    std::snprintf(expected, sizeof expected, "runs,v8,%s/v8.csv,8,0,20,TwrBsMyt_[kN-m],",
                  "cases.out");
    CHECK(csv.find(expected) != std::string::npos);
    std::snprintf(expected, sizeof expected, ",%.10g\n", d8);
    CHECK(csv.find(expected) != std::string::npos);
    // Lifetime: bins [6, 10] and [10, 14] of the Weibull (10, 2).
    auto F = [](double v) { return 1 - std::exp(-(v / 10) * (v / 10)); };
    const double life =
        std::pow((F(10) - F(6)) * std::pow(d8, 4) + (F(14) - F(10)) * std::pow(d12, 4), 0.25);
    std::snprintf(expected, sizeof expected, "runs,lifetime,,,,,TwrBsMyt,,,,,,,%.10g\n", life);
    CHECK(csv.find(expected) != std::string::npos);
    CHECK(csv.find("reference,lifetime,,,,,TwrBsMyt,") != std::string::npos);
    const std::string svg = read_file(dir + "/p.svg");
    CHECK(svg.find("<svg") != std::string::npos);
    CHECK(svg.find("DEL m=4 TwrBsMyt") != std::string::npos);
    CHECK(svg.find("reference") != std::string::npos);

    // The wind speeds from a manifest's wind column instead of a channel; runs
    // without a row (the reference's) take their Wind1VelX.
    write_file(dir + "/cases.csv",
               "id,model,tmax,dt,wind\nv8,m.mbd,20,0.05,9\nv12,m.mbd,20,0.05,13\n");
    REQUIRE(run_loads(dir, "--batch cases.out --speeds cases.csv --reference openfast "
                           "--channels TwrBsMyt -o s.csv") == 0);
    const std::string speeds = read_file(dir + "/s.csv");
    CHECK(speeds.find("runs,v12,cases.out/v12.csv,13,") != std::string::npos);
    CHECK(speeds.find("reference,of12,openfast/of12.csv,12,") != std::string::npos);
    // Patterns and folders in --runs and --reference, expanded by yamsc, sorted.
    REQUIRE(run_loads(dir, "--runs 'cases.out/v*.csv' --reference openfast --channels TwrBsMyt "
                           "--wohler 4 -o g.csv") == 0);
    const std::string globbed = read_file(dir + "/g.csv");
    CHECK(globbed.find("runs,v12,cases.out/v12.csv,12,") <
          globbed.find("runs,v8,cases.out/v8.csv,8,"));
    CHECK(globbed.find("reference,of12,openfast/of12.csv,12,") != std::string::npos);
    // A pattern the shell expands after an option: every file is the option's.
    REQUIRE(run_loads(dir, "--runs cases.out/v*.csv --reference openfast/*.csv --channels "
                           "TwrBsMyt --wohler 4 -o e.csv") == 0);
    const std::string expanded = read_file(dir + "/e.csv");
    CHECK(expanded.find("reference,of8,openfast/of8.csv,8,") != std::string::npos);
    CHECK(expanded.find("reference,of12,openfast/of12.csv,12,") != std::string::npos);
    CHECK(expanded.find("runs,of") == std::string::npos);
    CHECK(expanded.find("runs,v8,") != std::string::npos);
    CHECK(run_loads(dir, "--runs 'nothing/*.csv'") == 2);
    CHECK(run_loads(dir, "--batch cases.out --speeds cases.csv --wind-channel NoWind") == 0);
    CHECK(run_loads(dir, "openfast/of8.csv --speeds cases.csv --wind-channel NoWind") == 1);
    CHECK(
        read_file(dir + "/err.txt")
            .find("of8.csv: no channel 'NoWind' (--wind-channel) and no row 'of8' in cases.csv") !=
        std::string::npos);
}
