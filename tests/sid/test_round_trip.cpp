// The writer writes what the reader reads back exactly: read_sid(write_sid(x)) == x.
#include "sid_test_support.hpp"

#include <doctest/doctest.h>

#include <cstring>

using namespace yamsc;
using test::read_text;

namespace {

/// The lines between `name` and `end name` (the first such block).
std::string block_text(const std::string& text, const std::string& name) {
    const std::size_t begin = text.find("\n" + name + "\n");
    const std::size_t end = text.find("\nend " + name + "\n", begin);
    REQUIRE(begin != std::string::npos);
    REQUIRE(end != std::string::npos);
    return text.substr(begin, end - begin);
}

int count(const std::string& text, const std::string& what) {
    int n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) {
        ++n;
    }
    return n;
}

bool same_bits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

} // namespace

TEST_CASE("a synthetic SID with first-order terms reads back equal") {
    const sid::Sid original = test::synthetic_sid();
    const std::string text = sid::write_sid(original);
    const test::ReadResult r = read_text(text);
    INFO(test::brief(r.diags));
    REQUIRE(r.sid.has_value());
    CHECK(r.diags.all().empty()); // a written file needs no warning
    const sid::Sid& back = *r.sid;
    CHECK(back == original);

    // Spot checks of numbers that a lossy format would change.
    CHECK(back.mass == 1234.5678901234567);
    CHECK(back.mode_names[1] == "fore-aft #2 (0.32 Hz)");
    REQUIRE(back.nodes.size() == 3);
    CHECK(back.nodes[2].rframe == "tip frame");
    CHECK(back.nodes[2].has_sigma);
    CHECK_FALSE(back.nodes[0].has_sigma);
    CHECK(back.De.at0(1, 1) == 1.0 / 7.0);
    for (std::size_t i = 0; i < original.Gr.m1.size(); ++i) {
        CHECK(same_bits(back.Gr.m1[i], original.Gr.m1[i]));
    }
    CHECK(back.J.at1(0, 2, 1) == back.J.at1(2, 0, 1)); // filled from the one listed entry
    CHECK(back.Ge.nq == 0);
    CHECK(back.Ge.m1.empty());

    // Writing again gives the same text: the format is a fixed point.
    CHECK(sid::write_sid(back) == text);
}

TEST_CASE("the writer lists entries by structure") {
    const std::string text = sid::write_sid(test::synthetic_sid());
    // J is symmetric (structure 2): j <= i only, 6 of 9 entries for m0 and per mode for m1.
    const std::string j = block_text(text, "J");
    CHECK(count(j, "structure    = 2") == 1);
    CHECK(count(j, "m0(") == 6);
    CHECK(count(j, "m1(") == 12);
    CHECK(count(j, "m0(1, 2)") == 0);
    // De is diagonal (structure 1): 2 entries; ksigma is zero (structure 0): none.
    CHECK(count(block_text(text, "De"), "m0(") == 2);
    CHECK(count(block_text(text, "ksigma"), "m0(") == 0);
    // Gr is full, first order: 3 x 6 numbers and 3 x 6 x 2 first-order ones.
    CHECK(count(block_text(text, "Gr"), "m0(") == 18);
    CHECK(count(block_text(text, "Gr"), "m1(") == 36);
    CHECK(text.rfind("end modal\nend part\n") == text.size() - 19);
}

TEST_CASE("a block whose numbers break its structure is written full and still reads back") {
    sid::Sid s = test::synthetic_sid();
    s.Me.at0(0, 1) = 0.25;    // Me says structure 2, but is no longer symmetric
    s.De.at0(1, 0) = -3.0;    // De says diagonal
    s.ksigma.at0(1, 0) = 9.5; // ksigma says zero
    const std::string text = sid::write_sid(s);
    CHECK(count(block_text(text, "Me"), "structure    = 3") == 1);
    CHECK(count(block_text(text, "De"), "structure    = 3") == 1);
    CHECK(count(block_text(text, "ksigma"), "structure    = 3") == 1);
    const test::ReadResult r = read_text(text);
    INFO(test::brief(r.diags));
    REQUIRE(r.sid.has_value());
    CHECK(*r.sid == s);
    CHECK(r.sid->Me.at0(0, 1) == 0.25);
    CHECK(r.sid->Me.at0(1, 0) == s.Me.at0(1, 0));
    CHECK(r.sid->Me.structure == 3);
}

TEST_CASE("a SID without modes (a rigid body in SID form) reads back equal") {
    sid::Sid s;
    s.mass = 5.5;
    s.nq = 0;
    s.md_cm = sid::Taylor::zeros(0, 3, 1, 0);
    s.md_cm.at0(2, 0) = 11.0;
    s.J = sid::Taylor::zeros(0, 3, 3, 0, 2);
    s.J.at0(0, 0) = s.J.at0(1, 1) = 2.0;
    s.J.at0(2, 2) = 1.0;
    for (sid::Taylor* t : {&s.Ct, &s.Cr}) *t = sid::Taylor::zeros(0, 0, 3, 0, 0);
    for (sid::Taylor* t : {&s.Me, &s.Ke, &s.De, &s.Gr, &s.Ge}) *t = sid::Taylor::zeros(0, 0, 0, 0);
    s.Gr = sid::Taylor::zeros(0, 3, 0, 0, 0);
    s.Oe = sid::Taylor::zeros(0, 0, 6, 0, 0);
    s.ksigma = sid::Taylor::zeros(0, 0, 1, 0, 0);
    const test::ReadResult r = read_text(sid::write_sid(s));
    INFO(test::brief(r.diags));
    REQUIRE(r.sid.has_value());
    CHECK(*r.sid == s);
    CHECK(r.sid->md_cm.at0(2, 0) == 11.0);
    CHECK(r.sid->nodes.empty());
}

TEST_CASE("a SID written to a file reads back through read_sid_file") {
    const sid::Sid s = test::synthetic_sid();
    const std::string path = std::string(YAMSC_TEST_BINARY_DIR) + "/round_trip.sid";
    {
        std::ofstream out(path, std::ios::binary);
        out << sid::write_sid(s);
    }
    diag::Diagnostics diags;
    const std::optional<sid::Sid> back = sid::read_sid_file(path, diags);
    INFO(test::brief(diags));
    REQUIRE(back.has_value());
    CHECK(*back == s);
}

TEST_CASE("read_sid_file reports a file it cannot read as an Io error") {
    diag::Diagnostics diags;
    CHECK_FALSE(sid::read_sid_file(test::data_path("no_such_file.sid"), diags).has_value());
    REQUIRE(diags.error_count() == 1);
    CHECK(diags.all()[0].kind == diag::Kind::Io);
    CHECK(diags.all()[0].message.find("no_such_file.sid") != std::string::npos);

    diag::Diagnostics dir_diags; // a directory is not a file
    CHECK_FALSE(sid::read_sid_file(test::data_path("bad"), dir_diags).has_value());
    CHECK(dir_diags.all().at(0).kind == diag::Kind::Io);
}

TEST_CASE("the writer refuses a Taylor whose arrays do not match its size") {
    sid::Sid s = test::synthetic_sid();
    s.Me.m0.pop_back();
    CHECK_THROWS_AS(sid::write_sid(s), diag::InternalError);
}
