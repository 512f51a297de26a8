#pragma once
// Expressions as LaTeX, the way the paper's Appendix E prints them: expanded
// into sums of products of symbols and elementary functions, like terms
// collected, numbers with 6 significant digits, the model's own names
// (`M_N` -> `M_{N}`, `theta_t` -> `\theta_{t}`, `q'` -> `\dot{q}`).
//
// Expansion walks the IR graph (ir/graph.hpp), memoised per node: the
// equations are DAGs, and a walk as a tree would be exponential. Terms are
// ordered by their printed form, so the text depends neither on the graph's
// operand order nor on how a value was built. An expression whose expansion
// exceeds a number of terms is reported as too long instead of printed.
#include "ir/graph.hpp"

#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace yamsc::codegen::latex {

/// A model name in math mode: `theta_t` -> `\theta_{t}`, `M_N` -> `M_{N}`,
/// `tower_Me_1_1` -> `\mathrm{tower}_{Me,1,1}`; `primes` adds \dot / \ddot;
/// `suffix` is appended to the subscript (`0` for operating-point values).
std::string symbol_name(const std::string& name, int primes = 0, const std::string& suffix = "");

/// Text with LaTeX's special characters escaped (for titles, docs, names in text).
std::string escape_text(const std::string& text);

/// A number with 6 significant digits: `2.5`, `-1.91\cdot 10^{6}`.
std::string number(double value);

/// The expansion has more terms than the limit.
struct TooLong : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class Expander {
public:
    /// Expressions of `graph` (which must outlive the Expander); every symbol they
    /// read must be named first.
    explicit Expander(const ir::Graph& graph, std::size_t max_terms = 400);

    /// The LaTeX name of a symbol, and where it goes in a printed product: lower
    /// ranks first (functions and parenthesised sums come last). E.g. parameters
    /// (rank 0) before coordinates (1): `c \dot{\theta}`, `g m \sin\left(\theta\right)`.
    void name(ir::SymbolRef s, std::string latex, int rank = 1);

    /// From now on, `s` stands for `value` (a node of the same graph) or a number.
    void substitute(ir::SymbolRef s, ir::NodeId value);
    void substitute(ir::SymbolRef s, double value);

    /// The signed terms of the expanded expression Σ weight * node, in print
    /// order, each starting with "+" or "-" ("-\frac{1}{2} x^{2}"); empty for 0.
    /// Throws TooLong.
    std::vector<std::string> terms(const std::vector<ir::Operand>& combination);
    std::vector<std::string> terms(ir::NodeId e) { return terms({{e, 1.0}}); }

private:
    using Monomial = std::vector<std::pair<std::string, int>>; // atom -> exponent, by atom
    using Poly = std::map<Monomial, double>;
    using Key = std::pair<int, int>; // a symbol: kind, index
    static Key key(ir::SymbolRef s) { return {static_cast<int>(s.kind), s.index}; }
    const Poly& poly(ir::NodeId node);
    Poly compute(ir::NodeId node);
    Poly sum(const std::vector<std::pair<const Poly*, double>>& parts) const;
    Poly product(const Poly& a, const Poly& b) const;
    Poly reduce_trigonometry(Poly p) const;
    Poly power(const Poly& p, double exponent) const;
    Poly atom(const std::string& text, int exponent = 1) const;
    std::string print(const Poly& p) const;
    std::vector<std::string> print_terms(const Poly& p) const;

    const ir::Graph& graph_;
    std::size_t max_terms_;
    std::map<Key, std::string> names_;
    std::map<Key, Poly> substituted_;
    std::map<std::string, int> rank_; // by atom text
    std::unordered_map<ir::NodeId, Poly> memo_;
};

} // namespace yamsc::codegen::latex
