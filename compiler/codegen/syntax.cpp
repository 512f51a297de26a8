#include "codegen/syntax.hpp"

#include "text/number.hpp"

#include <cfloat>
#include <cmath>

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

Syntax c_syntax(const std::string& prefix, bool single_precision) {
    Syntax s = with_prefix("");
    s.functions[static_cast<int>(Function::abs)] = "fabs";
    if (single_precision) {
        // C99's float functions: sinf, fabsf, powf, ...; a call of the double
        // one would compute in double and convert back.
        for (std::string& f : s.functions) f += "f";
        s.single_precision = true;
        s.real_type = "float";
    }
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
    // Plain notation up to 1e16, then exponent notation (fmt's and Python's layout).
    std::string text = text::shortest_general(value);
    if (text.find_first_of(".eEn") == std::string::npos) text += ".0";
    return text;
}

std::string format_float(double value) {
    // Checked before the conversion: a double beyond the float range has no
    // float value to convert to, and clamping it to FLT_MAX would silently
    // compute another model.
    if (!std::isfinite(value) || std::fabs(value) > FLT_MAX)
        throw NumberOutOfRange("the number " + format_number(value) +
                               " does not fit in a float (at most 3.4e38 in magnitude): "
                               "compile with --real double");
    // A nonzero constant below the smallest float (1.4e-45) becomes a signed
    // zero, as float arithmetic would round the term anyway: times any float
    // it is below 5e-7, and in practice such constants are round-off of the
    // model's data (4e-54 in the floating template's forcing).
    const auto single = static_cast<float>(value);
    // The shortest text that reads back as the same float, so 9.81 prints as
    // 9.81, not as the double 9.8100004196166992.
    std::string text = text::shortest_general(single);
    if (text.find_first_of(".eE") == std::string::npos) text += ".0";
    return text + "f";
}

std::string format_literal(double value, const Syntax& syntax) {
    return syntax.single_precision ? format_float(value) : format_number(value);
}

} // namespace yamsc::codegen
