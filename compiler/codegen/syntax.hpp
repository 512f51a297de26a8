#pragma once
// Per-language tables for the expression printer: how functions, parameters and
// helpers are spelt. C++ and C share one printer; a LaTeX printer would bring
// its own layout (fractions, \cdot) but can reuse the function table's slots.
#include "codegen/graph.hpp"

#include <array>
#include <string>

namespace yamsc::codegen {

struct Syntax {
    std::array<std::string, function_count> functions; // indexed by Function
    std::string param_access;   // written before a parameter's name: "p." or "p->"
    std::string helper_prefix;  // written before the names of helper functions
    std::string helper_linkage; // "static " in C; C++ helpers live in an anonymous namespace
    std::string params_type;    // of the parameter `p`: "const Params&", "const m_params*"
};

Syntax cpp_syntax();                        // std::sin, std::pow, p.name
Syntax c_syntax(const std::string& prefix); // sin, fabs, p->name, <prefix>_ldlt_*
Syntax neutral_syntax();                    // for dump(): sin, abs, p.name

/// A double literal that reads back as exactly `value`: the shortest such
/// decimal, with ".0" when it would otherwise read as an integer.
std::string format_number(double value);

} // namespace yamsc::codegen
