#pragma once
// The symbolic system: M(q) q'' = F(q, q', u, t) and the outputs, as GiNaC
// expressions over the symbols listed here. Produced by symbolic/ (Kane's
// method); lower::lower() turns it into the ir::System that the passes and the
// code generator work on. Also read by the numeric evaluator and the LaTeX
// printer.
//
// Expressions are DAGs: subexpressions are shared, never expanded. Walk them
// with the memoised operations of symbolic/dag.hpp, never with GiNaC's own
// recursive subs/diff/evalf (exponential on shared trees).
#include <ginac/ginac.h>

#include <optional>
#include <string>
#include <vector>

namespace yamsc::symbolic {

using Row = std::vector<GiNaC::ex>;
using Matrix = std::vector<Row>; // row-major, rows of equal length

struct Dof {
    std::string name;
    std::string doc;
    GiNaC::symbol q, qd, qdd; // the coordinate, its rate, its acceleration
};

/// One entry of the input vector u. An input declared `order 2` gives three
/// channels: `theta_p`, `theta_p'`, `theta_p''`.
struct InputChannel {
    std::string name;   // as the user writes it: theta_p''
    std::string c_name; // identifier for code: theta_p_dd
    std::string doc;
    GiNaC::symbol sym;
};

struct Parameter {
    std::string name;
    std::string doc;
    std::optional<double> value; // the default; none: must be set at run time
    GiNaC::symbol sym;
};

struct Output {
    std::string name;
    std::string doc;
    GiNaC::ex value; // function of t, q, q', u, p and, for reaction loads, q''
    Row dqdd = {};   // ∂value/∂q''_s, one per DOF; empty when value does not read q''
};

/// One row of the model's constraints (docs/theory.md, Constraint rows).
struct ConstraintRow {
    std::string name;      // `closing.x`
    bool holonomic = true; // Φ = 0 (its r is dΦ/dt), else a velocity row only
    int dependent = -1;    // the DOF the model names dependent for this row, or -1
    std::string source;    // "file:line:col" of the declaration
    GiNaC::ex phi = 0;     // holonomic: Φ(q, t, u, p)
    GiNaC::ex r = 0;       // B(q, t, u) q' + c(q, t, u)
    GiNaC::ex r_t = 0;     // ∂r/∂t + Σ ∂r/∂u u': the part of dr/dt not through q, q'
};

struct Equations {
    std::string model_name;
    std::string title;
    std::string source_path;   // as given on the command line
    std::string source_digest; // hex digest of the model source (and files it read)

    GiNaC::symbol t;
    std::vector<Dof> dofs;
    std::vector<InputChannel> inputs;
    std::vector<Parameter> params;
    std::vector<Output> outputs;

    Matrix M; // nq x nq, symmetric, depends on q and p (and u, t for prescribed motion)
    Row F;    // nq

    // The compiler derives the Jacobians on the IR (passes/); these GiNaC ones
    // are filled only by tests, as references independent of the IR.
    Matrix dF_dq, dF_dqd, dF_du; // nq x nq, nq x nq, nq x nu
    // d(M(q) a)/dq for a vector of symbols `a` (nq x nq): with a = q'' it completes
    // the Jacobian of the first-order system x' = f(x) = [q', M^-1 F].
    std::vector<GiNaC::symbol> a;
    Matrix dMa_dq;
    // M(q) a assembled body by body from Kane's q''-part of the inertia forces: a DAG
    // of O(bodies x DOFs) nodes where Σ_s M_rs a_s has O(bodies x DOFs²). Filled by
    // derive() together with `a`; when empty, passes::derive_jacobians forms Σ_s M_rs a_s.
    Row Ma;

    // The constraints' rows, the nh holonomic ones first (empty without constraints).
    std::vector<ConstraintRow> constraints;

    int nq() const { return static_cast<int>(dofs.size()); }
    int nu() const { return static_cast<int>(inputs.size()); }
    int np() const { return static_cast<int>(params.size()); }
    int ny() const { return static_cast<int>(outputs.size()); }
    int nc() const { return static_cast<int>(constraints.size()); }
    int nh() const {
        int n = 0;
        for (const ConstraintRow& r : constraints) n += r.holonomic ? 1 : 0;
        return n;
    }
};

} // namespace yamsc::symbolic
