#include "lower/from_ginac.hpp"
#include "lower/lower.hpp"

#include <cmath>

namespace yamsc::lower {

double operation_count(const symbolic::Equations& eq, const std::vector<GiNaC::ex>& roots) {
    Graph g(4, ir::Variables{eq.nq(), eq.nu(), eq.np()});
    GinacImporter importer(g, eq);
    std::vector<bool> needed;
    for (const GiNaC::ex& e : roots) {
        const NodeId id = importer.import(e);
        if (needed.size() < g.size()) needed.resize(g.size(), false);
        needed[id] = true;
    }
    // Operands come before their users: one pass from the last node down.
    double ops = 0;
    for (std::size_t i = needed.size(); i-- > 0;) {
        if (!needed[i]) continue;
        const auto id = static_cast<NodeId>(i);
        const ir::Node& n = g.node(id);
        const ir::OperandSpan operands = g.operands(id);
        for (const ir::Operand& op : operands) needed[op.node] = true;
        const auto count = static_cast<double>(operands.size());
        switch (n.kind) {
        case ir::NodeKind::add:
            ops += count - 1 + (n.value != 0.0 ? 1 : 0);
            for (const ir::Operand& op : operands) ops += std::fabs(op.weight) != 1.0 ? 1 : 0;
            break;
        case ir::NodeKind::mul:
            ops += count - 1 + (std::fabs(n.value) != 1.0 ? 1 : 0);
            for (const ir::Operand& op : operands) ops += std::fabs(op.weight) - 1;
            break;
        case ir::NodeKind::call:
            ops += 10;
            break;
        case ir::NodeKind::number:
        case ir::NodeKind::symbol:
            break;
        }
    }
    return ops;
}

} // namespace yamsc::lower
