#pragma once
// Reading test texts: the data files, edits of them, and the diagnostics a reader
// reports, each with its line and column.
#include "diag/diagnostics.hpp"
#include "diag/read_text.hpp"

#include <doctest/doctest.h>

#include <memory>
#include <string>
#include <vector>

namespace hydro_test {

inline const std::string data_dir = std::string(YAMSC_SOURCE_DIR) + "/tests/data/hydro/";

inline std::string file_text(const std::string& name) {
    yamsc::diag::Diagnostics diags;
    const auto f = yamsc::diag::read_text_file(data_dir + name, diags);
    REQUIRE(f);
    return f->text();
}

/// `text` with the first `what` replaced by `with` (which must be there).
inline std::string replaced(std::string text, const std::string& what, const std::string& with) {
    const auto at = text.find(what);
    REQUIRE_MESSAGE(at != std::string::npos, what);
    return text.replace(at, what.size(), with);
}

/// The 1-based line of the first line of `text` holding `what`.
inline int line_of(const std::string& text, const std::string& what) {
    const auto at = text.find(what);
    REQUIRE_MESSAGE(at != std::string::npos, what);
    int line = 1;
    for (std::size_t i = 0; i < at; ++i) line += text[i] == '\n';
    return line;
}

/// The 1-based column of `what` in the first line holding `what`.
inline int col_of(const std::string& text, const std::string& what) {
    const auto at = text.find(what);
    REQUIRE_MESSAGE(at != std::string::npos, what);
    const auto start = text.rfind('\n', at);
    return static_cast<int>(at - (start == std::string::npos ? 0 : start + 1)) + 1;
}

/// The diagnostics of one severity, in order.
inline std::vector<yamsc::diag::Diagnostic> of(const yamsc::diag::Diagnostics& d,
                                               yamsc::diag::Severity s) {
    std::vector<yamsc::diag::Diagnostic> out;
    for (const auto& x : d.all())
        if (x.severity == s) out.push_back(x);
    return out;
}

} // namespace hydro_test
