// The parser never crashes, hangs or lies on damaged input: truncations and byte mutations of a
// full model, random bytes, and pathological texts. Whenever it returns no model it has
// reported an error; whenever it returns a model it has reported none; every reported position
// lies inside the file.
#include "parse_test_support.hpp"

#include <doctest/doctest.h>

#include <fstream>
#include <random>
#include <sstream>

using namespace yamsc;

namespace {

std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    REQUIRE_MESSAGE(in.good(), "cannot read " << path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::string example() {
    return read_file(YAMSC_SOURCE_DIR "/tests/parse/example.mbd");
}

/// Parses `text` and checks the invariants; returns whether it parsed.
bool parse_checked(const std::string& text) {
    const auto source = test::make_source(text);
    diag::Diagnostics diags;
    const std::optional<ast::ModelFile> file = parse::parse_model(source, diags);
    CAPTURE(text);
    CHECK(file.has_value() == !diags.has_errors());
    CHECK(diags.error_count() <= 50);
    for (const diag::Diagnostic& d : diags.all()) {
        const bool syntax_or_limit = d.kind == diag::Kind::Syntax || d.kind == diag::Kind::Limit;
        CHECK(syntax_or_limit);
        CHECK(d.loc.file.get() == source.get());
        CHECK(d.loc.line >= 1);
        CHECK(d.loc.line <= source->line_count());
        CHECK(d.loc.col >= 1);
        CHECK(static_cast<std::size_t>(d.loc.col) <= source->line(d.loc.line).size() + 2);
        CHECK_FALSE(d.message.empty());
    }
    if (diags.has_errors()) CHECK_FALSE(diags.render().empty());
    if (file) (void)ast::dump(*file); // must not crash on whatever was parsed
    return file.has_value();
}

} // namespace

TEST_CASE("the example model parses") {
    CHECK(parse_checked(example()));
}

TEST_CASE("every truncation of the example model") {
    const std::string text = example();
    // Cutting after a complete line outside any block or parentheses leaves
    // complete statements: a valid model. Cutting inside a block `{ ... }`
    // leaves it open: never a model. (Other cuts, in a statement at the top
    // level, may leave a shorter valid one: `param g = 9.8` cut to `param g = 9`.)
    int braces = 0, parens = 0, complete = 0, open = 0;
    bool comment = false, string = false;
    for (std::size_t n = 0; n <= text.size(); ++n) {
        const bool parsed = parse_checked(text.substr(0, n));
        if (braces > 0) {
            CHECK_FALSE(parsed);
            ++open;
        } else if (parens == 0 && (n == 0 || text[n - 1] == '\n')) {
            CHECK(parsed);
            ++complete;
        }
        if (n == text.size()) break;
        const char c = text[n];
        if (comment || c == '\n') {
            comment = c != '\n';
        } else if (string) {
            string = c != '"';
        } else if (c == '#') {
            comment = true;
        } else if (c == '"') {
            string = true;
        } else {
            braces += (c == '{') - (c == '}');
            parens += (c == '(') - (c == ')');
        }
    }
    CHECK(braces == 0);
    CHECK(parens == 0);
    // Both kinds of cut, as many as example.mbd has (its lines at the top
    // level, the bytes inside its blocks).
    CHECK(complete == 57);
    CHECK(open == 990);
}

TEST_CASE("random byte mutations of the example model") {
    const std::string text = example();
    std::mt19937 rng(20240611);
    const std::string interesting =
        std::string("(){}\"'\\\n;#->^.,=:_ xyz09e") + std::string("\0\xFF\xC3\r\t", 5);
    int failures = 0;
    for (int round = 0; round < 2000; ++round) {
        std::string t = text;
        const int edits = 1 + static_cast<int>(rng() % 4);
        for (int e = 0; e < edits && !t.empty(); ++e) {
            const std::size_t at = rng() % t.size();
            switch (rng() % 4) {
            case 0:
                t[at] = interesting[rng() % interesting.size()];
                break;
            case 1:
                t[at] = static_cast<char>(rng() % 256);
                break;
            case 2:
                t.erase(at, 1 + rng() % 8);
                break;
            default:
                t.insert(at, t.substr(rng() % t.size(), 1 + rng() % 20));
                break;
            }
        }
        failures += !parse_checked(t);
    }
    CHECK(failures > 1000); // most damage is noticed
}

TEST_CASE("random bytes") {
    std::mt19937 rng(7);
    for (int round = 0; round < 1000; ++round) {
        std::string t(rng() % 200, '\0');
        for (char& c : t) c = static_cast<char>(rng() % 256);
        parse_checked(t);
    }
}

TEST_CASE("random tokens") {
    const char* tokens[] = {
        "model",  "param", "rigid", "flexible", "joint", "beam", "mode",  "modes",     "free",
        "rotate", "at",    "x",     "-",        "->",    "(",    ")",     "{",         "}",
        "=",      ",",     ";",     "\n",       "1.5",   "deg",  "q'",    "\"s\"",     "#c\n",
        ":",      "^",     "*",     "output",   "in",    "on",   "force", "linearize", "a"};
    std::mt19937 rng(99);
    for (int round = 0; round < 2000; ++round) {
        std::string t;
        const int n = static_cast<int>(rng() % 40);
        for (int i = 0; i < n; ++i) t += std::string(tokens[rng() % std::size(tokens)]) + " ";
        parse_checked(t);
    }
}

TEST_CASE("pathological inputs end with an error, not a crash or a hang") {
    CHECK_FALSE(parse_checked(std::string(100'000, '(')));
    CHECK_FALSE(parse_checked("param a = " + std::string(100'000, '(')));
    CHECK_FALSE(parse_checked("param a = " + std::string(100'000, '-') + "1"));
    CHECK_FALSE(parse_checked(std::string(100'000, '{')));
    CHECK_FALSE(parse_checked(std::string(100'000, '}')));
    CHECK_FALSE(parse_checked(std::string(100'000, '"')));
    CHECK_FALSE(parse_checked("model " + std::string(100'000, '"')));
    CHECK_FALSE(parse_checked(std::string(100'000, '\0')));
    std::string nested_blocks;
    for (int i = 0; i < 10'000; ++i) nested_blocks += "rigid a { ";
    CHECK_FALSE(parse_checked(nested_blocks));
    std::string nested_parens_lines = "param a = ";
    for (int i = 0; i < 10'000; ++i) nested_parens_lines += "(\n";
    CHECK_FALSE(parse_checked(nested_parens_lines));
    CHECK(parse_checked("param a = " + std::string(100'000, '9')));
    CHECK(parse_checked("param " + std::string(100'000, 'a')));
    CHECK(parse_checked("param a = 1e99999999999999999999"));
}

TEST_CASE("a large valid model parses") {
    std::string text;
    for (int i = 0; i < 20'000; ++i) {
        text += "param p" + std::to_string(i) + " = " + std::to_string(i) + " * (a + b)^2\n";
    }
    test::Parsed r = test::parse_text(text);
    REQUIRE(r.file.has_value());
    CHECK(r.file->params.size() == 20'000);
    CHECK(r.file->params.back().id.loc.line == 20'000);
}
