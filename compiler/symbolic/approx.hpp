#pragma once
// Small-angle approximations (`approx SYMS order N`, paper sections 4.5-4.6 and
// Appendix E): expressions replaced by their Taylor polynomial about 0 in a group
// of symbols, truncated at total order N in that group. Trigonometric and other
// elementary functions are expanded through their derivatives at the expansion
// point, e.g. sin(theta_t + nu q) to order 1 in theta_t becomes
// sin(nu q) + cos(nu q) theta_t.
//
// The expansion is a truncated multivariate power series computed node by node
// and memoised by node, so shared subexpressions are expanded once and nodes
// that do not depend on the group stay as they are. It runs on a Tape
// (symbolic/tape.hpp), not on GiNaC objects: GiNaC's evaluation of new sums and
// products asks their operands whether they commute (return_type), a walk of
// the whole tree below them, exponential on the shared DAGs of the equations.
#include "diag/diagnostics.hpp"
#include "model/model.hpp"
#include "symbolic/equations.hpp"
#include "symbolic/tape.hpp"

#include <memory>
#include <stdexcept>
#include <unordered_map>
#include <vector>

namespace yamsc::symbolic {

/// An expression that has no Taylor expansion at 0 in the group (a pole, such
/// as 1/theta) or one this implementation does not compute (abs, atan2 of the
/// group's symbols). `not_supported` distinguishes the second case.
struct NotExpandable : std::runtime_error {
    NotExpandable(const std::string& what, bool unsupported)
        : std::runtime_error(what), not_supported(unsupported) {}
    bool not_supported;
};

/// The Taylor polynomial of expressions about 0 in `symbols`, truncated at total
/// order `order`. Memoised across calls: use one for all the expressions of a
/// system. Numbers become doubles (as in generated code).
class TaylorExpansion {
public:
    TaylorExpansion(std::vector<GiNaC::symbol> symbols, int order);

    /// Throws NotExpandable.
    GiNaC::ex operator()(const GiNaC::ex& e);

private:
    using Series = std::vector<TapeId>; // coefficient per monomial, dense
    Series series(TapeId node);
    Series compute(TapeId node);
    Series constant(TapeId c) const;
    Series multiply(const Series& a, const Series& b);
    Series scale(const Series& a, TapeId c);
    Series add_to(Series a, const Series& b, double weight = 1.0);
    /// Σ c_k r^k for k = 0..order; r must have no constant term.
    Series compose(const std::vector<TapeId>& c, const Series& r);
    /// s^exponent: repeated products for whole exponents, else the binomial series.
    Series power(const Series& s, TapeId exponent);
    Series function(TapeId node);
    /// f^(k)(a0) / k! for k = 0..order, through a placeholder variable.
    std::vector<TapeId> derivatives_at(TapeFunction f, TapeId a0);
    TapeId substitute_placeholder(TapeId node, TapeId value,
                                  std::unordered_map<TapeId, TapeId>& memo);
    bool depends(TapeId node) const;
    TapeId times(TapeId a, TapeId b);
    TapeId sum(const std::vector<TapeTerm>& terms);
    TapeId call(TapeFunction f, TapeId argument);

    std::size_t group_size_;
    int order_;
    std::unique_ptr<Tape> tape_;
    std::size_t placeholder_; // the variable index of the placeholder
    TapeId placeholder_node_ = 0;
    std::vector<std::vector<int>> monomials_;     // exponents, by total degree
    std::vector<int> degree_;                     // total degree of each monomial
    std::vector<std::vector<int>> product_index_; // [i][j] -> monomial of i*j, -1 if beyond
    std::vector<TapeId> monomial_values_;         // the product of powers of each monomial
    std::unordered_map<TapeId, Series> memo_;
};

/// Replaces M and F of `eq` by their expansions, group after group, for the
/// model's `approx` statements (before derive_jacobians). The outputs stay exact.
/// Reports what cannot be expanded at the group's `approx` line; false then.
bool approximate(const model::Model& m, Equations& eq, diag::Diagnostics& diags);

} // namespace yamsc::symbolic
