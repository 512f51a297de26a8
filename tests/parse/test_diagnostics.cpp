// The diagnostics library: source lines, rendering with a caret, suggestions, kinds.
#include "diag/diagnostics.hpp"

#include <doctest/doctest.h>

#include <memory>
#include <set>

using namespace yamsc::diag;

namespace {
std::shared_ptr<const SourceFile> file(std::string text) {
    return std::make_shared<const SourceFile>("turbine.mbd", std::move(text));
}
} // namespace

TEST_CASE("SourceFile splits lines, without their newline or carriage return") {
    const auto f = file("first\r\nsecond\n\nlast");
    CHECK(f->line(1) == "first");
    CHECK(f->line(2) == "second");
    CHECK(f->line(3) == "");
    CHECK(f->line(4) == "last");
    CHECK(f->line(5) == "");
    CHECK(f->line(0) == "");
    CHECK(f->line(-3) == "");
    CHECK(f->line_count() == 4);
    CHECK(file("a\n")->line_count() == 2);
    CHECK(file("")->line_count() == 1);
}

TEST_CASE("render: file:line:col, severity, message, kind, the line and a caret") {
    const auto f = file("model m\nrigid nacele {\n");
    const Diagnostic d{Severity::error, Kind::UnknownName, Location{f, 2, 7},
                       "unknown body 'nacele' (did you mean 'nacelle'?)"};
    CHECK(render(d) == "turbine.mbd:2:7: error: unknown body 'nacele' (did you mean 'nacelle'?) "
                       "[unknown-name]\n"
                       "  rigid nacele {\n"
                       "        ^\n");
}

TEST_CASE("render: tabs are kept in the caret line so that the caret lines up") {
    const auto f = file("\tmass =\t\tx\n");
    const Diagnostic d{Severity::error, Kind::Syntax, Location{f, 1, 10}, "bad"};
    CHECK(render(d) == "turbine.mbd:1:10: error: bad [syntax]\n"
                       "  \tmass =\t\tx\n"
                       "  \t      \t\t^\n");
}

TEST_CASE("render: warnings, notes, positions past the end, no position, no file") {
    const auto f = file("dof q\n");
    CHECK(render(Diagnostic{Severity::warning, Kind::DofUsage, Location{f, 1, 5}, "unused"}) ==
          "turbine.mbd:1:5: warning: unused [dof-usage]\n  dof q\n      ^\n");
    CHECK(render(Diagnostic{Severity::note, Kind::Syntax, Location{f, 1, 1}, "declared here"}) ==
          "turbine.mbd:1:1: note: declared here\n  dof q\n  ^\n");
    // The end of the line and the (empty) line after the final newline.
    CHECK(render(Diagnostic{Severity::error, Kind::Syntax, Location{f, 1, 6}, "x"}) ==
          "turbine.mbd:1:6: error: x [syntax]\n  dof q\n       ^\n");
    CHECK(render(Diagnostic{Severity::error, Kind::Syntax, Location{f, 2, 1}, "x"}) ==
          "turbine.mbd:2:1: error: x [syntax]\n  \n  ^\n");
    CHECK(render(Diagnostic{Severity::error, Kind::Io, Location{f, 0, 0}, "cannot read"}) ==
          "turbine.mbd: error: cannot read [io]\n");
    CHECK(render(Diagnostic{Severity::error, Kind::Io, Location{}, "no input"}) ==
          "error: no input [io]\n");
    CHECK(render(Diagnostic{Severity::error, Kind::Syntax, Location{f, 9, 1}, "far"}) ==
          "turbine.mbd:9:1: error: far [syntax]\n");
}

TEST_CASE("render: control bytes and invalid UTF-8 show as '?', valid UTF-8 is kept") {
    const auto f = file(std::string("a\0\xC3\xA9\xFF z", 7));
    // bytes: a NUL c3 a9 ff ' ' z -> columns of 'z' is 7; é is one character on screen
    CHECK(render(Diagnostic{Severity::error, Kind::Syntax, Location{f, 1, 7}, "m"}) ==
          "turbine.mbd:1:7: error: m [syntax]\n  a?\xC3\xA9? z\n       ^\n");
}

TEST_CASE("render: a very long line is shown as a window around the caret") {
    std::string line(1000, 'a');
    line[600] = 'X';
    const auto f = file(line);
    const std::string out =
        render(Diagnostic{Severity::error, Kind::Syntax, Location{f, 1, 601}, "here"});
    const std::size_t first_end = out.find('\n');
    REQUIRE(first_end != std::string::npos);
    const std::size_t second = first_end + 1;
    const std::size_t second_end = out.find('\n', second);
    REQUIRE(second_end != std::string::npos);
    const std::string quoted = out.substr(second, second_end - second);
    const std::string caret = out.substr(second_end + 1);
    REQUIRE(caret.find('^') != std::string::npos);
    REQUIRE(caret.find('^') < quoted.size());
    CHECK(quoted.size() < 200);
    CHECK(quoted.substr(0, 5) == "  ...");
    CHECK(quoted.substr(quoted.size() - 3) == "...");
    CHECK(quoted[caret.find('^')] == 'X');
}

TEST_CASE("Diagnostics collects in order and counts errors only") {
    Diagnostics diags;
    CHECK_FALSE(diags.has_errors());
    diags.warning(Kind::DofUsage, Location{}, "w");
    diags.note(Location{}, "n");
    CHECK_FALSE(diags.has_errors());
    diags.error(Kind::Syntax, Location{}, "e1");
    diags.error(Kind::Limit, Location{}, "e2");
    CHECK(diags.has_errors());
    CHECK(diags.error_count() == 2);
    REQUIRE(diags.all().size() == 4);
    CHECK(diags.all()[2].message == "e1");
    CHECK(diags.render() ==
          "warning: w [dof-usage]\nnote: n\nerror: e1 [syntax]\nerror: e2 [limit]\n");
}

TEST_CASE("closest_name finds plausible misspellings only") {
    const std::vector<std::string> bodies{"nacelle", "tower", "rotor", "blade1", "blade2", "hub"};
    CHECK(closest_name("nacele", bodies) == "nacelle");   // deletion
    CHECK(closest_name("nacellle", bodies) == "nacelle"); // insertion
    CHECK(closest_name("towre", bodies) == "tower");      // transposition
    CHECK(closest_name("rotar", bodies) == "rotor");      // substitution
    CHECK(closest_name("Tower", bodies) == "tower");      // case
    CHECK(closest_name("HUB", bodies) == "hub");          // case, short name
    CHECK(closest_name("blade3", bodies) == "blade1");    // the first of equally close ones
    CHECK(closest_name("generator", bodies).empty());
    CHECK(closest_name("hb", bodies) == "hub"); // one edit in a two-letter name
    CHECK(closest_name("xy", bodies).empty());
    CHECK(closest_name("nclle", bodies).empty()); // two edits in five letters
    CHECK(closest_name("tower", bodies).empty()); // an exact match is no misspelling
    CHECK(closest_name("", bodies).empty());
    CHECK(closest_name("x", {"y"}).empty());
    CHECK(closest_name("q3", {"q1", "q2"}) == "q1");
    CHECK(closest_name("anything", {}).empty());
    CHECK(closest_name(std::string(5000, 'a'), {std::string(5000, 'a') + "b"}).empty());
}

TEST_CASE("did_you_mean") {
    CHECK(did_you_mean("rigd", {"rigid", "flexible"}) == " (did you mean 'rigid'?)");
    CHECK(did_you_mean("zzz", {"rigid", "flexible"}).empty());
}

TEST_CASE("every kind has a distinct short name") {
    const std::vector<Kind> kinds = all_kinds();
    CHECK(kinds.size() == 16);
    CHECK(kinds.front() == Kind::Syntax);
    CHECK(kinds.back() == Kind::Limit);
    std::set<std::string_view> names;
    for (const Kind k : kinds) {
        CHECK_FALSE(kind_name(k).empty());
        names.insert(kind_name(k));
    }
    CHECK(names.size() == kinds.size());
    CHECK(kind_name(Kind::UnknownName) == "unknown-name");
    CHECK(kind_name(Kind::Limit) == "limit");
}
