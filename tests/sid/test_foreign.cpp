// Files in the shape other tools write: a free-text header, entries in any order, symmetric and
// diagonal blocks, Fortran exponents, mixed case, tabs, CR LF, unknown blocks and keys, blocks
// left out.
#include "sid_test_support.hpp"

#include <doctest/doctest.h>

using namespace yamsc;

namespace {

std::string with_crlf(const std::string& text) {
    std::string out;
    for (const char c : text) {
        if (c == '\n') out += '\r';
        out += c;
    }
    return out;
}

/// The diagnostic whose message holds `fragment`, or nullptr.
const diag::Diagnostic* find(const diag::Diagnostics& diags, const std::string& fragment) {
    for (const diag::Diagnostic& d : diags.all()) {
        if (d.message.find(fragment) != std::string::npos) return &d;
    }
    return nullptr;
}

void check_foreign(const test::ReadResult& r) {
    INFO(test::brief(r.diags));
    REQUIRE(r.sid.has_value());
    const sid::Sid& s = *r.sid;
    CHECK(s.mass == 347460.2);
    CHECK(s.nq == 2);
    CHECK(s.mode_names ==
          std::vector<std::string>{"Eigen Mode    1 :  0.324 Hz", "Eigen Mode    2 :  0.327 Hz"});

    REQUIRE(s.nodes.size() == 2);
    const sid::Node& base = s.nodes[0];
    CHECK(base.id == 1);
    CHECK(base.rframe == "body ref");
    CHECK(base.origin.order == 0);
    CHECK(base.origin.m0 == std::vector<double>{0, 0, 0}); // no entries: all zero
    CHECK(base.psi.structure == 0);
    CHECK(base.ap.order == 1);
    CHECK(base.ap.at0(1, 1) == 1.0);
    CHECK(base.ap.at0(0, 1) == 0.0);
    CHECK(base.ap.m1 == std::vector<double>(18, 0.0));

    const sid::Node& top = s.nodes[1];
    CHECK(top.id == 2);
    CHECK(top.origin.order == 1);
    CHECK(top.origin.at0(2, 0) == 87.6);
    CHECK(top.origin.at1(0, 0, 0) == 1.0);
    CHECK(top.origin.at1(1, 0, 1) == 1.0); // given before the header of its block
    CHECK(top.origin.at1(1, 0, 0) == 0.0);
    CHECK(top.phi.at0(0, 0) == 1.0);
    CHECK(top.phi.at0(1, 1) == 1.0);
    CHECK(top.phi.at1(2, 0, 0) == -1.42e-2);
    CHECK(top.phi.at1(2, 1, 1) == -0.0139);
    CHECK(top.psi.at0(1, 0) == 0.0237);
    CHECK(top.psi.at0(0, 1) == -0.0241);
    CHECK(top.ap.order == 0);
    CHECK(top.ap.at0(2, 2) == 1.0);

    CHECK(s.md_cm.at0(2, 0) == 2.1e7);
    CHECK(s.md_cm.at1(0, 0, 0) == 7.0e4);
    CHECK(s.md_cm.at1(1, 0, 1) == 6.9e4);
    // J lists its lower triangle (structure 2): the upper one mirrors it.
    CHECK(s.J.at0(1, 0) == -2.0);
    CHECK(s.J.at0(0, 1) == -2.0);
    CHECK(s.J.at0(0, 2) == 1500.0);
    CHECK(s.J.at0(2, 2) == 2.7e6);
    CHECK(s.J.at0(1, 2) == 0.0);
    CHECK(s.Cr.at0(0, 1) == 3.3e6);
    CHECK(s.Cr.at0(1, 0) == -3.2e6);
    CHECK(s.Me.nq == 0); // as written
    CHECK(s.Me.at0(0, 1) == 12.5);
    CHECK(s.Me.at0(1, 1) == 4.1e4);
    CHECK(s.Gr.at0(0, 2) == -2.0);
    CHECK(s.Gr.at0(2, 3) == 1.5);
    CHECK(s.Oe.at0(1, 5) == 3.25);
    CHECK(s.Oe.at1(0, 0, 0) == 0.5);
    CHECK(s.Ke.structure == 1);
    CHECK(s.Ke.at0(0, 0) == 1.7e5);
    CHECK(s.Ke.at0(1, 1) == 1.8e5);
    CHECK(s.Ke.at0(0, 1) == 0.0);

    // Blocks left out: zero, of the right shape.
    CHECK(s.Ct.nrow == 2);
    CHECK(s.Ct.ncol == 3);
    CHECK(s.Ct.m0 == std::vector<double>(6, 0.0));
    CHECK(s.De.m0 == std::vector<double>(4, 0.0));
    CHECK(s.Ge.ncol == 6);
    CHECK(s.ksigma.nrow == 2);

    // What was skipped or assumed is said, where it stands.
    const diag::Diagnostic* frq = find(r.diags, "unknown block `Frq`");
    REQUIRE(frq != nullptr);
    CHECK(frq->severity == diag::Severity::warning);
    CHECK(frq->loc.line == 156);
    const diag::Diagnostic* nelem = find(r.diags, "unknown key `nelem`");
    REQUIRE(nelem != nullptr);
    CHECK(nelem->loc.line == 149);
    CHECK(nelem->loc.col == 5);
    const diag::Diagnostic* ct = find(r.diags, "no block `Ct`");
    REQUIRE(ct != nullptr);
    CHECK(ct->kind == diag::Kind::MissingProperty);
    CHECK(find(r.diags, "after `end part`") != nullptr);
    CHECK(r.diags.all().size() == 4);
    CHECK_FALSE(r.diags.has_errors());
}

} // namespace

TEST_CASE("a file in the shape other tools write reads with its values") {
    const std::string text = test::file_text(test::data_path("foreign_tool.sid"));
    REQUIRE(text.size() > 1000);
    SUBCASE("LF line ends") {
        check_foreign(test::read_text(text, "foreign_tool.sid"));
    }
    SUBCASE("CR LF line ends") {
        check_foreign(test::read_text(with_crlf(text), "foreign_tool.sid"));
    }
}

TEST_CASE("a foreign file written back and read again keeps its values") {
    const test::ReadResult first =
        test::read_text(test::file_text(test::data_path("foreign_tool.sid")));
    REQUIRE(first.sid.has_value());
    const test::ReadResult second = test::read_text(sid::write_sid(*first.sid));
    INFO(test::brief(second.diags));
    REQUIRE(second.sid.has_value());
    CHECK(*second.sid == *first.sid);
    CHECK(second.diags.all().empty());
}

TEST_CASE("numbers in the forms tools write") {
    const auto mass_of = [](const std::string& literal) {
        const test::ReadResult r = test::read_text(
            "part\nnew modal\nrefmod\nmass = " + literal +
            "\nnelastq = 0\nend refmod\nmdCM\norder = 0\nnrow = 3\nncol = 1\nstructure = 0\n"
            "end mdCM\nJ\norder = 0\nnrow = 3\nncol = 3\nstructure = 0\nend J\nMe\norder = 0\n"
            "nrow = 0\nncol = 0\nstructure = 0\nend Me\nend modal\nend part\n");
        INFO(literal << "\n" << test::brief(r.diags));
        REQUIRE(r.sid.has_value());
        return r.sid->mass;
    };
    CHECK(mass_of("12") == 12.0);
    CHECK(mass_of("+12.5") == 12.5);
    CHECK(mass_of(".5") == 0.5);
    CHECK(mass_of("5.") == 5.0);
    CHECK(mass_of("1.5e3") == 1500.0);
    CHECK(mass_of("1.5E+03") == 1500.0);
    CHECK(mass_of("3.4746020D+05") == 347460.2);
    CHECK(mass_of("2.5d-2") == 0.025);
    CHECK(mass_of("1e-400") == 0.0); // underflow reads as zero
    CHECK(mass_of("0.1") == 0.1);
}
