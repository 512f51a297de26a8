#include "ir/evaluate.hpp"

#include <algorithm>
#include <cmath>

namespace yamsc::ir {

std::vector<double> evaluate(const Graph& g, const std::vector<NodeId>& roots,
                             const std::function<double(SymbolRef)>& symbol_value) {
    NodeId last = 0;
    for (NodeId r : roots) last = std::max(last, r);
    std::vector<double> v(roots.empty() ? 0 : last + 1, 0.0);
    for (NodeId id = 0; id < v.size(); ++id) {
        const Node& n = g.node(id);
        const OperandSpan ops = g.operands(id);
        switch (n.kind) {
        case NodeKind::number:
            v[id] = n.value;
            break;
        case NodeKind::symbol:
            v[id] = symbol_value(n.symbol);
            break;
        case NodeKind::add: {
            double s = n.value;
            for (const Operand& op : ops) s += op.weight * v[op.node];
            v[id] = s;
            break;
        }
        case NodeKind::mul: {
            double p = n.value;
            for (const Operand& op : ops) p *= std::pow(v[op.node], op.weight);
            v[id] = p;
            break;
        }
        case NodeKind::call:
            v[id] = ir::evaluate(n.function, v[ops[0].node], ops.size() > 1 ? v[ops[1].node] : 0.0);
            break;
        }
    }
    std::vector<double> out;
    for (NodeId r : roots) out.push_back(v[r]);
    return out;
}

} // namespace yamsc::ir
