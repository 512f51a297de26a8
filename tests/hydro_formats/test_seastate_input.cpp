// SeaState's input file: every entry of the OC3-Hywind sea state read (OpenFAST v4 and
// v5 layouts), the options read but not modelled warned at their line, and the errors
// located at their line and column.
#include "seastate/seastate_input.hpp"
#include "support.hpp"

using namespace yamsc;
using namespace hydro_test;
using diag::Severity;

namespace {

struct Read {
    std::optional<seastate::Input> input;
    diag::Diagnostics diags;
};

std::unique_ptr<Read> read(const std::string& text) {
    auto r = std::make_unique<Read>();
    auto file = std::make_shared<const diag::SourceFile>("ss.dat", text);
    r->input = seastate::read_seastate_input(file, r->diags, aerodyn::includes_refused());
    return r;
}

/// `text` with the value of the entry `key` (the first token of its line) replaced.
std::string with_value(const std::string& text, const std::string& key, const std::string& value) {
    const auto at = text.find("   " + key + " ");
    REQUIRE_MESSAGE(at != std::string::npos, key);
    const auto start = text.rfind('\n', at) + 1;
    return std::string(text).replace(start, at - start, value);
}

/// The one diagnostic of `severity` is at the value of `key`, with `message` in it.
void check_at_value(const std::string& text, Severity severity, const std::string& key,
                    const std::string& message) {
    const auto r = read(text);
    INFO(r->diags.render());
    const auto found = of(r->diags, severity);
    REQUIRE(found.size() == 1);
    CHECK(found[0].loc.line == line_of(text, "   " + key + " "));
    CHECK(found[0].loc.col == 1);
    CHECK(found[0].message.find(message) != std::string::npos);
    CHECK(r->input.has_value() == (severity == Severity::warning));
}

} // namespace

TEST_CASE("the OC3-Hywind sea state (OpenFAST v4 layout): every entry") {
    diag::Diagnostics diags;
    const auto in =
        seastate::read_seastate_input(std::filesystem::path(data_dir + "oc3_sea_state.dat"), diags);
    INFO(diags.render());
    REQUIRE(in);
    CHECK(diags.all().empty());
    CHECK(!in->water_density);
    CHECK(!in->water_depth);
    CHECK(!in->msl2swl);
    CHECK(in->x_half_width == 30);
    CHECK(in->y_half_width == 30);
    CHECK(in->z_depth == 130);
    CHECK(in->nx == 3);
    CHECK(in->ny == 3);
    CHECK(in->nz == 40);
    CHECK(in->wave_mod == seastate::WaveKind::irregular);
    CHECK(!in->regular_user_phase);
    CHECK(in->stretching == seastate::Stretching::none);
    CHECK(in->wave_current_mod == 0);
    CHECK(in->wave_tmax == 600);
    CHECK(in->wave_dt == 0.25);
    CHECK(in->wave_hs == 6);
    CHECK(in->wave_tp == 10);
    CHECK(!in->peak_shape);
    CHECK(in->low_cutoff == 0);
    CHECK(in->high_cutoff == 500);
    CHECK(in->wave_dir_deg == 0);
    CHECK(in->wave_dir_mod == 0);
    CHECK(in->wave_dir_spread == 1);
    CHECK(in->wave_n_dir == 1);
    CHECK(in->wave_dir_range == 90);
    CHECK(in->seed1 == 123456789);
    CHECK(!in->seed2);
    CHECK(in->generator == seastate::RandomGenerator::ranlux);
    CHECK(in->normal_amplitudes);
    CHECK(in->wave_kin_file.empty());
    CHECK(!in->diff_qtf);
    CHECK(!in->sum_qtf);
    CHECK(in->low_cutoff_diff == 0);
    CHECK(in->high_cutoff_diff == 3.5);
    CHECK(in->low_cutoff_sum == 0.1);
    CHECK(in->high_cutoff_sum == 3.5);
    CHECK(in->const_wave_mod == 0);
    CHECK(in->crest_hmax == 1);
    CHECK(in->crest_time == 60);
    CHECK(in->crest_xi == 0);
    CHECK(in->crest_yi == 0);
    CHECK(in->curr_mod == 0);
    CHECK(in->curr_ssv0 == 0);
    CHECK(!in->curr_ss_dir_deg);
    CHECK(in->curr_ns_ref == 20);
    CHECK(in->curr_nsv0 == 0);
    CHECK(in->curr_ns_dir_deg == 0);
    CHECK(in->curr_div == 0);
    CHECK(in->curr_di_dir_deg == 0);
    CHECK(in->mcfd == 0);
    CHECK(!in->sum_file);
    CHECK(in->out_switch == 2);
    CHECK(in->out_fmt == "G0");
    CHECK(in->out_sfmt == "A11");
    CHECK(in->wave_elev_x == std::vector<double>{0});
    CHECK(in->wave_elev_y == std::vector<double>{0});
    CHECK(in->wave_kin_x == std::vector<double>{10.5, -18});
    CHECK(in->wave_kin_y == std::vector<double>{25, -6});
    CHECK(in->wave_kin_z == std::vector<double>{-14, -17});
    CHECK(in->out_channels == std::vector<std::string>{"Wave1Elev"});
    const std::string text = file_text("oc3_sea_state.dat");
    CHECK(in->out_channel_lines == std::vector<int>{line_of(text, "\"Wave1Elev\"")});
    CHECK(in->location("WaveHs").line == line_of(text, "WaveHs"));
    CHECK(in->location("wavehs").col == 14);
    CHECK(in->location("WaveSeed(2)").col == 1);
}

TEST_CASE("values as OpenFAST accepts them: numbers for defaults, 1P#, a numeric second seed, "
          "v5's WvCrntMod, no points, en dashes in comments") {
    std::string t = file_text("oc3_sea_state.dat");
    t = with_value(t, "WtrDens", "1025");
    t = with_value(t, "WtrDpth", "320.0");
    t = with_value(t, "MSL2SWL", "0");
    t = with_value(t, "Z_Depth", "DEFAULT");
    t = with_value(t, "WaveMod", "1p30.5");
    t = with_value(t, "WaveStMod", "3");
    t = with_value(t, "WavePkShp", "3.3");
    t = with_value(t, "WaveSeed(2)", "-42");
    t = with_value(t, "WaveSeed(1)", "2147483647");
    t = with_value(t, "WaveNDAmp", ".false.");
    t = with_value(t, "CurrSSDir", "45");
    t = replaced(t, "           600   WaveTMax",
                 "             0   WvCrntMod\n           600   WaveTMax");
    t = with_value(t, "NWaveKin", "0");
    t = replaced(t, "X_HalfWidth    - Half", "X_HalfWidth    \xE2\x80\x93 Half");
    const auto r = read(t);
    INFO(r->diags.render());
    REQUIRE(r->input);
    CHECK(r->diags.all().empty());
    const auto& in = *r->input;
    CHECK(in.water_density == 1025);
    CHECK(in.water_depth == 320);
    CHECK(in.msl2swl == 0);
    CHECK(!in.z_depth);
    CHECK(in.wave_mod == seastate::WaveKind::regular);
    CHECK(in.regular_user_phase);
    CHECK(in.wave_phase_deg == 30.5);
    CHECK(in.stretching == seastate::Stretching::wheeler);
    CHECK(in.peak_shape == 3.3);
    CHECK(in.seed2 == -42);
    CHECK(in.seed1 == 2147483647);
    CHECK(in.generator == seastate::RandomGenerator::intrinsic);
    CHECK(!in.normal_amplitudes);
    CHECK(in.curr_ss_dir_deg == 45);
    CHECK(in.wave_kin_x.empty());
    CHECK(in.wave_kin_z.empty());
    CHECK(in.out_channels == std::vector<std::string>{"Wave1Elev"});
}

TEST_CASE("options read but not modelled: a warning at the entry's value") {
    const std::string t = file_text("oc3_sea_state.dat");
    using S = Severity;
    for (int mod = 3; mod <= 7; ++mod) {
        CAPTURE(mod);
        check_at_value(with_value(t, "WaveMod", std::to_string(mod)), S::warning, "WaveMod",
                       "WaveMod " + std::to_string(mod));
    }
    check_at_value(with_value(t, "WaveDirMod", "1"), S::warning, "WaveDirMod", "WaveDirMod 1");
    check_at_value(with_value(t, "WvDiffQTF", "TRUE"), S::warning, "WvDiffQTF", "second-order");
    check_at_value(with_value(t, "WvSumQTF", "T"), S::warning, "WvSumQTF", "second-order");
    check_at_value(with_value(t, "ConstWaveMod", "1"), S::warning, "ConstWaveMod", "constrained");
    check_at_value(with_value(t, "CurrMod", "1"), S::warning, "CurrMod", "current");
    check_at_value(with_value(t, "MCFD", "9.4"), S::warning, "MCFD", "MacCamy-Fuchs");
    check_at_value(replaced(t, "           600   WaveTMax",
                            "1   WvCrntMod  - waves and current\n           600   WaveTMax"),
                   S::warning, "WvCrntMod", "wave-current");
    // Spreading matters only for irregular waves: none with still water.
    const auto r = read(with_value(with_value(t, "WaveDirMod", "1"), "WaveMod", "0"));
    CHECK(r->diags.all().empty());
}

TEST_CASE("errors at their line and column, with the entry's name") {
    const std::string t = file_text("oc3_sea_state.dat");
    using S = Severity;
    check_at_value(with_value(t, "WaveMod", "8"), S::error, "WaveMod", "'WaveMod' must be 0 to 7");
    check_at_value(with_value(t, "WaveMod", "1Px"), S::error, "WaveMod", "1P# needs the phase");
    check_at_value(with_value(t, "WaveSeed(2)", "T"), S::error, "WaveSeed(2)", "invalid generator");
    check_at_value(with_value(t, "WaveSeed(2)", "MT19937"), S::error, "WaveSeed(2)",
                   "must be an integer or RANLUX, not 'MT19937'");
    check_at_value(with_value(t, "WaveSeed(2)", "3000000000"), S::error, "WaveSeed(2)",
                   "must be a 32-bit integer, not '3000000000'");
    check_at_value(with_value(t, "WaveSeed(1)", "1.5"), S::error, "WaveSeed(1)",
                   "'WaveSeed(1)' must be a 32-bit integer, not '1.5'");
    check_at_value(with_value(t, "WaveStMod", "4"), S::error, "WaveStMod",
                   "'WaveStMod' must be 0 to 3");
    check_at_value(with_value(t, "NWaveElev", "10"), S::error, "NWaveElev",
                   "'NWaveElev' must be 0 to 9");
    check_at_value(with_value(t, "NX", "1"), S::error, "NX", "'NX' must be 2 to 10000");
    check_at_value(with_value(t, "WaveHs", "six"), S::error, "WaveHs",
                   "'WaveHs' must be a number, not 'six'");
    check_at_value(with_value(t, "WaveNDAmp", "yes"), S::error, "WaveNDAmp",
                   "must be True or False");
    check_at_value(with_value(t, "WtrDens", "heavy"), S::error, "WtrDens",
                   "'WtrDens' must be a number");
    {
        // Two points announced, one given: the error at the key that follows the value.
        const std::string two = with_value(t, "NWaveElev", "2");
        const auto r = read(two);
        const auto e = of(r->diags, S::error);
        REQUIRE(e.size() == 1);
        CHECK(e[0].loc.line == line_of(two, "WaveElevxi"));
        CHECK(e[0].loc.col == col_of(two, "WaveElevxi"));
        CHECK(e[0].message == "WaveElevxi: value 2 must be a number, not 'WaveElevxi'");
    }
    {
        const std::string missing = replaced(t, "WaveTp ", "WaveTq ");
        const auto r = read(missing);
        const auto e = of(r->diags, S::error);
        REQUIRE(e.size() == 1);
        CHECK(e[0].loc.line == line_of(missing, "WaveTq"));
        CHECK(e[0].message == "expected the entry 'WaveTp' here (this line holds 'WaveTq')");
    }
}

TEST_CASE("the fuzz seed is a file the reader accepts (v5, 1P30, an intrinsic seed)") {
    diag::Diagnostics diags;
    const auto in = seastate::read_seastate_input(
        std::filesystem::path(std::string(YAMSC_SOURCE_DIR) +
                              "/tests/fuzz/seeds/seastate/regular_v5.dat"),
        diags);
    INFO(diags.render());
    REQUIRE(in);
    CHECK(diags.all().empty());
    CHECK(in->regular_user_phase);
    CHECK(in->wave_phase_deg == 30);
    CHECK(in->seed2 == -42);
}
