#pragma once
// What the C and C++ emitters share: the statements of a routine's body and
// the fixed-size LDL^T solver both languages call.
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
/// With more than `max_statements` statements (> 0) the work is cut into part
/// functions, returned in `helpers` to be defined before the body's function.
/// Throws diag::InternalError if the body needs an argument not in `signature`.
/// The operations of one call of each internal routine, by name: what a sweep
/// over it costs per column.
using CalleeCosts = std::map<std::string, OperationCount>;

BodyText body_text(const Routine& routine, const ModelInfo& model, const Syntax& syntax,
                   const std::vector<std::string>& signature, int max_statements = 0,
                   const CalleeCosts& callee_costs = {});

/// True when some routine factorises or solves (then the helpers must be emitted).
bool uses_solver(const Module& module);

/// Definitions of <helper_prefix>ldlt_factor and <helper_prefix>ldlt_solve, each
/// declared with `linkage` ("static " in C, "" inside an anonymous namespace).
std::string solver_helpers_text(const Syntax& syntax, const std::string& linkage);

} // namespace yamsc::codegen
