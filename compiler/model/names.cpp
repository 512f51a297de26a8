#include "model/names.hpp"

#include "ast/keywords.hpp"

#include <array>
#include <set>

namespace yamsc::model {
namespace {

// The model language's keywords and predefined names (ast/keywords.cpp: one list
// for the parser's suggestions and for this check).
const std::set<std::string, std::less<>>& language_words() {
    static const std::set<std::string, std::less<>> words = [] {
        std::set<std::string, std::less<>> all(ast::language_keywords().begin(),
                                               ast::language_keywords().end());
        all.insert(ast::predefined_names().begin(), ast::predefined_names().end());
        return all;
    }();
    return words;
}

// C and C++ keywords and alternative tokens (C++20 included), and the standard
// library names generated code relies on.
const std::set<std::string, std::less<>>& c_cpp_keywords() {
    static const std::set<std::string, std::less<>> words = {"alignas",
                                                             "alignof",
                                                             "and",
                                                             "and_eq",
                                                             "asm",
                                                             "atomic_cancel",
                                                             "atomic_commit",
                                                             "atomic_noexcept",
                                                             "auto",
                                                             "bitand",
                                                             "bitor",
                                                             "bool",
                                                             "break",
                                                             "case",
                                                             "catch",
                                                             "char",
                                                             "char8_t",
                                                             "char16_t",
                                                             "char32_t",
                                                             "class",
                                                             "compl",
                                                             "concept",
                                                             "const",
                                                             "consteval",
                                                             "constexpr",
                                                             "constinit",
                                                             "const_cast",
                                                             "continue",
                                                             "co_await",
                                                             "co_return",
                                                             "co_yield",
                                                             "decltype",
                                                             "default",
                                                             "delete",
                                                             "do",
                                                             "double",
                                                             "dynamic_cast",
                                                             "else",
                                                             "enum",
                                                             "explicit",
                                                             "export",
                                                             "extern",
                                                             "false",
                                                             "float",
                                                             "for",
                                                             "friend",
                                                             "goto",
                                                             "if",
                                                             "inline",
                                                             "int",
                                                             "long",
                                                             "mutable",
                                                             "namespace",
                                                             "new",
                                                             "noexcept",
                                                             "not",
                                                             "not_eq",
                                                             "nullptr",
                                                             "operator",
                                                             "or",
                                                             "or_eq",
                                                             "private",
                                                             "protected",
                                                             "public",
                                                             "reflexpr",
                                                             "register",
                                                             "reinterpret_cast",
                                                             "requires",
                                                             "restrict",
                                                             "return",
                                                             "short",
                                                             "signed",
                                                             "sizeof",
                                                             "static",
                                                             "static_assert",
                                                             "static_cast",
                                                             "struct",
                                                             "switch",
                                                             "synchronized",
                                                             "template",
                                                             "this",
                                                             "thread_local",
                                                             "throw",
                                                             "true",
                                                             "try",
                                                             "typedef",
                                                             "typeid",
                                                             "typename",
                                                             "union",
                                                             "unsigned",
                                                             "using",
                                                             "virtual",
                                                             "void",
                                                             "volatile",
                                                             "wchar_t",
                                                             "while",
                                                             "xor",
                                                             "xor_eq",
                                                             "_Alignas",
                                                             "_Alignof",
                                                             "_Atomic",
                                                             "_Bool",
                                                             "_Complex",
                                                             "_Generic",
                                                             "_Imaginary",
                                                             "_Noreturn",
                                                             "_Static_assert",
                                                             "_Thread_local",
                                                             "std",
                                                             "main",
                                                             "NULL",
                                                             "errno",
                                                             "assert",
                                                             "offsetof"};
    return words;
}

// Object-like macros of <math.h>/<cmath> that would replace a struct field name.
const std::set<std::string, std::less<>>& math_macros() {
    static const std::set<std::string, std::less<>> words = {
        "NAN",          "INFINITY",       "HUGE_VAL",
        "HUGE_VALF",    "HUGE_VALL",      "FP_NAN",
        "FP_INFINITE",  "FP_ZERO",        "FP_SUBNORMAL",
        "FP_NORMAL",    "FP_FAST_FMA",    "FP_FAST_FMAF",
        "FP_FAST_FMAL", "FP_ILOGB0",      "FP_ILOGBNAN",
        "MATH_ERRNO",   "MATH_ERREXCEPT", "math_errhandling",
        "M_E",          "M_LOG2E",        "M_LOG10E",
        "M_LN2",        "M_LN10",         "M_PI",
        "M_PI_2",       "M_PI_4",         "M_1_PI",
        "M_2_PI",       "M_2_SQRTPI",     "M_SQRT2",
        "M_SQRT1_2",    "DOMAIN",         "SING",
        "OVERFLOW",     "UNDERFLOW",      "TLOSS",
        "PLOSS",        "X_TLOSS"};
    return words;
}

} // namespace

std::string reserved_reason(std::string_view name) {
    if (language_words().count(name)) return "is a keyword of the model language";
    if (c_cpp_keywords().count(name)) return "is a C or C++ keyword or reserved name";
    if (math_macros().count(name)) return "is a macro of the C math library";
    if (function_arity(name) >= 0) return "is a function of the model language";
    if (name.size() >= 2 && name[0] == '_' &&
        (name[1] == '_' || (name[1] >= 'A' && name[1] <= 'Z')))
        return "is reserved for the C/C++ implementation (leading underscore)";
    if (name.find("__") != std::string_view::npos)
        return "is reserved for the C/C++ implementation (double underscore)";
    return "";
}

int function_arity(std::string_view name) {
    static const std::array<std::string_view, 10> unary = {"sin",  "cos",  "tan", "asin", "acos",
                                                           "atan", "sqrt", "exp", "log",  "abs"};
    for (auto f : unary)
        if (f == name) return 1;
    if (name == "atan2") return 2;
    return -1;
}

bool is_kinematic_function(std::string_view name) {
    return name == "position" || name == "velocity" || name == "angular_velocity" ||
           is_reaction_function(name);
}

bool is_reaction_function(std::string_view name) {
    return name == "reaction_force" || name == "reaction_moment";
}

} // namespace yamsc::model
