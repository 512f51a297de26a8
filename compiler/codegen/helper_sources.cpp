#include "codegen/helper_sources.hpp"

#include "diag/diagnostics.hpp"
#include "embedded_helpers.hpp"

#include <algorithm>
#include <cctype>

namespace yamsc::codegen {
namespace {

bool identifier_char(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

/// The source after its opening comment (which documents the file, not the output).
std::string body_of(const char* source) {
    const std::string text(source);
    const auto end = text.find("*/\n");
    if (text.compare(0, 2, "/*") != 0 || end == std::string::npos)
        throw diag::InternalError("a helper source without its opening comment");
    return text.substr(end + 3);
}

/// Every YAMSC_LITERAL(v) replaced by v as a literal of the syntax's type.
std::string literals(const std::string& text, const Syntax& syntax) {
    static const std::string open = "YAMSC_LITERAL(";
    std::string out;
    std::size_t at = 0;
    for (;;) {
        const auto start = text.find(open, at);
        if (start == std::string::npos) return out + text.substr(at);
        const auto close = text.find(')', start);
        if (close == std::string::npos) throw diag::InternalError("helper: an open YAMSC_LITERAL");
        const std::string value = text.substr(start + open.size(), close - start - open.size());
        out += text.substr(at, start - at) + format_literal(std::stod(value), syntax);
        at = close + 1;
    }
}

} // namespace

std::string replace_identifier(const std::string& text, const std::string& word,
                               const std::string& by) {
    std::string out;
    std::size_t at = 0;
    for (;;) {
        const auto hit = text.find(word, at);
        if (hit == std::string::npos) return out + text.substr(at);
        const bool whole =
            (hit == 0 || !identifier_char(text[hit - 1])) &&
            (hit + word.size() == text.size() || !identifier_char(text[hit + word.size()]));
        out += text.substr(at, hit - at) + (whole ? by : word);
        at = hit + word.size();
    }
}

std::string ldlt_source(const Syntax& syntax, const std::string& linkage) {
    std::string text = body_of(helper_text_ldlt);
    text = replace_identifier(text, "YAMSC_LINKAGE void", linkage + "void");
    for (const char* name : {"ldlt_factor", "ldlt_solve"})
        text = replace_identifier(text, name, syntax.helper_prefix + name);
    return replace_identifier(text, "yamsc_real", syntax.real_type);
}

std::string rk4_source(const Syntax& syntax, const std::string& prefix, const std::string& api_real,
                       const std::string& params_type, int nx) {
    std::string text = body_of(helper_text_rk4);
    text = replace_identifier(text, "rk4_step", prefix + "_rk4_step");
    text = replace_identifier(text, "rhs", prefix + "_rhs");
    text = replace_identifier(text, "yamsc_api_real", api_real);
    text = replace_identifier(text, "yamsc_real", syntax.real_type);
    text = replace_identifier(text, "yamsc_params", params_type);
    text = replace_identifier(text, "YAMSC_NX_ARRAY", std::to_string(std::max(nx, 1)));
    text = replace_identifier(text, "YAMSC_NX", std::to_string(nx));
    return literals(text, syntax);
}

} // namespace yamsc::codegen
