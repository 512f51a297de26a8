#pragma once
// What the C and C++ emitters share: the statements of a routine's body and
// the LDL^T solver functions both languages call.
#include "codegen/module.hpp"
#include "codegen/printer.hpp"
#include "codegen/syntax.hpp"

#include <map>
#include <string>
#include <vector>

namespace yamsc::codegen {

struct BodyText {
    std::string text;    // statements, one per line, indented by four spaces
    std::string helpers; // the part functions the body calls (see body_plan.hpp), or ""
    OperationCount count;
};

/// The body of `routine` for a function whose parameters are `signature` (a
/// subset of the routine's arguments): unused parameters are cast to void.
/// With more than `max_statements` statements (> 0; hot_part_factor times as
/// many for the routines a simulation calls every step) the work is cut into
/// part functions, returned in `helpers` to be defined before the body's
/// function.
/// Throws diag::InternalError if the body needs an argument not in `signature`.
/// The operations of one call of each internal routine, by name: what a sweep
/// over it costs per column.
using CalleeCosts = std::map<std::string, OperationCount>;

/// rhs and outputs_from_qdd are cut into parts this many times larger: a value
/// that crosses parts goes through the work array in memory, and fewer parts
/// made the 16-DOF turbine's rhs 5-7 % faster (docs/benchmarks.md), for about
/// 20 % more time compiling it.
inline constexpr int hot_part_factor = 5;

BodyText body_text(const Routine& routine, const Module& module, const Syntax& syntax,
                   const std::vector<std::string>& signature, int max_statements = 0,
                   const CalleeCosts& callee_costs = {});

/// The solver functions the module's factor and solve steps call
/// (ldlt_text.hpp), each declared with `linkage` ("static " in C, "" inside an
/// anonymous namespace): <helper_prefix>mass_ldlt_factor and _solve for the
/// module's straight-line plan, <helper_prefix>ldlt_factor and ldlt_solve for
/// the other steps; "" when no routine solves.
std::string solver_helpers_text(const Module& module, const Syntax& syntax,
                                const std::string& linkage);

} // namespace yamsc::codegen
