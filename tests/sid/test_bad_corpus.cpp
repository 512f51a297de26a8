// Damaged SID files: tests/sid/data/bad/ holds one file per error. Its first line (free text
// before `part`, which the reader skips) says what the first error must be:
//   expect: <line>: <kind>: <message fragment>
#include "sid_test_support.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <vector>

using namespace yamsc;

namespace {

struct Expectation {
    int line = 0;
    std::string kind;
    std::string fragment;
};

Expectation expectation_of(const std::string& text) {
    const std::string head = text.substr(0, text.find('\n'));
    REQUIRE(head.rfind("expect: ", 0) == 0);
    Expectation e;
    const std::size_t a = head.find(": ", 8);
    REQUIRE(a != std::string::npos);
    const std::size_t b = head.find(": ", a + 2);
    REQUIRE(b != std::string::npos);
    e.line = std::stoi(head.substr(8, a - 8));
    e.kind = head.substr(a + 2, b - a - 2);
    e.fragment = head.substr(b + 2);
    return e;
}

std::vector<std::filesystem::path> bad_files() {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(test::data_path("bad"))) {
        if (entry.path().extension() == ".sid") files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

} // namespace

TEST_CASE("the file the damaged ones derive from is valid") {
    const test::ReadResult r = test::read_text(test::file_text(test::data_path("minimal.sid")));
    INFO(test::brief(r.diags));
    REQUIRE(r.sid.has_value());
    CHECK(r.diags.all().empty());
    CHECK(r.sid->Ke.at0(0, 0) == 2500.0);
    CHECK(r.sid->nodes.at(0).origin.at1(0, 0, 0) == 1.0);
}

TEST_CASE("every damaged file gives its error, at its line, and no SID") {
    const std::vector<std::filesystem::path> files = bad_files();
    CHECK(files.size() >= 40);
    std::set<std::string> kinds;
    for (const std::filesystem::path& path : files) {
        const std::string text = test::file_text(path.string());
        const Expectation expected = expectation_of(text);
        const test::ReadResult r = test::read_text(text, path.filename().string());
        CAPTURE(path.filename().string());
        INFO(test::brief(r.diags));
        CHECK_FALSE(r.sid.has_value());
        const auto first =
            std::find_if(r.diags.all().begin(), r.diags.all().end(), [](const diag::Diagnostic& d) {
                return d.severity == diag::Severity::error;
            });
        REQUIRE(first != r.diags.all().end());
        CHECK(first->loc.line == expected.line);
        CHECK(diag::kind_name(first->kind) == expected.kind);
        CHECK(first->message.find(expected.fragment) != std::string::npos);
        CHECK(first->loc.file->path() == path.filename().string());
        // One error and what it entails, not a cascade.
        CHECK(r.diags.error_count() <= 3);
        kinds.insert(expected.kind);
    }
    // The corpus covers each kind of error the reader reports for a damaged file.
    CHECK(kinds == std::set<std::string>{"syntax", "invalid-value", "missing-property", "limit",
                                         "not-supported"});
}

TEST_CASE("a damaged file reports every error it holds, each at its line") {
    std::string text = test::file_text(test::data_path("minimal.sid"));
    const auto replace = [&text](const std::string& from, const std::string& to) {
        const std::size_t at = text.find(from);
        REQUIRE(at != std::string::npos);
        text.replace(at, from.size(), to);
    };
    replace("m0( 3, 1)    = 10.0", "m0( 3, 1)    10.0");     // line 18: syntax
    replace("structure    = 1", "structure    = 7");         // line 45: AP
    replace("m0( 1, 1)    = 25.0", "m0( 1, 1)    = 25.0.0"); // line 97: Me
    const test::ReadResult r = test::read_text(text);
    INFO(test::brief(r.diags));
    CHECK_FALSE(r.sid.has_value());
    REQUIRE(r.diags.error_count() == 3);
    CHECK(r.diags.all()[0].loc.line == 18);
    CHECK(r.diags.all()[0].loc.col == 18);
    CHECK(r.diags.all()[1].loc.line == 45);
    CHECK(r.diags.all()[2].loc.line == 97);
    CHECK(r.diags.all()[2].loc.col == 20);
}
