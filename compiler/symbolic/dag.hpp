#pragma once
// Memoised operations on expression DAGs. The equations share subexpressions
// heavily (each body's kinematics is built from its parent's); GiNaC's own
// diff/subs/evalf walk trees and would take exponential time. These walk each
// distinct node once, identified by its address (the memo keeps it alive).
#include <ginac/ginac.h>

#include <functional>
#include <map>
#include <unordered_map>

namespace yamsc::symbolic {

/// Identity of a node: the address of the object an ex points to.
inline const GiNaC::basic* node_id(const GiNaC::ex& e) {
    return &GiNaC::ex_to<GiNaC::basic>(e);
}

/// A per-node memo that keeps the keyed nodes alive (so addresses are not reused).
template <class T> class NodeMemo {
public:
    const T* find(const GiNaC::ex& e) const {
        auto it = map_.find(node_id(e));
        return it == map_.end() ? nullptr : &it->second.second;
    }
    const T& put(const GiNaC::ex& e, T value) {
        return map_.insert_or_assign(node_id(e), std::make_pair(e, std::move(value)))
            .first->second.second;
    }

private:
    std::unordered_map<const GiNaC::basic*, std::pair<GiNaC::ex, T>> map_;
};

/// d/ds of expressions, memoised across calls (reuse one per symbol).
class Differentiator {
public:
    explicit Differentiator(GiNaC::symbol s) : s_(std::move(s)) {}
    GiNaC::ex operator()(const GiNaC::ex& e);

private:
    GiNaC::ex compute(const GiNaC::ex& e);
    GiNaC::symbol s_;
    NodeMemo<GiNaC::ex> memo_;
};

/// Replaces symbols by expressions, memoised across calls.
class Substituter {
public:
    explicit Substituter(GiNaC::exmap map) : map_(std::move(map)) {}
    GiNaC::ex operator()(const GiNaC::ex& e);

private:
    GiNaC::exmap map_;
    NodeMemo<GiNaC::ex> memo_;
};

/// Whether expressions depend on any of a set of symbols, memoised.
class DependsOn {
public:
    explicit DependsOn(std::vector<GiNaC::symbol> symbols);
    bool operator()(const GiNaC::ex& e);

private:
    std::vector<GiNaC::symbol> symbols_;
    NodeMemo<bool> memo_;
};

/// Numeric value of expressions for given symbol values, memoised.
class Evaluator {
public:
    using Values = std::map<GiNaC::ex, double, GiNaC::ex_is_less>;
    explicit Evaluator(Values values) : values_(std::move(values)) {}
    /// Throws diag::InternalError for a symbol without value or an unknown node type.
    double operator()(const GiNaC::ex& e);

private:
    Values values_;
    NodeMemo<double> memo_;
};

/// Rebuilds `e` with its operands mapped by `f` (add, mul, power, function).
GiNaC::ex map_operands(const GiNaC::ex& e, const std::function<GiNaC::ex(const GiNaC::ex&)>& f);

/// Number of distinct nodes of a set of expressions (its DAG size).
std::size_t dag_size(const std::vector<GiNaC::ex>& roots);

} // namespace yamsc::symbolic
