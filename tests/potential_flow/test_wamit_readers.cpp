// WAMIT's .1, .3 and .hst as written (the cylinder of tests/data/hydro), every
// field of a row, and the errors located at their line and column.
#include "diag/read_text.hpp"
#include "wamit/wamit.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <string>

using namespace yamsc;

namespace {

const std::string data = std::string(YAMSC_SOURCE_DIR) + "/tests/data/hydro/";

std::shared_ptr<const diag::SourceFile> text(const std::string& t) {
    return std::make_shared<const diag::SourceFile>("w.1", t);
}

std::shared_ptr<const diag::SourceFile> file(const std::string& name) {
    diag::Diagnostics diags;
    auto f = diag::read_text_file(data + name, diags);
    REQUIRE(static_cast<bool>(f));
    return f;
}

template <class Read> std::string errors_of(Read read, const std::string& t) {
    diag::Diagnostics diags;
    const auto out = read(text(t), diags);
    CHECK(!out);
    return diags.render();
}

} // namespace

TEST_CASE("a .1 row: period, modes, added mass and damping; the limits' rows carry A alone") {
    diag::Diagnostics diags;
    const auto r = wamit::read_radiation(
        text("-1 1 1 3.9E3\n  0.0, 1, 5, -9.8D4\n\n 6.2831853 2 4 9.5 0.25\n"), diags);
    REQUIRE(r);
    REQUIRE(r->rows.size() == 3);
    CHECK(r->rows[0].period == -1);
    CHECK(r->rows[0].i == 1);
    CHECK(r->rows[0].j == 1);
    CHECK(r->rows[0].added_mass == 3900);
    CHECK(!r->rows[0].damping);
    CHECK(r->rows[1].period == 0);
    CHECK(r->rows[1].j == 5);
    CHECK(r->rows[1].added_mass == -9.8e4);
    CHECK(r->rows[1].line == 2);
    CHECK(r->rows[2].period == doctest::Approx(6.2831853));
    CHECK(r->rows[2].i == 2);
    CHECK(r->rows[2].j == 4);
    CHECK(r->rows[2].added_mass == 9.5);
    CHECK(*r->rows[2].damping == 0.25);
    CHECK(r->rows[2].line == 4);
}

TEST_CASE("a .3 row: period, heading, mode, modulus, phase, real and imaginary parts") {
    diag::Diagnostics diags;
    const auto x = wamit::read_excitation(text("12.5 -90.0 3 2.0 -45.0 1.4142 -1.4142\n"), diags);
    REQUIRE(x);
    REQUIRE(x->rows.size() == 1);
    const wamit::ExcitationRow& e = x->rows[0];
    CHECK(e.period == 12.5);
    CHECK(e.heading == -90);
    CHECK(e.i == 3);
    CHECK(e.modulus == 2);
    CHECK(e.phase == -45);
    CHECK(e.re == 1.4142);
    CHECK(e.im == -1.4142);
    CHECK(e.line == 1);
}

TEST_CASE("a .hst row: modes and restoring") {
    diag::Diagnostics diags;
    const auto h = wamit::read_hydrostatics(text("3 3 78.5\n5\t5\t-9.8E4\n"), diags);
    REQUIRE(h);
    REQUIRE(h->rows.size() == 2);
    CHECK(h->rows[1].i == 5);
    CHECK(h->rows[1].j == 5);
    CHECK(h->rows[1].restoring == -9.8e4);
    CHECK(h->rows[1].line == 2);
}

TEST_CASE("the cylinder's files read whole") {
    diag::Diagnostics diags;
    const auto r = wamit::read_radiation(file("cylinder.1"), diags);
    const auto x = wamit::read_excitation(file("cylinder.3"), diags);
    const auto h = wamit::read_hydrostatics(file("cylinder.hst"), diags);
    REQUIRE(r);
    REQUIRE(x);
    REQUIRE(h);
    CHECK(r->rows.size() == 738);  // 9 entries x (2 limits + 80 periods)
    CHECK(x->rows.size() == 1840); // 80 periods x 5 headings x 4 or 5 modes
    CHECK(h->rows.size() == 36);
    CHECK(r->rows[0].added_mass == doctest::Approx(M_PI * 25 * 50).epsilon(1e-6));
    CHECK(h->rows[14].restoring == doctest::Approx(M_PI * 25).epsilon(1e-6));
}

TEST_CASE("errors at their line and column") {
    const auto rad = [](auto f, diag::Diagnostics& d) { return wamit::read_radiation(f, d); };
    const auto exc = [](auto f, diag::Diagnostics& d) { return wamit::read_excitation(f, d); };
    const auto hst = [](auto f, diag::Diagnostics& d) { return wamit::read_hydrostatics(f, d); };
    CHECK(errors_of(rad, "-1 1 1 2\n5.0 1 1 x 2\n").find("w.1:2:9: error: 'x' is not a number") !=
          std::string::npos);
    CHECK(errors_of(rad, "5.0 1 1 2\n")
              .find("w.1:1:9: error: a row of a positive period needs "
                    "its damping") != std::string::npos);
    CHECK(errors_of(rad, "5.0 1 1 2 3 4\n").find("w.1:1:13: error: a row of a WAMIT .1 file") !=
          std::string::npos);
    CHECK(errors_of(rad, "5.0 1 1\n").find("w.1:1:8: error:") != std::string::npos);
    CHECK(errors_of(rad, "5.0 0 1 2 3\n")
              .find("w.1:1:5: error: a mode index must be a whole "
                    "number from 1 to 600, not '0'") != std::string::npos);
    CHECK(errors_of(rad, "5.0 1 1.5 2 3\n").find("w.1:1:7: error: a mode index") !=
          std::string::npos);
    CHECK(errors_of(rad, "5.0 1 1e300 2 3\n").find("w.1:1:7:") != std::string::npos);
    CHECK(errors_of(rad, "\n  \n").find("w.1:1:1: error: the WAMIT .1 file") != std::string::npos);
    CHECK(errors_of(exc, "0 0 1 1 0 1 0\n")
              .find("w.1:1:1: error: a .3 row needs a positive "
                    "period") != std::string::npos);
    CHECK(errors_of(exc, "5 0 1 1 0 1\n").find("has 7 values, found 6") != std::string::npos);
    CHECK(errors_of(hst, "1 1 nan\n").find("w.1:1:5: error: 'nan' is not a number") !=
          std::string::npos);
    CHECK(errors_of(hst, "1 601 1\n").find("w.1:1:3: error: a mode index") != std::string::npos);
}
