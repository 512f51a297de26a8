// The reader never crashes, throws or hangs, whatever the text: truncated and mutated files,
// and hostile ones that try to make it allocate or recurse without bound.
#include "sid_test_support.hpp"

#include <doctest/doctest.h>

#include "sid/read_context.hpp"

#include <chrono>

using namespace yamsc;

namespace {

/// Reads `text`; the result must be consistent: a SID without errors, or errors without one.
bool read_consistently(const std::string& text) {
    const test::ReadResult r = test::read_text(text);
    return r.sid.has_value() != r.diags.has_errors();
}

} // namespace

TEST_CASE("truncated and mutated files give a SID or errors, never a crash") {
    const std::string foreign = test::file_text(test::data_path("foreign_tool.sid"));
    const std::string written = sid::write_sid(test::synthetic_sid());
    int inconsistent = 0;
    int readable = 0;
    int not_written_back = 0;
    int cases = 0;
    for (const std::string* source : {&foreign, &written}) {
        const std::string& text = *source;
        const std::size_t step = text.size() / 397 + 1;
        for (std::size_t at = 0; at < text.size(); at += step) {
            const std::string truncated = text.substr(0, at);
            inconsistent += read_consistently(truncated) ? 0 : 1;
            for (const char c : {'(', ')', '=', 'x', '\n', '9', '-', '\0', '\r', ' ', 'e'}) {
                std::string mutated = text;
                mutated[at] = c;
                const test::ReadResult r = test::read_text(mutated);
                inconsistent += r.sid.has_value() == r.diags.has_errors() ? 1 : 0;
                readable += r.sid.has_value() ? 1 : 0;
                ++cases;
                if (r.sid) { // whatever the reader accepts, the writer writes back exactly
                    const test::ReadResult again = test::read_text(sid::write_sid(*r.sid));
                    not_written_back += again.sid && *again.sid == *r.sid ? 0 : 1;
                }
            }
            std::string without_line = text; // a whole line removed
            const std::size_t end = text.find('\n', at);
            const std::size_t begin = text.rfind('\n', at);
            if (end != std::string::npos && begin != std::string::npos) {
                without_line.erase(begin, end - begin);
                inconsistent += read_consistently(without_line) ? 0 : 1;
                inconsistent +=
                    read_consistently(without_line + text.substr(begin, end - begin)) ? 0 : 1;
            }
        }
    }
    CHECK(inconsistent == 0);
    CHECK(not_written_back == 0);
    CHECK(cases > 8000);
    // Some mutations are harmless (a digit in a value, a blank): the reader is not too strict.
    CHECK(readable > cases / 20);
}

TEST_CASE("hostile files hit limits, not memory or time") {
    const auto start = std::chrono::steady_clock::now();
    const std::string head = "part\nnew modal\nrefmod\nmass = 1\nnelastq = 10000\nend refmod\n";

    SUBCASE("huge blocks declared in a few lines") {
        std::string text = head;
        for (const std::string name : {"Me", "Ke", "De", "Ge"}) {
            const std::string ncol = name == "Ge" ? "30000" : "10000"; // the shapes are right
            text += name + "\norder = 1\nnrow = 10000\nncol = " + ncol +
                    "\nnq = 10000\nstructure = 3\nend " + name + "\n";
        }
        const test::ReadResult r = test::read_text(text + "end modal\nend part\n");
        CHECK_FALSE(r.sid.has_value());
        int limits = 0;
        for (const diag::Diagnostic& d : r.diags.all()) limits += d.kind == diag::Kind::Limit;
        CHECK(limits == 4); // each block refused before any allocation
    }
    SUBCASE("sizes and indices beyond any integer") {
        const test::ReadResult r = test::read_text(
            "part\nnew modal\nrefmod\nmass = 1\nnelastq = 99999999999999999999999\nend refmod\n"
            "Me\norder = 0\nnrow = -5\nncol = 18446744073709551617\nstructure = 3\n"
            "m0(99999999999999999999999, -3) = 1\nend Me\nend modal\nend part\n");
        CHECK_FALSE(r.sid.has_value());
        CHECK(r.diags.has_errors());
    }
    SUBCASE("a million lines of nested unknown blocks") {
        std::string text = "part\nnew modal\n";
        for (int i = 0; i < 200000; ++i) text += "deep\n";
        for (int i = 0; i < 200000; ++i) text += "end deep\n";
        for (int i = 0; i < 600000; ++i) text += "end nothing\n";
        const test::ReadResult r = test::read_text(text + "end modal\nend part\n");
        CHECK_FALSE(r.sid.has_value());
        CHECK(r.diags.error_count() <= sid::Limits::max_errors + 1);
    }
    SUBCASE("a million nodes") {
        std::string text = head;
        text += "new frame\n";
        for (int i = 0; i < 110000; ++i) text += "new node = " + std::to_string(i) + "\nend node\n";
        const test::ReadResult r = test::read_text(text + "end frame\nend modal\nend part\n");
        CHECK_FALSE(r.sid.has_value());
        bool limit = false;
        for (const diag::Diagnostic& d : r.diags.all()) limit |= d.kind == diag::Kind::Limit;
        CHECK(limit);
    }
    SUBCASE("blocks left out count like blocks given") {
        std::string text = "part\nnew modal\nrefmod\nmass = 1\nnelastq = 3000\nend refmod\n"
                           "mdCM\norder = 0\nnrow = 3\nncol = 1\nstructure = 0\nend mdCM\n"
                           "J\norder = 0\nnrow = 3\nncol = 3\nstructure = 0\nend J\n";
        for (const std::string name : {"Me", "Ke"}) { // 2 x 9e6 numbers: within the budget
            text +=
                name + "\norder = 0\nnrow = 3000\nncol = 3000\nstructure = 0\nend " + name + "\n";
        }
        const test::ReadResult r = test::read_text(text + "end modal\nend part\n");
        INFO(test::brief(r.diags));
        CHECK_FALSE(r.sid.has_value());
        REQUIRE(r.diags.error_count() == 1); // Ge, 3000 x 9000 zeros, is too many
        const diag::Diagnostic& e = r.diags.all().back();
        CHECK(e.kind == diag::Kind::Limit);
        CHECK(e.message.find("block `Ge`, left out, would be 3000 x 9000 zeros") == 0);
    }
    SUBCASE("binary junk") {
        std::string text = "part\n";
        for (int i = 0; i < 100000; ++i) text += static_cast<char>((i * 7919) % 256);
        CHECK(read_consistently(text));
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CHECK(seconds < 30.0);
}
