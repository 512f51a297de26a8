#include "lower/from_ginac.hpp"

#include "diag/diagnostics.hpp"

#include <array>
#include <string>
#include <string_view>
#include <utility>

namespace yamsc::lower {

using ir::Operand;
using ir::SymbolKind;

namespace {

const GiNaC::basic* identity(const GiNaC::ex& e) {
    return &GiNaC::ex_to<GiNaC::basic>(e);
}

// The pairs of a sum or product as GiNaC stores them. Its op(i) would rebuild
// each pair as a new, evaluated mul or power: costly (evaluation normalises the
// content of sums) and of no use to a walk by identity. A pointer to a
// protected member formed in a derived class is standard C++ and may be
// applied to any object of the base class.
struct PairsOf : GiNaC::expairseq {
    static const GiNaC::epvector& pairs(const GiNaC::expairseq& e) { return e.*(&PairsOf::seq); }
    static const GiNaC::ex& numeric_part(const GiNaC::expairseq& e) {
        return e.*(&PairsOf::overall_coeff);
    }
};

[[noreturn]] void unsupported(const std::string& what) {
    throw diag::InternalError("import of the equations: " + what);
}

double real_value(const GiNaC::numeric& n) {
    if (!n.is_real()) unsupported("a complex number in the equations");
    return n.to_double();
}

} // namespace

// One node being imported: its operands to import first (with the weight they
// carry in a sum or product) and the numeric part folded out of them.
struct GinacImporter::Frame {
    GiNaC::ex e;
    std::size_t first = 0; // its operands: pending_[first, first + count)
    std::size_t count = 0;
    std::size_t next = 0;
    double scalar = 0.0; // add: constant term; mul: coefficient
    bool expanded = false;
};

GinacImporter::GinacImporter(Graph& graph, const symbolic::Equations& eq) : graph_(graph) {
    auto add = [this](const GiNaC::symbol& s, SymbolKind kind, int index) {
        symbols_.emplace(GiNaC::ex(s), SymbolRef{kind, index});
    };
    add(eq.t, SymbolKind::time, 0);
    for (std::size_t i = 0; i < eq.dofs.size(); ++i) {
        const int k = static_cast<int>(i);
        add(eq.dofs[i].q, SymbolKind::q, k);
        add(eq.dofs[i].qd, SymbolKind::qd, k);
        add(eq.dofs[i].qdd, SymbolKind::qdd, k);
    }
    for (std::size_t i = 0; i < eq.inputs.size(); ++i)
        add(eq.inputs[i].sym, SymbolKind::input, static_cast<int>(i));
    for (std::size_t i = 0; i < eq.params.size(); ++i)
        add(eq.params[i].sym, SymbolKind::param, static_cast<int>(i));
    for (std::size_t i = 0; i < eq.a.size(); ++i)
        add(eq.a[i], SymbolKind::acceleration, static_cast<int>(i));
}

NodeId GinacImporter::memoised(const GiNaC::ex& e) const {
    const NodeId* id = memo_.find(identity(e));
    if (id == nullptr) throw diag::InternalError("import: an operand was not imported");
    return *id;
}

// `e` is a copy on purpose: GiNaC's comparisons (here, the symbol table's) make
// equal expressions share one object by re-pointing the handles compared, which
// would change the identity of the caller's handle.
NodeId GinacImporter::leaf(GiNaC::ex e) {
    if (GiNaC::is_a<GiNaC::numeric>(e))
        return graph_.number(real_value(GiNaC::ex_to<GiNaC::numeric>(e)));
    if (GiNaC::is_a<GiNaC::constant>(e)) {
        const GiNaC::ex value = GiNaC::ex_to<GiNaC::constant>(e).evalf();
        if (!GiNaC::is_a<GiNaC::numeric>(value)) unsupported("a constant without a value");
        return graph_.number(real_value(GiNaC::ex_to<GiNaC::numeric>(value)));
    }
    const auto it = symbols_.find(e);
    if (it == symbols_.end())
        unsupported("the symbol '" + GiNaC::ex_to<GiNaC::symbol>(e).get_name() +
                    "' is not one of the model's");
    return graph_.symbol(it->second);
}

void GinacImporter::expand(Frame& frame) {
    const GiNaC::ex& e = frame.e;
    frame.first = pending_.size();
    if (GiNaC::is_exactly_a<GiNaC::add>(e) || GiNaC::is_exactly_a<GiNaC::mul>(e)) {
        // Terms (rest, coefficient) of a sum, factors (rest, exponent) of a product.
        const auto& sequence = GiNaC::ex_to<GiNaC::expairseq>(e);
        for (const GiNaC::expair& pair : PairsOf::pairs(sequence))
            pending_.emplace_back(pair.rest, real_value(GiNaC::ex_to<GiNaC::numeric>(pair.coeff)));
        frame.scalar = real_value(GiNaC::ex_to<GiNaC::numeric>(PairsOf::numeric_part(sequence)));
    } else if (GiNaC::is_exactly_a<GiNaC::power>(e)) {
        pending_.emplace_back(e.op(0), 1.0);
        pending_.emplace_back(e.op(1), 1.0);
    } else if (GiNaC::is_a<GiNaC::function>(e)) {
        const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
        if (!ir::model_function(name, e.nops()))
            unsupported("the function '" + name + "' has no counterpart in generated code");
        for (std::size_t i = 0; i < e.nops(); ++i) pending_.emplace_back(e.op(i), 1.0);
    } else {
        unsupported(std::string("an expression of class '") +
                    GiNaC::ex_to<GiNaC::basic>(e).class_name() + "' in the equations");
    }
    frame.count = pending_.size() - frame.first;
}

NodeId GinacImporter::build(const Frame& frame) {
    const GiNaC::ex& e = frame.e;
    std::vector<Operand> operands;
    operands.reserve(frame.count);
    for (std::size_t i = frame.first; i < frame.first + frame.count; ++i)
        operands.push_back({memoised(pending_[i].first), pending_[i].second});
    if (GiNaC::is_exactly_a<GiNaC::add>(e)) return graph_.add(std::move(operands), frame.scalar);
    if (GiNaC::is_exactly_a<GiNaC::mul>(e)) return graph_.mul(std::move(operands), frame.scalar);
    if (GiNaC::is_exactly_a<GiNaC::power>(e))
        return graph_.power(operands[0].node, operands[1].node);
    const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    std::vector<NodeId> arguments;
    for (const Operand& op : operands) arguments.push_back(op.node);
    if (const auto f = ir::model_function(name, arguments.size()))
        return graph_.call(*f, arguments);
    unsupported("the function '" + name + "'"); // expand() has already rejected it
}

NodeId GinacImporter::import(const GiNaC::ex& root) {
    pending_.clear(); // after an exception, an earlier walk may have left some
    std::vector<Frame> stack;
    stack.push_back(Frame{root});
    while (!stack.empty()) {
        Frame& top = stack.back();
        if (!top.expanded) {
            if (memo_.find(identity(top.e)) != nullptr) {
                stack.pop_back(); // reached twice before it was numbered
                continue;
            }
            const bool is_leaf = GiNaC::is_a<GiNaC::numeric>(top.e) ||
                                 GiNaC::is_a<GiNaC::constant>(top.e) ||
                                 GiNaC::is_a<GiNaC::symbol>(top.e);
            if (is_leaf) {
                remember(top.e, leaf(top.e));
                stack.pop_back();
                continue;
            }
            expand(top);
            top.expanded = true;
        }
        if (top.next < top.count) {
            const GiNaC::ex& operand = pending_[top.first + top.next++].first;
            if (memo_.find(identity(operand)) == nullptr) {
                GiNaC::ex copy = operand; // push_back may move `top` and `pending_`
                stack.push_back(Frame{std::move(copy)});
            }
            continue;
        }
        remember(top.e, build(top));
        pending_.resize(top.first);
        stack.pop_back();
    }
    return memoised(root);
}

void GinacImporter::remember(const GiNaC::ex& e, NodeId id) {
    memo_.insert(identity(e), id);
    keep_alive_.push_back(e); // the address stays this node's while we may look it up
}

} // namespace yamsc::lower
