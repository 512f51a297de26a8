#pragma once
// The model functions both emitters write, in order, with their parameters:
// one per routine, plus the short mass_matrix(q, p, M) when M depends on q and
// p only (the full form then forwards to it).
#include "codegen/module.hpp"

#include <string>
#include <vector>

namespace yamsc::codegen {

struct FunctionPlan {
    const Routine* routine = nullptr;
    std::vector<const Argument*> parameters;
    bool short_form = false;        // mass_matrix(q, p, M)
    bool forwards_to_short = false; // the full mass_matrix calling the short one
    /// forwards_to_short: its parameters the short form does not take (t, u).
    std::vector<const Argument*> not_forwarded;
};

/// The API functions (internal routines excluded).
std::vector<FunctionPlan> function_plans(const Module& module);
/// The internal routines (the tangent form's helpers), file-local in the output.
std::vector<FunctionPlan> internal_function_plans(const Module& module);

std::vector<std::string> parameter_names(const FunctionPlan& plan);

/// Indices into `plans`, every routine after the routines of `plans` its steps
/// call (outputs calls rhs), in the plans' order otherwise: the order in which
/// a callee's cost is known before its callers', and the order of definition
/// where nothing is declared ahead (file-local routines). Throws
/// diag::InternalError when routines call each other in a cycle.
std::vector<std::size_t> callees_first(const std::vector<FunctionPlan>& plans);

} // namespace yamsc::codegen
