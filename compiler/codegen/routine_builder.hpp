#pragma once
// Builds one Routine from nodes of the canonical Graph: collects the nodes its
// outputs need (children before parents, in an order that depends on structure
// only), binds symbols to the routine's arguments, and chooses the temporaries
// (common subexpression elimination over everything the routine computes).
#include "codegen/module.hpp"
#include "ir/graph.hpp"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace yamsc::codegen {

class RoutineBuilder {
public:
    /// The leaf (a load, a parameter or t) a symbol stands for in this routine, or
    /// nullopt when the routine has no value for it.
    using Binding = std::function<std::optional<Expr>(SymbolRef)>;

    RoutineBuilder(const Graph& graph, std::string name, std::string summary,
                   std::vector<Argument> arguments, Binding binding);

    /// What the routine is called, what it computes, and its arguments.
    struct Signature {
        std::string name;
        std::string summary;
        std::vector<Argument> arguments;
        std::optional<RoutineId> id = std::nullopt; // a routine of the API (routines.hpp)
    };
    RoutineBuilder(const Graph& graph, Signature signature, Binding binding)
        : RoutineBuilder(graph, std::move(signature.name), std::move(signature.summary),
                         std::move(signature.arguments), std::move(binding)) {
        routine_.id = signature.id;
    }

    /// Nodes the routine reads ready-made instead of computing them (e.g. from
    /// a work array a prologue filled): the leaf for such a node, or nullopt.
    using Frontier = std::function<std::optional<Expr>(NodeId)>;
    void set_frontier(Frontier frontier) { frontier_ = std::move(frontier); }

    void local(std::string name, int size);
    /// array[index] = value, in the current evaluation step.
    void assign(const std::string& array, int index, NodeId value);
    /// array[index] = from[from_index], after the step's other assignments so far.
    void copy(const std::string& array, int index, const std::string& from, int from_index);
    void factor(const std::string& matrix, int n);
    void solve(const std::string& matrix, int n, const std::string& target, int offset,
               int columns);
    /// A loop of calls to an internal routine, one per unit direction (module.hpp).
    void sweep(Sweep sweep);
    /// One call of an internal routine.
    void call(Call call);

    /// Chooses and names the temporaries: every non-leaf node used more than once,
    /// every call, every base of a repeated multiplication, and whatever keeps
    /// inline nesting within options.max_inline_depth.
    Routine finish(const Options& options) &&;

private:
    int import(NodeId root);
    Expr leaf_of(const Node& symbol_node) const;
    Step& evaluate_step();

    const Graph& graph_;
    Binding binding_;
    Frontier frontier_;
    Routine routine_;
    std::vector<int> expr_of_node_; // by NodeId; -1: not imported yet
    std::vector<int> step_of_expr_; // the evaluation step that first needs each expr
};

} // namespace yamsc::codegen
