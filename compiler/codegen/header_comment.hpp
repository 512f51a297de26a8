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

/// Rejects names that would not survive as an #include "..." operand.
void check_header_name(const std::string& name);

} // namespace yamsc::codegen
