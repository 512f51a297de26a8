#pragma once
// How generated code factorises M and solves with it: the statements of a
// routine's factor and solve steps, their operation counts, and the solver
// functions a file defines. For a plan printed as straight-line code
// (sparse_ldlt.hpp) the file defines <prefix>mass_ldlt_factor and
// <prefix>mass_ldlt_solve for this model's pattern; otherwise (and for a
// matrix of another size) the generic loops of helpers/ldlt.inc.
#include "codegen/module.hpp"
#include "codegen/printer.hpp"
#include "codegen/sparse_ldlt.hpp"
#include "codegen/syntax.hpp"

#include <string>

namespace yamsc::codegen {

/// Whether the factor or solve `step` calls the straight-line functions of `plan`.
bool straight_line_step(const LdltPlan& plan, const Step& step);

/// The call a factor or solve step prints, with its indentation and newline.
std::string solver_statement(const LdltPlan& plan, const Step& step, const Syntax& syntax);
/// The operations of one execution of a factor or solve step.
OperationCount solver_step_count(const LdltPlan& plan, const Step& step);

/// <prefix>mass_ldlt_factor(real* A): A = L D L^T in place for the pattern of
/// `plan` (lower triangle read; L below the diagonal where M's entries are, in
/// the permuted order, the diagonal 1/D), and <prefix>mass_ldlt_solve(const
/// real* LD, real* B, int m): B := M^-1 B for an n x m row-major B. Each is
/// declared with `linkage` ("static " in C, "" inside an anonymous namespace).
std::string straight_ldlt_text(const LdltPlan& plan, const Syntax& syntax,
                               const std::string& linkage);

/// The operations of straight_ldlt_text's functions (a solve of `columns` columns).
OperationCount straight_factor_count(const LdltPlan& plan);
OperationCount straight_solve_count(const LdltPlan& plan, int columns);

} // namespace yamsc::codegen
