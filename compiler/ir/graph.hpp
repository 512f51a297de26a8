#pragma once
// The intermediate representation of expressions: a hash-consed DAG whose
// nodes are numbered once per distinct structure. Operands of sums and
// products are kept in a canonical order that depends only on structure
// (names, numbers, operator kinds), never on GiNaC's hash order or on memory
// addresses, so everything printed from a Graph is identical from one process
// to the next. Operands come before their users (ids are topological), and
// each node knows which differentiation variables it depends on (a bit set
// over Variables), so a derivative visits only the nodes that depend on its
// variable.
#include "ir/function.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace yamsc::ir {

using NodeId = std::uint32_t;

/// What a symbol stands for; `index` is its position in the System's list of
/// that kind (0 for time).
enum class SymbolKind : std::uint8_t {
    time,
    q,            // coordinate
    qd,           // rate q'
    qdd,          // acceleration q''
    input,        // input channel u
    param,        // parameter
    acceleration, // the vector `a` of M a and dMa_dq
    seed,         // a direction of the tangent form
    multiplier,   // the constraint reactions λ of Bᵀλ (passes::constraint_derivatives)
};
inline constexpr int symbol_kind_count = 9;

struct SymbolRef {
    SymbolKind kind = SymbolKind::time;
    int index = 0;
};

/// The symbols derivatives may be taken with respect to, numbered q (0..nq-1),
/// q' (nq..2nq-1), u (2nq..2nq+nu-1), p (2nq+nu..): declared when the Graph is
/// made, since every node's dependence set is computed as it is added.
struct Variables {
    int nq = 0, nu = 0, np = 0;
    int count() const { return 2 * nq + nu + np; }
    /// The variable of a symbol, or -1 (t, q'', `a`, seeds, λ).
    int of(SymbolRef s) const;
};

enum class NodeKind : std::uint8_t { number, symbol, add, mul, call };

/// An operand with its weight: the coefficient of a term of a sum, the (integer)
/// exponent of a factor of a product, 1 for the arguments of a call.
struct Operand {
    NodeId node = 0;
    double weight = 1.0;
};

struct Node {
    NodeKind kind = NodeKind::number;
    Function function = Function::sin; // call
    SymbolRef symbol;                  // symbol
    double value = 0.0;        // number: the value; add: the constant term; mul: the coefficient
    std::uint64_t hash = 0;    // structural, deterministic across processes
    std::uint32_t depends = 0; // bit (1 << SymbolKind) for every symbol kind reachable
    std::uint32_t first_operand = 0; // the operands: Graph::operands(id)
    std::uint32_t operand_count = 0;
};

/// A node's operands, stored contiguously in the graph.
class OperandSpan {
public:
    OperandSpan(const Operand* first, std::size_t count) : first_(first), count_(count) {}
    const Operand* begin() const { return first_; }
    const Operand* end() const { return first_ + count_; }
    std::size_t size() const { return count_; }
    bool empty() const { return count_ == 0; }
    const Operand& operator[](std::size_t i) const { return first_[i]; }

private:
    const Operand* first_;
    std::size_t count_;
};

/// Normal forms kept by the constructors (so equal structures get equal ids):
///  - a sum has no number terms (folded into its constant), no term that is a
///    product with a coefficient other than 1 (folded into the term's weight),
///    no zero weights, no repeated term; a sum of one term and no constant is
///    that term (weight 1) or a product (w * x); an empty sum is its constant;
///    the first term of a sum has a positive weight (otherwise the sum is
///    negated and returned as the product -1 * sum);
///  - a product has no number factors (folded into its coefficient), no
///    product factors of integer exponent (flattened into it), and only
///    integer exponents with |e| <= max_multiplied_power; other powers become
///    calls of sqrt (for 1/2) or pow with exponent +-1; a product of one factor
///    of exponent 1 and coefficient 1 is that factor;
///  - numbers are never -0.0.
class Graph {
public:
    explicit Graph(int max_multiplied_power = 4, Variables variables = {})
        : max_multiplied_power_(max_multiplied_power), variables_(variables),
          words_((static_cast<std::size_t>(variables.count()) + 63) / 64) {}

    NodeId number(double value);
    NodeId symbol(SymbolRef ref);
    NodeId add(std::vector<Operand> terms, double constant);
    NodeId mul(std::vector<Operand> factors, double coefficient);
    NodeId call(Function f, const std::vector<NodeId>& arguments);
    /// base^exponent for any exponent (a product, a sqrt or a pow call).
    NodeId power(NodeId base, NodeId exponent);

    const Node& node(NodeId id) const { return nodes_[id]; }
    /// Valid until the next node is added.
    OperandSpan operands(NodeId id) const {
        return {operands_.data() + nodes_[id].first_operand, nodes_[id].operand_count};
    }
    std::size_t size() const { return nodes_.size(); }
    int max_multiplied_power() const { return max_multiplied_power_; }
    const Variables& variables() const { return variables_; }

    /// Whether node `id` depends on variable `v` (Variables numbering).
    bool depends(NodeId id, std::size_t v) const {
        return (dependence_[id * words_ + v / 64] >> (v % 64)) & 1u;
    }
    /// Whether node `id` depends on any variable of `mask` (dependence_words()
    /// 64-bit words, bit v for variable v).
    bool depends_on_any(NodeId id, const std::vector<std::uint64_t>& mask) const {
        for (std::size_t w = 0; w < words_; ++w)
            if (dependence_[id * words_ + w] & mask[w]) return true;
        return false;
    }
    std::size_t dependence_words() const { return words_; }

    /// A total order on structures: <0, 0 or >0. Equal structures have equal ids,
    /// so compare(a, b) == 0 exactly when a == b.
    int compare(NodeId a, NodeId b) const;

private:
    /// The id of the node `n` with `operands`, added if it is new. Flat storage
    /// and an open-addressing table: no allocation per node.
    NodeId intern(Node n, const std::vector<Operand>& operands);
    bool same_content(NodeId id, const Node& n, const std::vector<Operand>& operands) const;
    void grow_table();
    void sort_and_merge(std::vector<Operand>& operands) const;
    std::vector<Operand> operand_copy(NodeId id) const;

    int max_multiplied_power_;
    Variables variables_;
    std::size_t words_;                     // 64-bit words of a dependence set
    std::vector<std::uint64_t> dependence_; // words_ per node
    std::vector<Node> nodes_;
    std::vector<Operand> operands_;
    std::vector<NodeId> table_; // by hash, linear probing; empty_slot where free
    static constexpr NodeId empty_slot = 0xffffffffu;
};

} // namespace yamsc::ir
