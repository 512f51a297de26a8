#pragma once
// The `constraint` declarations checked against the kinds of constraint_kinds.hpp:
// kind, roles, the frames, DOFs and expressions each names (located errors with
// suggestions), and the rows each gives.
#include "diag/diagnostics.hpp"
#include "model/expr_check.hpp"
#include "model/model.hpp"
#include "model/names.hpp"

#include <vector>

namespace yamsc::model {

/// `model`'s bodies (with their SIDs), points and DOFs are built.
std::vector<Constraint> check_constraints(const ast::ModelFile& file, const Model& model,
                                          const SymbolTable& names, ExprChecker& exprs,
                                          diag::Diagnostics& diags);

/// The rows of a checked constraint, holonomic first (names as constraint_kinds.hpp says).
std::vector<ConstraintRow> constraint_rows(const Constraint& c);

/// "file:line:col" of a constraint's declaration, for run-time messages.
std::string constraint_source(const Model& model, const Constraint& c);

} // namespace yamsc::model
