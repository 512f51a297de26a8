#pragma once
// The LaTeX emitter (`--lang latex`): a standalone document, compilable by
// pdflatex with amsmath only, with M and F element by element (the exact and
// the approximated forms when the model has `approx`), and, when the model has
// a `linearize` block, the operating point, M0, C0, K0, Q0 and the residual
// F(q0, q0', u0), printed like the paper's Appendix E (codegen/latex_printer.hpp).
#include "codegen/emit.hpp"
#include "symbolic/equations.hpp"
#include "symbolic/linearize.hpp"

#include <string>
#include <vector>

namespace yamsc::codegen {

struct LatexInput {
    /// The equations as compiled, with their Jacobians (approximated when the
    /// model has `approx`).
    const symbolic::Equations* equations = nullptr;
    /// The exact M and F when `equations` are approximated; null otherwise.
    const symbolic::Equations* exact = nullptr;
    /// The `approx` groups, as readable text ("$\theta_{t}$ to order 1").
    std::vector<std::string> approximations;
    /// The operating point; the linear model is printed when it was declared.
    const symbolic::OperatingPoint* point = nullptr;
};

/// The document. Expressions too long to expand are named as such instead.
std::string emit_latex(const LatexInput& input, const EmitOptions& options);

} // namespace yamsc::codegen
