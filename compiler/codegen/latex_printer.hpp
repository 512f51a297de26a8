#pragma once
// Expressions as LaTeX, the way the paper's Appendix E prints them: expanded
// into sums of products of symbols and elementary functions, like terms
// collected, numbers with 6 significant digits, the model's own names
// (`M_N` -> `M_{N}`, `theta_t` -> `\theta_{t}`, `q'` -> `\dot{q}`).
//
// Expansion walks a Tape (symbolic/tape.hpp), memoised per node: GiNaC's own
// expand and printing walk shared DAGs as trees. Terms are ordered by their
// printed form, so the text does not depend on GiNaC's (address-seeded) order
// of operands. An expression whose expansion exceeds a number of terms is
// reported as too long instead of printed.
#include "symbolic/tape.hpp"

#include <ginac/ginac.h>

#include <map>
#include <memory>
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
    /// `symbols` with their LaTeX names; every symbol of the expressions must be one.
    Expander(const std::vector<GiNaC::symbol>& symbols, std::vector<std::string> names,
             std::size_t max_terms = 400);
    ~Expander();
    Expander(Expander&&) noexcept;
    Expander& operator=(Expander&&) noexcept;

    /// Where a symbol's name goes in a printed product: lower ranks first (default
    /// 0; functions and parenthesised sums come last). E.g. parameters before
    /// coordinates: `c \dot{\theta}`, `g m \sin\left(\theta\right)`.
    void set_rank(const std::string& name, int rank);

    /// From now on, `s` stands for `value` (an expression over the same symbols).
    void substitute(const GiNaC::symbol& s, const GiNaC::ex& value);

    /// The signed terms of the expanded expression, in print order, each starting
    /// with "+" or "-" ("-\frac{1}{2} x^{2}"); empty for 0. Throws TooLong.
    std::vector<std::string> terms(const GiNaC::ex& e);

private:
    using Monomial = std::vector<std::pair<std::string, int>>; // atom -> exponent, by atom
    using Poly = std::map<Monomial, double>;
    const Poly& poly(symbolic::TapeId node);
    Poly compute(symbolic::TapeId node);
    Poly sum(const std::vector<std::pair<const Poly*, double>>& parts) const;
    Poly product(const Poly& a, const Poly& b) const;
    Poly reduce_trigonometry(Poly p) const;
    Poly power(const Poly& p, double exponent) const;
    Poly atom(const std::string& text, int exponent = 1) const;
    std::string print(const Poly& p) const;
    std::vector<std::string> print_terms(const Poly& p) const;

    std::unique_ptr<symbolic::Tape> tape_;
    std::vector<std::string> names_;
    std::size_t max_terms_;
    std::map<std::size_t, Poly> substituted_; // by variable index
    std::map<std::string, int> rank_;         // by atom text
    std::unordered_map<symbolic::TapeId, Poly> memo_;
};

} // namespace yamsc::codegen::latex
