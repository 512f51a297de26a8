#pragma once
// The comment at the top of every generated file: where it comes from, how it
// was made, what the model's vectors hold, and what each function costs.
#include "codegen/emit.hpp"
#include "codegen/module.hpp"
#include "codegen/printer.hpp"

#include <string>
#include <vector>

namespace yamsc::codegen {

struct FunctionCost {
    std::string name;
    OperationCount count;
};

std::string header_comment(const Module& module, const EmitOptions& options,
                           const std::string& language, const std::string& namespace_name,
                           const std::vector<FunctionCost>& costs);

/// What every emitter checks before printing (an internal error otherwise:
/// the checker guarantees it): each parameter name a C identifier, the header
/// name one that survives as an #include "..." operand.
void check_printed_names(const Module& module, const EmitOptions& options);

} // namespace yamsc::codegen
