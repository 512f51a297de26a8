// The model examples of the documentation parse. Every fenced code block of README.md and
// docs/*.md carries a language tag, so the test knows what each one is:
//   ```mbd   a model or a fragment of one; it must parse without a diagnostic. A fragment (no
//            `model` line of its own) is parsed after a `model` line; a diagnostic names the
//            document's file and line.
//   anything else (```sh, ```cpp, ```text, ...) is not parsed: shell commands, C++, diagnostics
//            as printed, and examples that are wrong on purpose.
// An untagged block or an unclosed fence fails the test.
#include "parse_test_support.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>
#include <vector>

using namespace yamsc;

namespace {

struct Block {
    std::string doc;  // path relative to the source tree, e.g. "docs/language.md"
    int line = 0;     // 1-based line of the opening fence
    std::string tag;  // the first word after the backticks; empty if none
    std::string text; // the lines between the fences, each ending in '\n'
    bool closed = false;
};

std::string read_doc(const std::string& relative) {
    const std::string path = std::string(YAMSC_SOURCE_DIR) + "/" + relative;
    std::ifstream in(path, std::ios::binary);
    REQUIRE_MESSAGE(in.good(), "cannot read " << path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

/// The number of backticks a fence line starts with (after up to 3 spaces), 0 if none.
std::size_t fence_length(const std::string& line) {
    const std::size_t start = line.find_first_not_of(' ');
    if (start == std::string::npos || start > 3) return 0;
    const std::size_t end = line.find_first_not_of('`', start);
    const std::size_t n = (end == std::string::npos ? line.size() : end) - start;
    return n >= 3 ? n : 0;
}

/// The fenced code blocks of Markdown text, in order.
std::vector<Block> blocks_of(const std::string& doc, const std::string& markdown) {
    std::istringstream in(markdown);
    std::vector<Block> blocks;
    std::string line;
    int number = 0;
    std::size_t open = 0; // the opening fence's length while inside a block
    while (std::getline(in, line)) {
        ++number;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        const std::size_t fence = fence_length(line);
        if (open == 0) {
            if (fence == 0) continue;
            open = fence;
            Block b;
            b.doc = doc;
            b.line = number;
            std::istringstream info(line.substr(line.find('`') + fence));
            info >> b.tag;
            blocks.push_back(b);
        } else if (fence >= open && line.find_first_not_of("` ") == std::string::npos) {
            open = 0;
            blocks.back().closed = true;
        } else {
            blocks.back().text += line + "\n";
        }
    }
    return blocks;
}

/// The fenced code blocks of a file of the tree; an unclosed one fails the test.
std::vector<Block> code_blocks(const std::string& doc) {
    std::vector<Block> blocks = blocks_of(doc, read_doc(doc));
    for (const Block& b : blocks)
        REQUIRE_MESSAGE(b.closed, doc << ":" << b.line << ": code block never closed");
    return blocks;
}

/// README.md and docs/*.md, sorted.
std::vector<std::string> documents() {
    std::vector<std::string> docs{"README.md"};
    for (const auto& entry :
         std::filesystem::directory_iterator(std::string(YAMSC_SOURCE_DIR) + "/docs")) {
        if (entry.path().extension() == ".md")
            docs.push_back("docs/" + entry.path().filename().string());
    }
    std::sort(docs.begin() + 1, docs.end());
    return docs;
}

bool starts_with_model(const std::string& text) {
    std::istringstream in(text);
    std::string word;
    for (std::string line; std::getline(in, line);) {
        std::istringstream words(line);
        if (!(words >> word) || word[0] == '#') continue; // blank or comment line
        return word == "model";
    }
    return false;
}

/// Parses an ```mbd block as it stands in its document: the block's first line is the line after
/// the fence, so diagnostics point into the document. Fails the test (and goes on) if the block
/// has any diagnostic.
std::optional<ast::ModelFile> parse_block(const Block& b) {
    std::string text = starts_with_model(b.text) ? "" : "model doc_example";
    text += std::string(static_cast<std::size_t>(b.line), '\n') + b.text;
    diag::Diagnostics diags;
    std::optional<ast::ModelFile> file = parse::parse_model(test::make_source(text, b.doc), diags);
    INFO(b.doc << ":" << b.line << ": ```mbd block\n" << diags.render());
    CHECK(diags.all().empty());
    CHECK(file.has_value());
    return file;
}

std::vector<Block> mbd_blocks(const std::string& doc) {
    std::vector<Block> out;
    for (const Block& b : code_blocks(doc))
        if (b.tag == "mbd") out.push_back(b);
    return out;
}

} // namespace

TEST_CASE("the block reader: tags, fences, lines") {
    const std::vector<Block> blocks = blocks_of("x.md", "# Title\n"
                                                        "```mbd\n"
                                                        "model m\n"
                                                        "```\n"
                                                        "text\n"
                                                        "```\r\n"
                                                        "  ```` not a closing fence\n"
                                                        "````\n"
                                                        "```sh extra words\n"
                                                        "yamsc check m.mbd\n");
    REQUIRE(blocks.size() == 3);
    CHECK(blocks[0].line == 2);
    CHECK(blocks[0].tag == "mbd");
    CHECK(blocks[0].text == "model m\n");
    CHECK(blocks[0].closed);
    CHECK(blocks[1].line == 6);
    CHECK(blocks[1].tag.empty());
    CHECK(blocks[1].text == "  ```` not a closing fence\n");
    CHECK(blocks[1].closed);
    CHECK(blocks[2].tag == "sh");
    CHECK_FALSE(blocks[2].closed);
    CHECK(starts_with_model("# a comment\n\n  model m\n"));
    CHECK_FALSE(starts_with_model("# a comment\n\nrigid a { mass = 1 }\n"));
    CHECK(fence_length("```mbd") == 3);
    CHECK(fence_length("   ````") == 4);
    CHECK(fence_length("    ```") == 0); // indented code, not a fence
    CHECK(fence_length("``x") == 0);
}

TEST_CASE("every code block of the documentation is tagged, and every mbd block parses") {
    int mbd = 0, docs = 0;
    for (const std::string& doc : documents()) {
        ++docs;
        for (const Block& b : code_blocks(doc)) {
            CAPTURE(doc);
            CAPTURE(b.line);
            CHECK_MESSAGE(!b.tag.empty(), doc << ":" << b.line
                                              << ": code block without a language tag (```mbd, "
                                                 "```sh, ```cpp, ```text, ...)");
            if (b.tag != "mbd") continue;
            ++mbd;
            parse_block(b);
        }
    }
    CHECK(docs >= 10);
    CHECK(mbd >= 15);
}

TEST_CASE("the language reference shows every statement in an mbd block") {
    const std::vector<Block> blocks = mbd_blocks("docs/language.md");
    REQUIRE(blocks.size() >= 8); // zero blocks would mean the reader or the tags broke
    ast::ModelFile all;
    int models = 0;
    bool gravity = false;
    for (const Block& b : blocks) {
        std::optional<ast::ModelFile> parsed = parse_block(b);
        REQUIRE(parsed.has_value());
        ast::ModelFile& f = *parsed;
        models += f.model && f.model->name != "doc_example" ? 1 : 0;
        gravity = gravity || f.gravity.has_value();
        auto append = [](auto& to, auto& from) {
            std::move(from.begin(), from.end(), std::back_inserter(to));
        };
        append(all.params, f.params);
        append(all.inputs, f.inputs);
        append(all.dofs, f.dofs);
        append(all.rigid_bodies, f.rigid_bodies);
        append(all.flexible_bodies, f.flexible_bodies);
        append(all.joints, f.joints);
        append(all.points, f.points);
        append(all.forces, f.forces);
        append(all.torques, f.torques);
        append(all.springs, f.springs);
        append(all.genforces, f.genforces);
        append(all.approximations, f.approximations);
        append(all.outputs, f.outputs);
        if (f.linearize) all.linearize = std::move(f.linearize);
        if (f.initial) all.initial = std::move(f.initial);
    }
    CHECK(models == 1);
    CHECK(gravity);
    CHECK(!all.params.empty());
    CHECK(std::any_of(all.inputs.begin(), all.inputs.end(),
                      [](const ast::Input& i) { return i.order == 2; }));
    CHECK(!all.dofs.empty());
    CHECK(!all.rigid_bodies.empty());
    CHECK(all.flexible_bodies.size() == 4); // SID, ElastoDyn, inline beam, symbolic modes
    CHECK(all.joints.size() >= 5);
    CHECK(!all.points.empty());
    CHECK(!all.forces.empty());
    CHECK(!all.torques.empty());
    CHECK(!all.springs.empty());
    CHECK(!all.genforces.empty());
    CHECK(all.approximations.size() == 2);
    CHECK(!all.outputs.empty());
    REQUIRE(all.linearize.has_value());
    CHECK(all.linearize->point.size() == 3);
    REQUIRE(all.initial.has_value());
    CHECK(all.initial->state.size() == 2);
}

TEST_CASE("the tutorial's blocks, together, are models/double_pendulum.mbd") {
    std::string together;
    for (const Block& b : mbd_blocks("docs/tutorial.md")) together += b.text;
    diag::Diagnostics diags;
    const auto from_doc = parse::parse_model(test::make_source(together, "tutorial"), diags);
    INFO(diags.render());
    REQUIRE(from_doc.has_value());
    const auto from_file = parse::parse_model(
        test::make_source(read_doc("models/double_pendulum.mbd"), "double_pendulum.mbd"), diags);
    REQUIRE(from_file.has_value());
    // Equal but for the source locations (the file has a comment at its top).
    const std::regex location(" @[0-9]+:[0-9]+");
    const std::string doc_dump = std::regex_replace(ast::dump(*from_doc), location, "");
    CHECK(doc_dump.find("model double_pendulum") != std::string::npos);
    CHECK(doc_dump == std::regex_replace(ast::dump(*from_file), location, ""));
}
