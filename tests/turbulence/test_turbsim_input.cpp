// `yamsc turbulence` on TurbSim's own input for the reference file (U18_s1.inp):
// the grid, the times and the IEC scaling its summary U18_s1.sum reports, the v and
// w standard deviations (which do not depend on the random phases: no coherence,
// one amplitude per frequency), and the mean profile's table. The reader's
// located errors and warnings.
#include "analysis/commands.hpp"
#include "analysis/turbulence_spec.hpp"
#include "diag/errors.hpp"
#include "test_files.hpp"
#include "wind/turbsim_input.hpp"

#include <doctest/doctest.h>
#include <yamsc/wind/turbulence.hpp>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <stdexcept>

using namespace yamsc;

namespace {

const std::string reference = std::string(YAMSC_TEST_DATA_DIR) + "/reference/turbulence/";

// The number after "label ... =" (or the n-th number on the line starting with label).
double sum_value(const std::string& sum, const std::string& label, int index = 0) {
    const auto at = sum.find(label);
    REQUIRE(at != std::string::npos);
    const auto end = sum.find('\n', at);
    auto from = sum.find('=', at);
    if (from == std::string::npos || from > end) from = at + label.size() - 1;
    std::istringstream line(sum.substr(from + 1, end - from - 1));
    std::string word;
    std::vector<double> numbers;
    while (line >> word) {
        char* end = nullptr;
        const double v = std::strtod(word.c_str(), &end);
        if (end != word.c_str()) numbers.push_back(v); // "14.856%" too
    }
    REQUIRE(static_cast<int>(numbers.size()) > index);
    return numbers[static_cast<std::size_t>(index)];
}

// The number that starts the line holding label ("        15  Vertical grid-point ...").
double leading_value(const std::string& sum, const std::string& label) {
    const auto at = sum.find(label);
    REQUIRE(at != std::string::npos);
    const auto start = sum.rfind('\n', at) + 1;
    return std::strtod(sum.c_str() + start, nullptr);
}

wind::TurbSimInput read_text(const std::string& text) {
    std::istringstream in(text);
    return wind::read_turbsim_input(in, "t.inp");
}

std::string error_of(const std::string& text) {
    try {
        read_text(text);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST_CASE("U18_s1.inp: the grid, times and IEC scaling of TurbSim's U18_s1.sum") {
    driver::TurbulenceOptions o;
    o.input = reference + "U18_s1.inp";
    std::vector<std::string> warnings;
    runtime::TurbulenceSpec s = analysis::turbulence_spec(o, warnings);
    const std::string sum = test_support::read_file(reference + "U18_s1.sum");
    // RandSeed2 ("RanLux") is the one entry of this file yamsc does not follow.
    REQUIRE(warnings.size() == 1);
    CHECK(warnings[0].rfind(o.input + ":6:1: warning: TurbSim: RandSeed2:", 0) == 0);
    CHECK(s.seed == 1182001);

    const runtime::TurbulenceLayout l = runtime::turbulence_layout(s);
    const runtime::IecParameters p = runtime::iec_parameters(s);
    CHECK(s.nz == leading_value(sum, "Vertical grid-point matrix dimension"));
    CHECK(s.ny == leading_value(sum, "Horizontal grid-point matrix dimension"));
    CHECK(s.time_step == leading_value(sum, "Time step [seconds]"));
    CHECK(s.usable_time == leading_value(sum, "Usable output time [seconds]"));
    CHECK(s.width == leading_value(sum, "Grid width [m]"));
    CHECK(l.fft_steps == sum_value(sum, "Number of time steps in the FFT"));
    CHECK(l.steps_written == sum_value(sum, "Number of time steps output"));
    CHECK(s.ny * s.nz == sum_value(sum, "Number of points simulated"));
    CHECK(p.u_hub == doctest::Approx(sum_value(sum, "Mean wind speed at hub height")));
    CHECK(p.sigma[0] ==
          doctest::Approx(sum_value(sum, "Characteristic value of standard deviation"))
              .epsilon(2e-4));
    CHECK(100 * p.sigma[0] / p.u_hub ==
          doctest::Approx(sum_value(sum, "Characteristic value of hub turbulence intensity"))
              .epsilon(2e-4));
    CHECK(p.lambda1 == doctest::Approx(sum_value(sum, "Turbulence scale")));
    CHECK(p.length[0] == doctest::Approx(sum_value(sum, "u-component integral scale")));
    CHECK(p.coherence_length == doctest::Approx(sum_value(sum, "Coherency scale")));
    CHECK(0.12 / p.coherence_length == doctest::Approx(0.353e-3).epsilon(1e-3));
    CHECK(l.hub_on_grid);
    CHECK(l.z_bottom == doctest::Approx(17.5));
    CHECK(l.dy == doctest::Approx(145.0 / 14));
    // The mean profile table: height and speed per row, from the top.
    for (const char* row : {"162.5 ", "90.0 ", "17.5 "}) {
        const double z = std::atof(row);
        CHECK(runtime::mean_speed(s, z) ==
              doctest::Approx(sum_value(sum, std::string("    ") + row)).epsilon(3e-4));
    }

    // v and w: the same standard deviation at every point, set by the discrete
    // spectrum alone; a 3 x 3 grid over the same 145 m keeps the hub, the FFT's
    // length and the spectra.
    s.ny = s.nz = 3;
    const runtime::TurbulenceField f = runtime::generate_turbulence(s);
    REQUIRE(f.layout.fft_steps == 7392);
    for (int c = 1; c < 3; ++c) {
        double s2 = 0;
        for (int it = 0; it < 7392; ++it)
            s2 += f.hub[static_cast<std::size_t>(it) * 3 + c] *
                  f.hub[static_cast<std::size_t>(it) * 3 + c];
        const double turbsim = sum_value(sum, c == 1 ? "Lateral (v)" : "Vertical (w)", 3);
        CHECK(std::sqrt(s2 / 7392) == doctest::Approx(turbsim).epsilon(0.5e-3 / turbsim));
    }
}

TEST_CASE("the TurbSim reader: located errors and warnings") {
    const std::string text = test_support::read_file(reference + "U18_s1.inp");
    const wind::TurbSimInput t = read_text(text);
    CHECK(t.nz == 15);
    CHECK(t.usable_time == 360);
    CHECK(!t.periodic);
    CHECK(t.characteristic == wind::TurbulenceCharacteristic::B);
    CHECK(t.power_law == 0.2);
    using test_support::replace_all;
    CHECK(error_of(replace_all(text, "\"IECKAI\"      TurbModel", "\"IECVKM\"      TurbModel")) ==
          "t.inp:31:1: TurbSim: TurbModel: 'IECVKM' not supported: yamsc generates IECKAI only");
    CHECK(
        error_of(replace_all(text, "           145   GridHeight", "           1x5   GridHeight")) ==
        "t.inp:25:12: TurbSim: GridHeight: expected a number, not '1x5'");
    CHECK(
        error_of(replace_all(text, "\"NTM\"         IEC_WindType", "\"1EWM50\"      IEC_WindType"))
            .rfind("t.inp:35:1: TurbSim: IEC_WindType: '1EWM50' not supported", 0) == 0);
    CHECK(error_of(replace_all(text, "            90   HubHt", "")).rfind("t.inp:", 0) == 0);
    const wind::TurbSimInput etm = read_text(
        replace_all(text, "\"NTM\"         IEC_WindType", "\"2ETM\"        IEC_WindType"));
    CHECK(etm.model == wind::IecTurbulenceModel::extreme);
    CHECK(etm.turbine_class == 2);
    const wind::TurbSimInput ti =
        read_text(replace_all(text, "\"B\"   IECturbc", "12.5  IECturbc"));
    CHECK(ti.characteristic == wind::TurbulenceCharacteristic::percent);
    CHECK(ti.intensity_percent == 12.5);
    const wind::TurbSimInput flows =
        read_text(replace_all(replace_all(text, "          0   VFlowAng", "          8   VFlowAng"),
                              "False         WrHAWCFF", "True          WrHAWCFF"));
    CHECK(flows.warnings.size() == 3); // RandSeed2, WrHAWCFF, VFlowAng
}
