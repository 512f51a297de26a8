#include "codegen/routine_builder.hpp"

#include "codegen/shared_products.hpp"

#include "diag/diagnostics.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace yamsc::codegen {
namespace {

const char* symbol_kind_name(SymbolKind kind) {
    switch (kind) {
    case SymbolKind::time:
        return "t";
    case SymbolKind::q:
        return "q";
    case SymbolKind::qd:
        return "q'";
    case SymbolKind::qdd:
        return "q''";
    case SymbolKind::input:
        return "u";
    case SymbolKind::param:
        return "p";
    case SymbolKind::acceleration:
        return "a";
    case SymbolKind::seed:
        return "seed";
    case SymbolKind::multiplier:
        return "lambda";
    }
    return "?";
}

void mark_used(Routine& r, const std::string& name) {
    for (Argument& a : r.arguments)
        if (a.name == name) a.used = true;
}

} // namespace

RoutineBuilder::RoutineBuilder(const Graph& graph, std::string name, std::string summary,
                               std::vector<Argument> arguments, Binding binding)
    : graph_(graph), binding_(std::move(binding)), expr_of_node_(graph.size(), -1) {
    routine_.name = std::move(name);
    routine_.summary = std::move(summary);
    routine_.arguments = std::move(arguments);
}

void RoutineBuilder::local(std::string name, int size) {
    routine_.locals.push_back({std::move(name), size});
}

Step& RoutineBuilder::evaluate_step() {
    if (routine_.steps.empty() || routine_.steps.back().kind != StepKind::evaluate)
        routine_.steps.push_back(Step{});
    return routine_.steps.back();
}

void RoutineBuilder::assign(const std::string& array, int index, NodeId value) {
    evaluate_step();
    const int expr = import(value);
    evaluate_step().assignments.push_back({array, index, expr});
}

void RoutineBuilder::copy(const std::string& array, int index, const std::string& from,
                          int from_index) {
    evaluate_step();
    Expr load;
    load.kind = ExprKind::load;
    load.array = from;
    load.index = from_index;
    routine_.exprs.push_back(std::move(load));
    step_of_expr_.push_back(static_cast<int>(routine_.steps.size()) - 1);
    const int expr = static_cast<int>(routine_.exprs.size()) - 1;
    evaluate_step().assignments.push_back({array, index, expr});
}

void RoutineBuilder::factor(const std::string& matrix, int n) {
    Step s;
    s.kind = StepKind::factor;
    s.matrix = matrix;
    s.n = n;
    routine_.steps.push_back(std::move(s));
}

void RoutineBuilder::solve(const std::string& matrix, int n, const std::string& target, int offset,
                           int columns) {
    Step s;
    s.kind = StepKind::solve;
    s.matrix = matrix;
    s.n = n;
    s.target = target;
    s.offset = offset;
    s.columns = columns;
    routine_.steps.push_back(std::move(s));
}

void RoutineBuilder::sweep(Sweep sweep) {
    Step s;
    s.kind = StepKind::sweep;
    s.sweep = std::move(sweep);
    routine_.steps.push_back(std::move(s));
}

void RoutineBuilder::call(Call call) {
    Step s;
    s.kind = StepKind::call;
    s.call = std::move(call);
    routine_.steps.push_back(std::move(s));
}

Expr RoutineBuilder::leaf_of(const Node& symbol_node) const {
    std::optional<Expr> leaf = binding_(symbol_node.symbol);
    if (!leaf)
        throw diag::InternalError("code generation: " + routine_.name + " depends on " +
                                  symbol_kind_name(symbol_node.symbol.kind) + "[" +
                                  std::to_string(symbol_node.symbol.index) +
                                  "], for which it has no value");
    return *leaf;
}

int RoutineBuilder::import(NodeId root) {
    if (expr_of_node_.size() < graph_.size()) expr_of_node_.resize(graph_.size(), -1);
    if (expr_of_node_[root] >= 0) return expr_of_node_[root];
    const int step = static_cast<int>(routine_.steps.size()) - 1;
    struct Frame {
        NodeId node;
        std::size_t next;
    };
    // A node the routine reads ready-made (frontier_) is a leaf, like a symbol.
    auto as_leaf = [&](NodeId id) {
        if (!frontier_) return false;
        std::optional<Expr> leaf = frontier_(id);
        if (!leaf) return false;
        expr_of_node_[id] = static_cast<int>(routine_.exprs.size());
        routine_.exprs.push_back(std::move(*leaf));
        step_of_expr_.push_back(step);
        return true;
    };
    if (as_leaf(root)) return expr_of_node_[root];
    std::vector<Frame> stack{{root, 0}};
    while (!stack.empty()) {
        Frame& top = stack.back();
        const Node& n = graph_.node(top.node);
        const OperandSpan operands = graph_.operands(top.node);
        if (top.next < operands.size()) {
            const NodeId child = operands[top.next++].node;
            if (expr_of_node_[child] < 0 && !as_leaf(child)) stack.push_back({child, 0});
            continue;
        }
        Expr e;
        switch (n.kind) {
        case NodeKind::number:
            e.kind = ExprKind::number;
            break;
        case NodeKind::symbol:
            e = leaf_of(n);
            break;
        case NodeKind::add:
            e.kind = ExprKind::add;
            break;
        case NodeKind::mul:
            e.kind = ExprKind::mul;
            break;
        case NodeKind::call:
            e.kind = ExprKind::call;
            break;
        }
        if (n.kind != NodeKind::symbol) e.value = n.value;
        e.function = n.function;
        for (const Operand& op : operands)
            e.operands.push_back({expr_of_node_[op.node], op.weight});
        expr_of_node_[top.node] = static_cast<int>(routine_.exprs.size());
        routine_.exprs.push_back(std::move(e));
        step_of_expr_.push_back(step);
        stack.pop_back();
    }
    return expr_of_node_[root];
}

Routine RoutineBuilder::finish(const Options& options) && {
    std::vector<Expr>& exprs = routine_.exprs;
    share_pairs(exprs, step_of_expr_, routine_.steps);
    const std::size_t count = exprs.size();

    std::vector<int> uses(count, 0);
    for (const Expr& e : exprs)
        for (const ExprOperand& op : e.operands) ++uses[op.expr];
    for (const Step& s : routine_.steps)
        for (const Assignment& a : s.assignments) ++uses[a.expr];

    std::vector<bool> temporary(count, false);
    for (std::size_t i = 0; i < count; ++i) {
        const Expr& e = exprs[i];
        if (is_leaf(e)) continue;
        if (uses[i] > 1 || e.kind == ExprKind::call) temporary[i] = true;
        // x*x*x repeats its base: the base must be a name, not an expression.
        if (e.kind == ExprKind::mul)
            for (const ExprOperand& op : e.operands)
                if (std::fabs(op.weight) > 1.0 && !is_leaf(exprs[op.expr]))
                    temporary[op.expr] = true;
    }
    // Inline height: how deep a printed expression nests. Operands come first.
    std::vector<int> height(count, 0);
    for (std::size_t i = 0; i < count; ++i) {
        if (is_leaf(exprs[i])) continue;
        int h = 0;
        for (const ExprOperand& op : exprs[i].operands)
            if (!temporary[op.expr]) h = std::max(h, height[op.expr]);
        height[i] = h + 1;
        if (height[i] > options.max_inline_depth) temporary[i] = true;
    }

    int next_name = 0;
    for (std::size_t i = 0; i < count; ++i) {
        if (!temporary[i]) continue;
        exprs[i].temporary = next_name++;
        routine_.steps[static_cast<std::size_t>(step_of_expr_[i])].temporaries.push_back(
            static_cast<int>(i));
    }
    routine_.temporary_count = next_name;

    for (const Expr& e : exprs) {
        if (e.kind == ExprKind::load) mark_used(routine_, e.array);
        if (e.kind == ExprKind::param) mark_used(routine_, "p");
        if (e.kind == ExprKind::time) mark_used(routine_, "t");
    }
    for (const Step& s : routine_.steps) {
        for (const Assignment& a : s.assignments) mark_used(routine_, a.array);
        if (s.kind == StepKind::solve) mark_used(routine_, s.target);
        if (s.kind == StepKind::sweep) mark_used(routine_, s.sweep.target);
        const std::vector<std::string>* spellings = s.kind == StepKind::sweep  ? &s.sweep.arguments
                                                    : s.kind == StepKind::call ? &s.call.arguments
                                                                               : nullptr;
        if (spellings != nullptr)
            for (const std::string& spelling : *spellings) // "x + 2": the array is x
                mark_used(routine_, spelling.substr(0, spelling.find(' ')));
    }
    return std::move(routine_);
}

} // namespace yamsc::codegen
