#pragma once
// Forward-mode derivatives on the IR graph, memoised: either d/d(variable) for
// one variable, or the directional derivative Σ_v seed_v d/d(variable v) along
// seed nodes (the seed symbols of the tangent form), which costs one pass over
// the nodes that depend on a seeded variable however many there are. Every
// result is built through the Graph's constructors, so it is in normal form and
// shares whatever it can with the equations and the other derivatives.
#include "ir/graph.hpp"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace yamsc::passes {

class ForwardDerivative {
public:
    /// d/d(variable), Variables numbering.
    ForwardDerivative(ir::Graph& graph, std::size_t variable);
    /// seeds[v]: the derivative of variable v (a zero node for none).
    ForwardDerivative(ir::Graph& graph, std::vector<ir::NodeId> seeds);
    /// The node of the derivative of `node`; iterative.
    ir::NodeId operator()(ir::NodeId node);

private:
    ir::NodeId rule(ir::NodeId node);
    ir::NodeId memo(ir::NodeId node) const;
    bool relevant(ir::NodeId node) const { return graph_.depends_on_any(node, mask_); }

    ir::Graph& graph_;
    ir::NodeId zero_;
    std::vector<ir::NodeId> seeds_;   // by variable
    std::vector<std::uint64_t> mask_; // the variables with a nonzero seed
    std::unordered_map<ir::NodeId, ir::NodeId> done_;
};

} // namespace yamsc::passes
