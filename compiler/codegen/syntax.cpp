#include "codegen/syntax.hpp"

#include <fmt/format.h>

namespace yamsc::codegen {
namespace {

// Names in the order of enum Function.
constexpr std::array<const char*, function_count> base_names{
    "sin",  "cos",   "tan",   "asin",  "acos", "atan", "atan2", "sinh", "cosh",
    "tanh", "asinh", "acosh", "atanh", "exp",  "log",  "abs",   "sqrt", "pow",
};

Syntax with_prefix(const char* prefix) {
    Syntax s;
    for (int i = 0; i < function_count; ++i) s.functions[i] = std::string(prefix) + base_names[i];
    return s;
}

} // namespace

Syntax cpp_syntax() {
    Syntax s = with_prefix("std::");
    s.param_access = "p.";
    s.params_type = "const Params&";
    return s;
}

Syntax c_syntax(const std::string& prefix) {
    Syntax s = with_prefix("");
    s.functions[static_cast<int>(Function::abs)] = "fabs";
    s.param_access = "p->";
    s.helper_prefix = prefix + "_";
    s.helper_linkage = "static ";
    s.params_type = "const " + prefix + "_params*";
    return s;
}

Syntax neutral_syntax() {
    Syntax s = with_prefix("");
    s.param_access = "p.";
    return s;
}

std::string format_number(double value) {
    // fmt's default for double is the shortest representation that round-trips.
    std::string text = fmt::format("{}", value);
    if (text.find_first_of(".eEn") == std::string::npos) text += ".0";
    return text;
}

} // namespace yamsc::codegen
