// Damaged ElastoDyn tower and blade files: every problem is reported at its line.
#include "beam/elastodyn.hpp"
#include "beam_test_support.hpp"

#include <algorithm>
#include <doctest/doctest.h>

using namespace yamsc;

namespace {

/// The NREL file's text with the first `from` replaced by `to`.
std::string edited(const char* name, const std::string& from, const std::string& to) {
    std::string text = beam_test::nrel_file(name)->text();
    const std::size_t at = text.find(from);
    REQUIRE(at != std::string::npos);
    return text.replace(at, from.size(), to);
}

/// 1-based line of the first occurrence of `needle`.
int line_of(const std::string& text, const std::string& needle) {
    const std::size_t at = text.find(needle);
    REQUIRE(at != std::string::npos);
    return 1 +
           static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

struct Result {
    bool ok = false;
    diag::Diagnostics diags;
};

Result tower(const std::string& text, std::vector<std::string> modes = {"fa1", "ss1"},
             double length = 87.6) {
    Result r;
    auto f = std::make_shared<diag::SourceFile>("tower.dat", text);
    r.ok = beam::read_elastodyn_tower(f, length, modes, r.diags).has_value();
    return r;
}

Result blade(const std::string& text) {
    Result r;
    auto f = std::make_shared<diag::SourceFile>("blade.dat", text);
    r.ok = beam::read_elastodyn_blade(f, 61.5, {"flap1", "edge1"}, r.diags).has_value();
    return r;
}

/// The first error: its kind and line.
void check_error(const Result& r, diag::Kind kind, int line, const std::string& words) {
    CHECK(!r.ok);
    REQUIRE(r.diags.has_errors());
    const diag::Diagnostic& d = r.diags.all()[0];
    INFO(diag::render(d));
    CHECK(d.kind == kind);
    CHECK(d.loc.line == line);
    CHECK(d.message.find(words) != std::string::npos);
}

} // namespace

TEST_CASE("tower: missing key") {
    const std::string text = edited(beam_test::kTowerFile, "AdjFASt", "AdjXXSt");
    check_error(tower(text), diag::Kind::MissingProperty, 0, "'AdjFASt'");
}

TEST_CASE("tower: non-numeric value and table entry") {
    std::string text =
        edited(beam_test::kTowerFile, "2.1963   TwFAM1Sh(3)", "2.19x3   TwFAM1Sh(3)");
    check_error(tower(text), diag::Kind::InvalidValue, line_of(text, "TwFAM1Sh(3)"), "2.19x3");
    text = edited(beam_test::kTowerFile, "5.2324300E+03", "5.2324300F+03");
    check_error(tower(text), diag::Kind::InvalidValue, line_of(text, "F+03"), "TMassDen");
}

TEST_CASE("tower: table size disagrees with NTwInpSt") {
    std::string text = edited(beam_test::kTowerFile, "11   NTwInpSt", "12   NTwInpSt");
    check_error(tower(text), diag::Kind::InvalidValue, line_of(text, "---- TOWER FORE-AFT"),
                "has 11 rows, expected 12");
    text = edited(beam_test::kTowerFile, "11   NTwInpSt", "10   NTwInpSt");
    check_error(tower(text), diag::Kind::InvalidValue, line_of(text, "1.0000000E+00  2.53627"),
                "more than the 10 rows");
}

TEST_CASE("tower: fractions must rise from 0 to 1") {
    const std::string text =
        edited(beam_test::kTowerFile, "3.0000000E-01  4.55", "1.5000000E-01  4.55");
    check_error(tower(text), diag::Kind::InvalidValue, line_of(text, "1.5000000E-01"), "HtFract");
}

TEST_CASE("tower: unknown or repeated modes, bad length") {
    const std::string text = beam_test::nrel_file(beam_test::kTowerFile)->text();
    check_error(tower(text, {"fa1", "fa3"}), diag::Kind::InvalidValue, 0, "'fa3'");
    check_error(tower(text, {"ss2", "ss2"}), diag::Kind::InvalidValue, 0, "twice");
    check_error(tower(text, {"fa1"}, -1), diag::Kind::InvalidValue, 0, "length");
    CHECK(tower(text, {}).ok); // a tower without modes is a rigid body
}

TEST_CASE("blade: a row with a missing column") {
    const std::string text =
        edited(beam_test::kBladeFile, "1.3308000E+01  4.2632100E+02", "4.2632100E+02");
    check_error(blade(text), diag::Kind::InvalidValue, line_of(text, "3.5294000E-01"),
                "5 values, expected 6");
}

TEST_CASE("blade: shape coefficients adding up to zero") {
    std::string text = beam_test::nrel_file(beam_test::kBladeFile)->text();
    for (const char* p : {"0.3627", "2.5337", "-3.5772", "2.376", "-0.6952"}) {
        const std::size_t at = text.find(std::string(" ") + p + "   BldEdgSh");
        REQUIRE(at != std::string::npos);
        text.replace(at + 1, std::string(p).size(), "0");
    }
    check_error(blade(text), diag::Kind::InvalidValue, line_of(text, "BldEdgSh(2)"), "add up to 0");
}

TEST_CASE("blade: the reader tolerates a damaged file without crashing") {
    const std::string full = beam_test::nrel_file(beam_test::kBladeFile)->text();
    // Every prefix of the file that lacks the last key: errors, never a crash.
    const std::size_t last_key = full.find("BldEdgSh(6)");
    REQUIRE(last_key != std::string::npos);
    REQUIRE(last_key > 1000); // the loop below tries a few dozen prefixes at least
    for (std::size_t n = 0; n < last_key; n += 97) {
        Result r = blade(full.substr(0, n));
        CHECK(!r.ok);
        CHECK(r.diags.has_errors());
    }
    CHECK(blade(full).ok);
}
