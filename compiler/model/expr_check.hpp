#pragma once
// Validation of expressions against what may appear where: which kinds of names,
// which time derivatives, scalar or vector. Also the evaluation of constant
// expressions (parameter defaults).
#include "model/names.hpp"

#include <map>
#include <optional>

namespace yamsc::model {

/// Where an expression stands decides what it may use.
struct ExprContext {
    std::string what;          // for messages: "the mass of body 'arm'"
    bool params = true;        // parameters (and numbers, pi) are always allowed
    bool dofs = false;         // q
    int dof_primes = 0;        // highest derivative of q allowed: 0, 1 (q'), 2 (q'')
    bool inputs = false;       // u, and u', u''... up to the input's declared order
    int input_extra_order = 0; // inputs here need this many more derivatives than used
    bool time = false;         // t
    bool kinematics = false;   // position(b), velocity(b), angular_velocity(b)
    bool reactions = true;     // with kinematics: reaction_force(b), reaction_moment(b)
};

enum class Shape { scalar, vector, invalid };

class ExprChecker {
public:
    ExprChecker(const SymbolTable& names, const std::vector<Input>& inputs,
                diag::Diagnostics& diags)
        : names_(names), inputs_(inputs), diags_(diags) {}

    /// Reports every problem of `e` in context `ctx`; returns its shape.
    Shape check(const Expr& e, const ExprContext& ctx);
    /// Requires a scalar (reports otherwise); true when valid.
    bool scalar(const Expr& e, const ExprContext& ctx);
    /// Requires a 3-vector written as `(a, b, c)` and returns its components.
    std::optional<Vec> vector(const Expr& e, const ExprContext& ctx);

private:
    Shape check_name(const Expr& e, const ExprContext& ctx);
    Shape check_call(const Expr& e, const ExprContext& ctx);
    /// `body.node(k)` or `body.tip` as the argument of a reaction: a body and a constant.
    bool check_section(const Expr& e);
    const SymbolTable& names_;
    const std::vector<Input>& inputs_;
    diag::Diagnostics& diags_;
};

/// Value of a constant expression (numbers, pi, deg, functions); nullopt when it uses
/// a name or is not finite. `why` receives a reason.
std::optional<double> evaluate_constant(const Expr& e, std::string& why);

/// Values of names (parameter defaults) for evaluate_with.
using NameValues = std::map<std::string, double>;

/// Like evaluate_constant, but names found in `names` stand for their values.
std::optional<double> evaluate_with(const Expr& e, const NameValues& names, std::string& why);

/// The names of a given kind that appear in `e` (for DOF-usage analysis).
void collect_names(const Expr& e, std::vector<const Expr*>& out);

} // namespace yamsc::model
