#pragma once
// The system of equations in the intermediate representation:
// M(q) q'' = F(q, q', u, t), the outputs and everything the passes derive from
// them, as rows of node ids into one canonical Graph. Made once from the
// derivation's GiNaC expressions (compiler/lower/), transformed by the passes
// (compiler/passes/), lowered to code by codegen.
#include "ir/enum_set.hpp"
#include "ir/graph.hpp"

#include <optional>
#include <string>
#include <vector>

namespace yamsc::ir {

using Row = std::vector<NodeId>;
using Matrix = std::vector<Row>; // row-major, rows of equal length

struct Dof {
    std::string name;
    std::string doc;
};

/// One entry of the input vector u (`theta_p''` is its own channel).
struct InputChannel {
    std::string name;   // as the user writes it: theta_p''
    std::string c_name; // identifier for code: theta_p_dd
    std::string doc;
};

struct Parameter {
    std::string name;
    std::string doc;
    std::optional<double> value; // the default; none: must be set at run time
};

struct Output {
    std::string name;
    std::string doc;
    NodeId value = 0; // function of t, q, q', u, p and, for reaction loads, q''
    // ∂value/∂q''_s (one per DOF), empty when the output does not read q''. The
    // generated `outputs` solves M q'' = F for it; output_matrices adds
    // ∂y/∂q'' dq''/d[x, u] to C and D.
    std::vector<NodeId> dqdd = {};
};

/// The model's `linearize` block: q0, q0', u0 as functions of the parameters
/// (all 0 when the model has none).
struct OperatingPoint {
    Row q, qd, u;
    bool declared = false;
};

/// Partial derivatives, with respect to one parameter, of what the linear model
/// is built from (docs/linearization.md): M (lower triangle only), F and the
/// Jacobians dF_dq, dF_dqd, dF_du, dMa_dq, at fixed (t, q, q', u, a).
struct ParameterDerivatives {
    Matrix M, dF_dq, dF_dqd, dF_du, dMa_dq;
    Row F;
};

/// An external function of the model (`external ...`, docs/language.md): the
/// generated code evaluates `args`, calls the user's C function `name(args,
/// result)` and passes its results as the input channels first_input ..
/// first_input + results - 1 (after the declared channels) to the rest of the
/// code. Jacobians compose by the chain rule through dargs_*.
struct External {
    std::string name;
    std::string what;     // "force on nacelle", for comments
    std::string location; // "model.mbd:12:10" of the declaration, for messages
    int first_input = 0;
    int results = 0;
    Row args;                   // functions of t, q, q', the declared u and p
    bool user_jacobian = true;  // false: `without jacobian`, central differences only
    Matrix dargs_dq, dargs_dqd; // passes::external_jacobians: nargs x nq
    Matrix dargs_du;            // nargs x (declared channels)
};

/// One row of the model's constraints (docs/theory.md, Constraint rows).
struct ConstraintRow {
    std::string name;      // `closing.x`
    bool holonomic = true; // Φ = 0, its r = dΦ/dt; else a velocity row only
    int dependent = -1;    // the DOF the model names dependent for this row, or -1
    std::string source;    // "file:line:col" of the declaration
    NodeId phi = 0;        // holonomic: Φ(q, t, u, p)
    NodeId r = 0;          // B(q, t, u) q' + c(q, t, u)
    NodeId r_t = 0;        // ∂r/∂t + Σ ∂r/∂u u' (the part of dr/dt not through q, q')
};

/// The passes (compiler/passes/passes.hpp) as values. Each declares what it
/// adds to a System and which passes must have run before it
/// (passes/pass_order.hpp); a System records the passes that ran on it.
enum class Pass : std::uint8_t {
    separate_externals,     // adds: externals[k].args
    approximate,            // adds: exact_M, exact_F; replaces M and F
    derive_jacobians,       // adds: dF_dq, dF_dqd, dF_du, dMa_dq (and Ma)
    output_jacobians,       // adds: C, D
    derive_tangent,         // adds: dG, dY, tangent_form
    external_jacobians,     // adds: externals[k].dargs_dq, dargs_dqd, dargs_du
    parameter_derivatives,  // adds: sensitivity_params, sensitivities
    constraint_derivatives, // adds: B, dr_dq, gamma and the constraint Jacobians
};
inline constexpr std::size_t pass_count = 8;
using PassSet = EnumSet<Pass, pass_count>;

struct System {
    std::string model_name;
    std::string title;
    std::string source_path;   // as given on the command line
    std::string source_digest; // hex digest of the model source (and files it read)

    std::vector<Dof> dofs;
    std::vector<InputChannel> inputs;
    std::vector<Parameter> params;
    std::vector<Output> outputs;

    /// Every expression below is a node of this graph. Its variables are the
    /// model's q, q', u and p.
    Graph graph;

    Matrix M; // nq x nq, symmetric; empty in the tangent form
    Row F;    // nq
    // M a for the acceleration symbols `a` (SymbolKind::acceleration), assembled
    // body by body by Kane's method; when empty, passes::derive_jacobians forms
    // Σ_s M_rs a_s.
    Row Ma;

    // passes::approximate: M and F as derived, before the model's `approx`
    // groups replaced them (the LaTeX document prints both); empty otherwise.
    Matrix exact_M;
    Row exact_F;

    // passes::derive_jacobians: exact Jacobians of F, and d(M a)/dq, which with
    // a = q'' completes the Jacobian of x' = [q', M^-1 F].
    Matrix dF_dq, dF_dqd, dF_du, dMa_dq;
    // passes::output_jacobians: C = [∂y/∂q, ∂y/∂q'] (ny x 2nq), D = ∂y/∂u.
    Matrix C, D;
    // passes::derive_tangent: one directional derivative along the seed symbols
    // (SymbolKind::seed, [dq, dq', du]) of G = F - M a (a held) and of the outputs.
    bool tangent_form = false;
    Row dG, dY;
    // passes::parameter_derivatives: one entry per parameter index of
    // `sensitivity_params`, in that order.
    std::vector<std::size_t> sensitivity_params;
    std::vector<ParameterDerivatives> sensitivities;

    OperatingPoint point;

    /// The constraints' rows, the nh holonomic ones first (empty without constraints).
    std::vector<ConstraintRow> constraints;
    // passes::constraint_derivatives: B = ∂r/∂q' (nc x nq), ∂r/∂q (nc x nq),
    // γ = (∂r/∂q) q' + r_t (nc), and with λ (SymbolKind::multiplier) and `a`:
    // ∂(Bᵀλ)/∂q (nq x nq), ∂(B a + γ)/∂q (nc x nq), ∂γ/∂q' (nc x nq),
    // ∂(Bᵀλ)/∂u (nq x nu), ∂(B a + γ)/∂u (nc x nu).
    Matrix B, dr_dq;
    Row gamma;
    Matrix dBTl_dq, dacc_dq, dacc_dqd, dBTl_du, dacc_du;

    /// The external functions; their results are the last input channels.
    std::vector<External> externals;

    /// The passes that ran on this System (passes::enter records them), so
    /// that prerequisites are checked, not inferred from empty rows.
    PassSet passes;

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
    /// The input channels a caller gives (nu() less the externals' results).
    int declared_nu() const {
        int n = nu();
        for (const External& e : externals) n -= e.results;
        return n;
    }
    /// Whether an output reads q'' (reaction loads): its code solves M q'' = F.
    bool outputs_read_accelerations() const {
        for (const Output& y : outputs)
            if (!y.dqdd.empty()) return true;
        return false;
    }
};

} // namespace yamsc::ir
