#pragma once
// Per-language tables for the expression printer: how functions, parameters and
// helpers are spelt. C++ and C share one printer; a LaTeX printer would bring
// its own layout (fractions, \cdot) but can reuse the function table's slots.
#include "ir/function.hpp"

#include <array>
#include <stdexcept>
#include <string>

namespace yamsc::codegen {

using ir::Function;
using ir::function_count;

struct Syntax {
    std::array<std::string, function_count> functions; // indexed by Function
    std::string param_access;   // written before a parameter's name: "p." or "p->"
    std::string helper_prefix;  // written before the names of helper functions
    std::string helper_linkage; // "static " in C; C++ helpers live in an anonymous namespace
    std::string params_type;    // of the parameter `p`: "const Params&", "const m_params*"
    /// The arithmetic of the code: C with --real float computes in single
    /// precision, with float literals (`9.81f`) and the float functions (`sinf`).
    bool single_precision = false;
    std::string real_type = "double"; // the C type of temporaries and local arrays
};

Syntax cpp_syntax(); // std::sin, std::pow, p.name
/// sin, fabs, p->name, <prefix>_ldlt_*; with single_precision sinf, fabsf, float.
Syntax c_syntax(const std::string& prefix, bool single_precision = false);
Syntax neutral_syntax(); // for dump(): sin, abs, p.name

/// A constant of the model that the code's floating-point type cannot hold
/// (a float overflows above 3.4e38). A user error, not a bug: the message says
/// which number and what to do.
struct NumberOutOfRange : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// A double literal that reads back as exactly `value`: the shortest such
/// decimal, with ".0" when it would otherwise read as an integer.
std::string format_number(double value);

/// A float literal (`9.81f`): the shortest decimal that reads back as the
/// float nearest to `value`, with the `f` suffix (a signed zero below the
/// smallest float, 1.4e-45). Throws NumberOutOfRange when it would be infinite.
std::string format_float(double value);

/// `value` as a literal of the syntax's floating-point type.
std::string format_literal(double value, const Syntax& syntax);

} // namespace yamsc::codegen
