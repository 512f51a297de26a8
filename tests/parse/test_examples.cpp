// Whole files: the example model's AST dump matches its golden file, and the bad-input corpus
// files of the parser report what their first line says. (The examples of the documentation:
// test_doc_blocks.cpp.)
#include "parse_test_support.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace yamsc;

namespace {

std::string read_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    REQUIRE_MESSAGE(in.good(), "cannot read " << path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

ast::ModelFile parse_ok(std::string text, std::string path) {
    diag::Diagnostics diags;
    std::optional<ast::ModelFile> file =
        parse::parse_model(test::make_source(std::move(text), std::move(path)), diags);
    INFO(diags.render());
    REQUIRE(file.has_value());
    return std::move(*file);
}

} // namespace

TEST_CASE("the AST dump of the example model matches its golden file") {
    const std::string dir = YAMSC_SOURCE_DIR "/tests/parse/";
    const ast::ModelFile f = parse_ok(read_file(dir + "example.mbd"), "example.mbd");
    const std::string dump = ast::dump(f);
    CHECK(dump == read_file(dir + "example.ast"));
    CHECK(ast::dump(parse_ok(read_file(dir + "example.mbd"), "example.mbd")) == dump);
}

TEST_CASE("the parser's bad-input corpus: one error each, where the first line says") {
    const std::filesystem::path dir = YAMSC_SOURCE_DIR "/tests/bad";
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind("syntax_", 0) != 0 && name.rfind("limit_", 0) != 0) continue;
        if (entry.path().extension() != ".mbd") continue; // X.expected: tests/cli
        ++files;
        const std::string text = read_file(entry.path());
        const std::string prefix = "# expect: ";
        REQUIRE_MESSAGE(text.rfind(prefix, 0) == 0, name << " has no '# expect:' line");
        const std::size_t end = text.find('\n');
        REQUIRE_MESSAGE(end != std::string::npos, name << " has nothing after its first line");
        const std::string expected = text.substr(prefix.size(), end - prefix.size());

        diag::Diagnostics diags;
        CHECK_FALSE(parse::parse_model(test::make_source(text, name), diags).has_value());
        CAPTURE(name);
        CHECK(diags.error_count() == 1);
        REQUIRE_FALSE(diags.all().empty());
        const std::string rendered = diag::render(diags.all().front());
        CHECK(rendered.substr(0, expected.size()) == expected);
        const diag::Kind kind =
            name.rfind("limit_", 0) == 0 ? diag::Kind::Limit : diag::Kind::Syntax;
        CHECK(diags.all().front().kind == kind);
    }
    CHECK(files >= 10);
}
