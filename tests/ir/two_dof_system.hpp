#pragma once
// The small System the IR tests derive from.
#include "ir/graph.hpp"
#include "ir/system.hpp"

namespace ir_test {

using namespace yamsc::ir;

/// M q'' = F for two DOFs, one input, one parameter: M = [[2, cos(q0 - q1)],
/// [cos(q0 - q1), k + 1]], F = [-k q0 q1', u q1^2], y = q0 u.
inline System two_dof_system() {
    System s;
    s.dofs = {{"a", ""}, {"b", ""}};
    s.inputs = {{"u", "u", ""}};
    s.params = {{"k", "", 2.0}};
    s.graph = Graph(4, Variables{2, 1, 1});
    Graph& g = s.graph;
    const NodeId q0 = g.symbol({SymbolKind::q, 0}), q1 = g.symbol({SymbolKind::q, 1});
    const NodeId qd1 = g.symbol({SymbolKind::qd, 1}), u = g.symbol({SymbolKind::input, 0});
    const NodeId k = g.symbol({SymbolKind::param, 0});
    const NodeId c = g.call(Function::cos, {g.add({{q0, 1.0}, {q1, -1.0}}, 0.0)});
    s.M = {{g.number(2.0), c}, {c, g.add({{k, 1.0}}, 1.0)}};
    s.F = {g.mul({{k, 1.0}, {q0, 1.0}, {qd1, 1.0}}, -1.0), g.mul({{u, 1.0}, {q1, 2.0}}, 1.0)};
    s.outputs = {{"y", "", g.mul({{q0, 1.0}, {u, 1.0}}, 1.0)}};
    return s;
}

} // namespace ir_test
