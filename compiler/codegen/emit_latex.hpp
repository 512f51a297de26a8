#pragma once
// The LaTeX emitter (`--lang latex`): a standalone document, compilable by
// pdflatex with amsmath only, with M and F element by element (the exact and
// the approximated forms when the model has `approx`), and, when the model has
// a `linearize` block, the operating point, M0, C0, K0, Q0 and the residual
// F(q0, q0', u0), printed like the paper's Appendix E (codegen/latex_printer.hpp).
#include "codegen/emit.hpp"
#include "ir/system.hpp"

#include <string>
#include <vector>

namespace yamsc::codegen {

struct LatexInput {
    /// The equations as compiled: M and F (approximated when the model has
    /// `approx`, exact_M and exact_F then the exact ones) and, when the operating
    /// point is declared, the unrolled Jacobians (passes::derive_jacobians).
    const ir::System* system = nullptr;
    /// The `approx` groups, as readable text ("$\theta_{t}$ to order 1").
    std::vector<std::string> approximations;
};

/// The document. Expressions too long to expand are named as such instead.
std::string emit_latex(const LatexInput& input, const EmitOptions& options);

} // namespace yamsc::codegen
