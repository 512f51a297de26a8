#pragma once
// Hand-built symbolic::Equations for the code generator's tests, and an
// independent numeric reference: a memoised evaluator over GiNaC's own tree
// (it shares nothing with codegen's canonical graph) plus a small dense solver.
#include "codegen/module.hpp"
#include "ir/system.hpp"
#include "symbolic/equations.hpp"

#include <map>
#include <string>
#include <unordered_map>
#include <vector>

namespace codegen_test {

using yamsc::symbolic::Equations;

/// theta'' m l^2 = -m g l sin(theta) - c theta' + tau; m has no default.
Equations pendulum();
/// Planar double pendulum with a torque u at the first joint: M depends on
/// cos(q1 - q2), F on sin q1, sin q2, sin(q1 - q2) and the rates.
/// `perturb` builds the same equations with symbols created in another order
/// and unrelated GiNaC objects interleaved, so that GiNaC's hashes differ.
Equations double_pendulum(bool perturb = false);
/// One DOF whose M depends on an input and F on time: no short mass_matrix.
Equations prescribed();
/// One DOF and nothing else: no inputs, parameters or outputs. M = [1], F = [-q].
Equations bare();
/// x_{k+1} = sin(x_k) x_k + c x_k from x_0 = q, `levels` times: a DAG whose
/// tree is exponential. M = [m + x_L^2], F = [-x_L], Jacobians by forward mode.
Equations deep_chain(int levels);

/// The System of `eq` as the driver makes it: lowered to the IR, then the
/// Jacobians and the outputs' Jacobians derived by the passes.
yamsc::ir::System system_of(const Equations& eq);
/// The module of system_of(eq).
yamsc::codegen::Module build_module(const Equations& eq, const yamsc::codegen::Options& o = {});

struct Point {
    double t = 0.0;
    std::vector<double> q, qd, u, p;
};

/// A point where every value is set (params with and without defaults).
Point sample_point(const Equations& eq);

/// Memoised evaluation by node identity (GiNaC nodes kept alive meanwhile).
class Evaluator {
public:
    Evaluator(const Equations& eq, const Point& x, const std::vector<double>& a = {});
    double operator()(const GiNaC::ex& e);

private:
    std::map<GiNaC::ex, double, GiNaC::ex_is_less> symbols_;
    std::unordered_map<const GiNaC::basic*, double> memo_;
    std::vector<GiNaC::ex> keep_alive_;
};

using Vector = std::vector<double>;
using Dense = std::vector<Vector>;

Dense evaluate(Evaluator& ev, const yamsc::symbolic::Matrix& m);
/// Solves A X = B by Gaussian elimination with partial pivoting.
Dense solve(Dense A, Dense B);

struct Reference {
    Dense M, dF_dq, dF_dqd, dF_du, J;
    Vector F, y, xdot;
};
/// Everything the generated functions compute, from the expressions directly.
Reference reference(const Equations& eq, const Point& x);

/// How often `what` occurs in `text` (occurrences that do not overlap).
inline std::size_t occurrences(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t pos = text.find(what); pos != std::string::npos;
         pos = text.find(what, pos + what.size()))
        ++n;
    return n;
}

} // namespace codegen_test
