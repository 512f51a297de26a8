#pragma once
// Small-angle approximations (`approx SYMS order N`, paper sections 4.5-4.6 and
// Appendix E) on the IR: expressions replaced by their Taylor polynomial about 0
// in a group of variables, truncated at total order N in that group.
// Trigonometric and other elementary functions are expanded through their
// derivatives at the expansion point, e.g. sin(theta_t + nu q) to order 1 in
// theta_t becomes sin(nu q) + cos(nu q) theta_t.
//
// The expansion is a truncated multivariate power series computed node by node
// and memoised by node, so shared subexpressions are expanded once, and nodes
// that do not depend on the group (the Graph's dependence bits) stay as they
// are. Every coefficient is a node of the same Graph, in its normal form.
#include "ir/graph.hpp"

#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace yamsc::passes {

/// An expression that has no Taylor expansion at 0 in the group (a pole, such
/// as 1/theta) or one this implementation does not compute (abs, atan2 of the
/// group's variables). `not_supported` distinguishes the second case.
struct NotExpandable : std::runtime_error {
    NotExpandable(const std::string& what, bool unsupported)
        : std::runtime_error(what), not_supported(unsupported) {}
    bool not_supported;
    std::size_t group = 0; // the `approx` group's index (passes::run_pipeline)
};

/// The Taylor polynomial of nodes about 0 in `group` (symbols that are
/// variables of the graph: q, u or p), truncated at total order `order`.
/// Memoised across calls: use one for all the expressions of a system.
class TaylorExpansion {
public:
    TaylorExpansion(ir::Graph& graph, const std::vector<ir::SymbolRef>& group, int order);

    /// Throws NotExpandable.
    ir::NodeId operator()(ir::NodeId node);

private:
    using Series = std::vector<ir::NodeId>; // coefficient per monomial, dense
    Series series(ir::NodeId node);
    Series compute(ir::NodeId node);
    Series constant(ir::NodeId c) const;
    Series multiply(const Series& a, const Series& b);
    Series scale(const Series& a, ir::NodeId c);
    Series add_to(Series a, const Series& b);
    /// Σ c_k r^k for k = 0..order; r must have no constant term.
    Series compose(const std::vector<ir::NodeId>& c, const Series& r);
    /// s^exponent: repeated products for whole exponents, else the binomial series.
    Series power(const Series& s, ir::NodeId exponent);
    Series function(ir::Function f, ir::NodeId argument);
    /// f^(k)(a0) / k! for k = 0..order.
    std::vector<ir::NodeId> derivatives_at(ir::Function f, ir::NodeId a0);
    bool depends(ir::NodeId node) const { return graph_.depends_on_any(node, mask_); }
    ir::NodeId times(ir::NodeId a, ir::NodeId b);

    ir::Graph& graph_;
    std::vector<int> variable_to_group_; // by Variables index, -1 outside the group
    std::vector<std::uint64_t> mask_;    // the group's variables
    int order_;
    ir::NodeId zero_, one_;
    std::vector<std::vector<int>> monomials_;     // exponents, by total degree
    std::vector<int> degree_;                     // total degree of each monomial
    std::vector<std::vector<int>> product_index_; // [i][j] -> monomial of i*j, -1 if beyond
    std::vector<ir::NodeId> monomial_values_;     // the product of powers of each monomial
    std::unordered_map<ir::NodeId, Series> memo_;
};

} // namespace yamsc::passes
