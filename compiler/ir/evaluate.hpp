#pragma once
// Numeric evaluation of IR nodes (tests, checks): every node a root needs, once,
// in id order (operands come before their users).
#include "ir/graph.hpp"

#include <functional>
#include <vector>

namespace yamsc::ir {

/// The values of `roots`, with each symbol's value from `symbol_value`.
std::vector<double> evaluate(const Graph& g, const std::vector<NodeId>& roots,
                             const std::function<double(SymbolRef)>& symbol_value);

} // namespace yamsc::ir
