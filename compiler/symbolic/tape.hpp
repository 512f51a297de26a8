#pragma once
// A hash-consed expression DAG on the GiNaC side of the compiler, for what
// still works on GiNaC expressions before (or beside) the IR: the truncated
// Taylor arithmetic of `approx` (symbolic/approx.cpp) and the polynomial
// expansion and Jacobians of the LaTeX printer. Generated code takes its
// derivatives from the passes on the IR (compiler/passes/), not from here.
//
// GiNaC is a poor host for derivatives of large shared DAGs: its add and mul
// constructors flatten nested sums and products (a + (b + c) copies the terms
// of the inner sum, destroying the sharing the kinematics built), its op(i)
// of a sum or product builds a new object for every term with a coefficient
// (so a memo keyed on node identity misses), and its evaluation walks operand
// trees. The Tape stores nodes in flat arrays with integer ids: operands come
// before their users, identical nodes are stored once, nothing is flattened or
// expanded, and each node knows which of the differentiation variables it
// depends on.
//
// Expressions enter with import() (memoised on GiNaC node identity) and leave
// with to_ginac(): imported nodes come back as the very GiNaC objects they
// came from, new nodes are built as already-evaluated GiNaC objects without
// flattening or evaluation (see tape.cpp). The price: such objects are not in
// GiNaC's canonical form (operands in tape order, sums inside sums), so
// GiNaC's own equality and cancellation do not see through them (`a*b - b*a`
// can stay). Compare them numerically or in the IR (lower::lower), never with
// GiNaC's ==.
#include "ir/function.hpp"

#include <ginac/ginac.h>

#include <cstdint>
#include <map>
#include <unordered_map>
#include <vector>

namespace yamsc::symbolic {

using TapeId = std::uint32_t;

enum class TapeKind : std::uint8_t { number, symbol, add, mul, power, call };

/// The elementary functions: the IR's one table (ir/function.hpp).
using TapeFunction = ir::Function;
using ir::evaluate;

/// An operand with its weight: the coefficient of a term of a sum, the exponent
/// of a factor of a product, 1 for the operands of power and call nodes.
struct TapeTerm {
    TapeId node = 0;
    double weight = 1.0;
};

class Tape {
public:
    /// `variables`: the symbols derivatives may be taken with respect to.
    explicit Tape(const std::vector<GiNaC::symbol>& variables);

    /// The node of `e` (iterative, memoised on node identity). Throws
    /// diag::InternalError for what cannot be differentiated (unknown classes or
    /// functions, complex numbers).
    TapeId import(const GiNaC::ex& e);
    /// The GiNaC expression of a node: the imported object itself, or a new
    /// evaluated object sharing the exported operands.
    GiNaC::ex to_ginac(TapeId id);

    // Constructors. They fold numbers and drop zero terms and unit factors, and
    // sort operands by id so that equal sums and products are stored once. They
    // never flatten a sum into a sum or a product into a product.
    TapeId number(double value);
    TapeId add(std::vector<TapeTerm> terms, double constant = 0.0);
    TapeId mul(std::vector<TapeTerm> factors, double coefficient = 1.0);
    TapeId power(TapeId base, TapeId exponent);
    TapeId call(TapeFunction f, std::vector<TapeId> arguments);

    TapeKind kind(TapeId id) const { return nodes_[id].kind; }
    double value(TapeId id) const { return nodes_[id].value; }
    TapeFunction function(TapeId id) const { return nodes_[id].function; }
    /// The variable a symbol node is, or -1 (a symbol that is not a variable).
    int variable_of(TapeId id) const { return nodes_[id].variable; }
    const TapeTerm* operands(TapeId id) const { return terms_.data() + nodes_[id].first; }
    std::uint32_t operand_count(TapeId id) const { return nodes_[id].count; }
    bool depends(TapeId id, std::size_t variable) const {
        return (deps_[id * words_ + variable / 64] >> (variable % 64)) & 1u;
    }
    /// True when the node depends on any variable of `mask` (a set of words_
    /// 64-bit words, bit v for variable v).
    bool depends_on_any(TapeId id, const std::vector<std::uint64_t>& mask) const {
        for (std::size_t w = 0; w < words_; ++w)
            if (deps_[id * words_ + w] & mask[w]) return true;
        return false;
    }
    std::size_t dependence_words() const { return words_; }
    std::size_t size() const { return nodes_.size(); }
    std::size_t variable_count() const { return variable_count_; }
    TapeId zero() const { return zero_; }
    TapeId one() const { return one_; }

private:
    struct Node {
        TapeKind kind = TapeKind::number;
        TapeFunction function = TapeFunction::sin;
        std::int32_t variable = -1; // symbol: variable index, or -1
        std::int32_t symbol = -1;   // symbol: index into symbols_
        double value = 0.0;         // number: value; add: constant; mul: coefficient
        std::uint64_t hash = 0;
        std::uint32_t first = 0; // operands: terms_[first, first + count)
        std::uint32_t count = 0;
    };

    TapeId intern(Node n, const std::vector<TapeTerm>& operands);
    bool same(TapeId id, const Node& n, const std::vector<TapeTerm>& operands) const;
    void grow_table();
    TapeId symbol_node(const GiNaC::ex& s);
    TapeId import_leaf(const GiNaC::ex& e);
    GiNaC::ex build_ginac(TapeId id);

    std::size_t variable_count_;
    std::size_t words_; // 64-bit words of the dependence set of a node
    std::vector<Node> nodes_;
    std::vector<TapeTerm> terms_;
    std::vector<std::uint64_t> deps_; // words_ per node
    std::vector<TapeId> table_;       // hash table of node ids, linear probing
    TapeId zero_ = 0, one_ = 0;

    std::map<GiNaC::ex, std::pair<std::int32_t, std::int32_t>, GiNaC::ex_is_less>
        symbol_index_;                // symbol -> (index in symbols_, variable or -1)
    std::vector<GiNaC::ex> symbols_;  // by symbol index
    std::vector<GiNaC::ex> exported_; // by node id: the GiNaC object, once known
    std::vector<bool> has_export_;
    // GiNaC node identity -> tape id; the key objects are kept alive in the map.
    std::unordered_map<const GiNaC::basic*, std::pair<GiNaC::ex, TapeId>> imported_;
};

/// Forward-mode derivatives of tape nodes, memoised: either d/d(variable) for
/// one variable, or the directional derivative sum_v seed_v d/d(variable v)
/// along seed nodes (symbols of a direction, typically), which costs one pass
/// over the nodes that depend on a seeded variable however many there are.
class ForwardDerivative {
public:
    ForwardDerivative(Tape& tape, std::size_t variable);
    /// seeds[v]: the derivative of variable v (tape.zero() for none).
    ForwardDerivative(Tape& tape, std::vector<TapeId> seeds);
    /// The node of the derivative of `node`; iterative.
    TapeId operator()(TapeId node);

private:
    TapeId rule(TapeId node);
    TapeId memo(TapeId node) const;
    bool relevant(TapeId node) const { return tape_.depends_on_any(node, mask_); }

    Tape& tape_;
    std::vector<TapeId> seeds_;       // by variable
    std::vector<std::uint64_t> mask_; // the variables with a nonzero seed
    std::unordered_map<TapeId, TapeId> done_;
};

} // namespace yamsc::symbolic
