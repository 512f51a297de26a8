#include "fixtures.hpp"

#include "lower/lower.hpp"
#include "passes/passes.hpp"

#include <cmath>
#include <stdexcept>

namespace codegen_test {
namespace {

using GiNaC::ex;
using GiNaC::symbol;
using yamsc::symbolic::Dof;
using yamsc::symbolic::InputChannel;
using yamsc::symbolic::Matrix;
using yamsc::symbolic::Output;
using yamsc::symbolic::Parameter;
using yamsc::symbolic::Row;

Dof dof(const std::string& name) {
    return Dof{name, "angle " + name, symbol(name), symbol(name + "_d"), symbol(name + "_dd")};
}

Parameter param(const std::string& name, std::optional<double> value) {
    return Parameter{name, "parameter " + name, value, symbol(name)};
}

// Jacobians by GiNaC's diff: fine for these small trees.
void derive(Equations& eq) {
    const int nq = eq.nq();
    eq.dF_dq.assign(nq, Row(nq));
    eq.dF_dqd.assign(nq, Row(nq));
    eq.dF_du.assign(nq, Row(eq.nu()));
    eq.dMa_dq.assign(nq, Row(nq));
    eq.a.clear();
    for (int k = 0; k < nq; ++k) eq.a.emplace_back("a" + std::to_string(k));
    for (int i = 0; i < nq; ++i) {
        ex Ma = 0;
        for (int k = 0; k < nq; ++k) Ma += eq.M[i][k] * eq.a[k];
        for (int j = 0; j < nq; ++j) {
            eq.dF_dq[i][j] = eq.F[i].diff(eq.dofs[j].q);
            eq.dF_dqd[i][j] = eq.F[i].diff(eq.dofs[j].qd);
            eq.dMa_dq[i][j] = Ma.diff(eq.dofs[j].q);
        }
        for (int j = 0; j < eq.nu(); ++j) eq.dF_du[i][j] = eq.F[i].diff(eq.inputs[j].sym);
    }
}

double apply_function(const std::string& name, const std::vector<double>& a) {
    if (name == "sin") return std::sin(a[0]);
    if (name == "cos") return std::cos(a[0]);
    if (name == "tan") return std::tan(a[0]);
    if (name == "exp") return std::exp(a[0]);
    if (name == "log") return std::log(a[0]);
    if (name == "abs") return std::fabs(a[0]);
    if (name == "atan") return std::atan(a[0]);
    if (name == "atan2") return std::atan2(a[0], a[1]);
    throw std::runtime_error("evaluator: no function " + name);
}

} // namespace

Equations pendulum() {
    Equations eq;
    eq.model_name = "pendulum";
    eq.title = "Simple pendulum";
    eq.source_path = "tests/pendulum.mbd";
    eq.source_digest = "0123abcd";
    eq.t = symbol("t");
    eq.dofs.push_back(dof("theta"));
    eq.inputs.push_back(InputChannel{"tau", "tau", "joint torque [N m]", symbol("tau")});
    eq.params.push_back(param("m", std::nullopt));
    eq.params.push_back(param("l", 0.75));
    eq.params.push_back(param("g", 9.807));
    eq.params.push_back(param("c", 0.1));
    const ex m = eq.params[0].sym, l = eq.params[1].sym, g = eq.params[2].sym, c = eq.params[3].sym;
    const ex th = eq.dofs[0].q, thd = eq.dofs[0].qd;
    eq.M = {{m * l * l}};
    eq.F = {-m * g * l * sin(th) - c * thd + eq.inputs[0].sym};
    eq.outputs.push_back(Output{"x_tip", "horizontal tip position", l * sin(th)});
    eq.outputs.push_back(Output{"y_tip", "", -l * cos(th)});
    derive(eq);
    return eq;
}

Equations double_pendulum(bool perturb) {
    Equations eq;
    std::vector<ex> noise; // unrelated objects that shift serial numbers and addresses
    if (perturb) {
        for (int i = 0; i < 37; ++i) noise.push_back(symbol("noise") * (i + 1));
        eq.params.push_back(param("g", 9.81));
        eq.params.push_back(param("l2", 0.8));
        eq.params.push_back(param("l1", 1.1));
        eq.params.push_back(param("m2", 0.7));
        eq.params.push_back(param("m1", 1.5));
        std::swap(eq.params[0], eq.params[4]);
        std::swap(eq.params[1], eq.params[3]);
        eq.inputs.push_back(InputChannel{"u", "u", "torque at joint 1", symbol("u")});
        eq.dofs.push_back(dof("q2"));
        eq.dofs.insert(eq.dofs.begin(), dof("q1"));
        eq.t = symbol("t");
    } else {
        eq.t = symbol("t");
        eq.dofs.push_back(dof("q1"));
        eq.dofs.push_back(dof("q2"));
        eq.inputs.push_back(InputChannel{"u", "u", "torque at joint 1", symbol("u")});
        eq.params.push_back(param("m1", 1.5));
        eq.params.push_back(param("m2", 0.7));
        eq.params.push_back(param("l1", 1.1));
        eq.params.push_back(param("l2", 0.8));
        eq.params.push_back(param("g", 9.81));
    }
    eq.model_name = "double_pendulum";
    eq.title = "Double pendulum";
    eq.source_path = "tests/double_pendulum.mbd";
    eq.source_digest = "feedbeef";
    const ex m1 = eq.params[0].sym, m2 = eq.params[1].sym, l1 = eq.params[2].sym,
             l2 = eq.params[3].sym, g = eq.params[4].sym;
    const ex q1 = eq.dofs[0].q, q2 = eq.dofs[1].q, q1d = eq.dofs[0].qd, q2d = eq.dofs[1].qd;
    const ex c12 = m2 * l1 * l2 * cos(q1 - q2);
    const ex s12 = m2 * l1 * l2 * sin(q1 - q2);
    eq.M = {{(m1 + m2) * l1 * l1, c12}, {c12, m2 * l2 * l2}};
    // The perturbed build also writes -(x (m1 + m2)) as x (-m1 - m2): the same value
    // with another structure, as a different derivation order could produce.
    const ex total_mass_term =
        perturb ? g * l1 * sin(q1) * (-m1 - m2) : -(g * l1 * sin(q1) * (m1 + m2));
    // Products with sums of mixed signs: GiNaC gives each such sum the sign of
    // its first term in its hash order, which changes from process to process.
    const ex u = eq.inputs[0].sym;
    const ex signed_sums = u * (l1 - l2) * q1d + g * (m1 - m2) * q2d * q1d +
                           (l2 - g) * (m2 - l1) * u + (q1 - q2) * (l1 - m2) * m1;
    eq.F = {-s12 * pow(q2d, 2) + total_mass_term + eq.inputs[0].sym,
            s12 * pow(q1d, 2) - m2 * g * l2 * sin(q2) + signed_sums};
    eq.outputs.push_back(Output{"x2", "tip x", l1 * sin(q1) + l2 * sin(q2)});
    eq.outputs.push_back(Output{"y2", "tip y", -l1 * cos(q1) - l2 * cos(q2)});
    eq.outputs.push_back(Output{"energy_rate", "", q1d * eq.inputs[0].sym});
    derive(eq);
    return eq;
}

Equations prescribed() {
    Equations eq;
    eq.model_name = "prescribed";
    eq.title = "Bead on a rod of prescribed length";
    eq.source_path = "tests/prescribed.mbd";
    eq.source_digest = "42";
    eq.t = symbol("t");
    eq.dofs.push_back(dof("phi"));
    eq.inputs.push_back(InputChannel{"r", "r", "radius", symbol("r")});
    eq.inputs.push_back(InputChannel{"r'", "r_d", "its rate", symbol("r_d")});
    eq.params.push_back(param("J", 0.2));
    eq.params.push_back(param("m", 2.0));
    eq.params.push_back(param("w", 3.0));
    const ex J = eq.params[0].sym, m = eq.params[1].sym, w = eq.params[2].sym;
    const ex r = eq.inputs[0].sym, rd = eq.inputs[1].sym;
    const ex phi = eq.dofs[0].q, phid = eq.dofs[0].qd;
    eq.M = {{J + m * pow(r, 2)}};
    eq.F = {-2 * m * r * rd * phid + sin(w * eq.t) * exp(-phi * phi) + sqrt(J) / (1 + pow(phi, 5)) +
            GiNaC::Pi * GiNaC::numeric(1, 3) * atan2(phi, r)};
    eq.outputs.push_back(Output{"r_phi", "", pow(r, GiNaC::numeric(-1, 2)) * abs(phi)});
    derive(eq);
    return eq;
}

Equations bare() {
    Equations eq;
    eq.model_name = "bare";
    eq.t = symbol("t");
    eq.dofs.push_back(dof("q"));
    eq.M = {{1}};
    eq.F = {-ex(eq.dofs[0].q)};
    derive(eq);
    return eq;
}

// GiNaC's operator* asks both operands for their return_type(), and sin()'s
// eval multiplies its argument by 60/Pi: both walk the argument as a tree,
// exponential on this DAG; so does power's eval. Build the nodes directly
// instead (held functions and powers, products and sums allocated without
// those checks).
ex dag_mul(const ex& a, const ex& b) {
    return GiNaC::dynallocate<GiNaC::mul>(a, b);
}
ex dag_add(const ex& a, const ex& b) {
    return GiNaC::dynallocate<GiNaC::add>(a, b);
}

Equations deep_chain(int levels) {
    Equations eq;
    eq.model_name = "deep_chain";
    eq.title = "Repeated self-composition";
    eq.source_path = "tests/deep_chain.mbd";
    eq.source_digest = "dd";
    eq.t = symbol("t");
    eq.dofs.push_back(dof("q"));
    eq.params.push_back(param("c", 0.2));
    eq.params.push_back(param("m", 1.0));
    const ex c = eq.params[0].sym, m = eq.params[1].sym;
    ex x = eq.dofs[0].q;
    ex dx = 1; // dx/dq, by forward-mode differentiation: shares x's nodes
    for (int k = 0; k < levels; ++k) {
        const ex s = sin(x).hold();
        const ex next = dag_add(dag_mul(s, x), dag_mul(x, c));
        dx = dag_add(dag_add(dag_mul(dag_mul(cos(x).hold(), dx), x), dag_mul(s, dx)),
                     dag_mul(dx, c));
        x = next;
    }
    eq.a = {symbol("a0")};
    eq.M = {{dag_add(m, GiNaC::power(x, 2).hold())}};
    eq.F = {-x};
    eq.dF_dq = {{-dx}};
    eq.dF_dqd = {{0}};
    eq.dF_du = {Row{}};
    eq.dMa_dq = {{dag_mul(dag_mul(x, dx), dag_mul(2, eq.a[0]))}};
    eq.outputs.push_back(Output{"x_last", "", x});
    return eq;
}

Point sample_point(const Equations& eq) {
    Point x;
    x.t = 0.37;
    for (int i = 0; i < eq.nq(); ++i) {
        x.q.push_back(0.3 + 0.41 * i);
        x.qd.push_back(-0.7 + 0.53 * i);
    }
    for (int i = 0; i < eq.nu(); ++i) x.u.push_back(0.9 - 0.35 * i);
    for (const auto& p : eq.params) x.p.push_back(p.value ? *p.value * 1.01 : 1.3);
    return x;
}

Evaluator::Evaluator(const Equations& eq, const Point& x, const std::vector<double>& a) {
    symbols_[eq.t] = x.t;
    for (int i = 0; i < eq.nq(); ++i) {
        symbols_[eq.dofs[i].q] = x.q[i];
        symbols_[eq.dofs[i].qd] = x.qd[i];
    }
    for (int i = 0; i < eq.nu(); ++i) symbols_[eq.inputs[i].sym] = x.u[i];
    for (int i = 0; i < eq.np(); ++i) symbols_[eq.params[i].sym] = x.p[i];
    for (std::size_t i = 0; i < a.size(); ++i) symbols_[eq.a[i]] = a[i];
}

double Evaluator::operator()(const GiNaC::ex& e) {
    const GiNaC::basic* node = &GiNaC::ex_to<GiNaC::basic>(e);
    if (auto it = memo_.find(node); it != memo_.end()) return it->second;
    double v = 0.0;
    if (GiNaC::is_a<GiNaC::numeric>(e)) {
        v = GiNaC::ex_to<GiNaC::numeric>(e).to_double();
    } else if (GiNaC::is_a<GiNaC::constant>(e)) {
        v = GiNaC::ex_to<GiNaC::numeric>(e.evalf()).to_double();
    } else if (GiNaC::is_a<GiNaC::symbol>(e)) {
        v = symbols_.at(GiNaC::ex(e)); // a copy: GiNaC may re-point compared handles
    } else if (GiNaC::is_a<GiNaC::add>(e)) {
        for (std::size_t i = 0; i < e.nops(); ++i) v += (*this)(e.op(i));
    } else if (GiNaC::is_a<GiNaC::mul>(e)) {
        v = 1.0;
        for (std::size_t i = 0; i < e.nops(); ++i) v *= (*this)(e.op(i));
    } else if (GiNaC::is_a<GiNaC::power>(e)) {
        v = std::pow((*this)(e.op(0)), (*this)(e.op(1)));
    } else if (GiNaC::is_a<GiNaC::function>(e)) {
        std::vector<double> args;
        for (std::size_t i = 0; i < e.nops(); ++i) args.push_back((*this)(e.op(i)));
        v = apply_function(GiNaC::ex_to<GiNaC::function>(e).get_name(), args);
    } else {
        throw std::runtime_error("evaluator: unsupported expression");
    }
    memo_.emplace(node, v);
    keep_alive_.push_back(e);
    return v;
}

Dense evaluate(Evaluator& ev, const Matrix& m) {
    Dense out;
    for (const Row& row : m) {
        Vector r;
        for (const ex& e : row) r.push_back(ev(e));
        out.push_back(r);
    }
    return out;
}

Dense solve(Dense A, Dense B) {
    const std::size_t n = A.size();
    for (std::size_t k = 0; k < n; ++k) {
        std::size_t pivot = k;
        for (std::size_t i = k + 1; i < n; ++i)
            if (std::fabs(A[i][k]) > std::fabs(A[pivot][k])) pivot = i;
        std::swap(A[k], A[pivot]);
        std::swap(B[k], B[pivot]);
        for (std::size_t i = k + 1; i < n; ++i) {
            const double f = A[i][k] / A[k][k];
            for (std::size_t j = k; j < n; ++j) A[i][j] -= f * A[k][j];
            for (std::size_t j = 0; j < B[i].size(); ++j) B[i][j] -= f * B[k][j];
        }
    }
    for (std::size_t k = n; k-- > 0;) {
        for (std::size_t j = 0; j < B[k].size(); ++j) {
            double s = B[k][j];
            for (std::size_t i = k + 1; i < n; ++i) s -= A[k][i] * B[i][j];
            B[k][j] = s / A[k][k];
        }
    }
    return B;
}

Reference reference(const Equations& eq, const Point& x) {
    const std::size_t nq = static_cast<std::size_t>(eq.nq());
    Evaluator ev(eq, x);
    Reference r;
    r.M = evaluate(ev, eq.M);
    for (const ex& f : eq.F) r.F.push_back(ev(f));
    r.dF_dq = evaluate(ev, eq.dF_dq);
    r.dF_dqd = evaluate(ev, eq.dF_dqd);
    r.dF_du = evaluate(ev, eq.dF_du);
    for (const auto& y : eq.outputs) r.y.push_back(ev(y.value));

    Dense F_column;
    for (double f : r.F) F_column.push_back({f});
    const Dense qdd = solve(r.M, F_column);
    r.xdot = x.qd;
    Vector a;
    for (std::size_t i = 0; i < nq; ++i) {
        r.xdot.push_back(qdd[i][0]);
        a.push_back(qdd[i][0]);
    }
    Evaluator with_a(eq, x, a);
    const Dense dMa = evaluate(with_a, eq.dMa_dq);
    Dense rhs_block(nq, Vector(2 * nq));
    for (std::size_t i = 0; i < nq; ++i)
        for (std::size_t j = 0; j < nq; ++j) {
            rhs_block[i][j] = r.dF_dq[i][j] - dMa[i][j];
            rhs_block[i][nq + j] = r.dF_dqd[i][j];
        }
    const Dense lower = solve(r.M, rhs_block);
    r.J.assign(2 * nq, Vector(2 * nq, 0.0));
    for (std::size_t i = 0; i < nq; ++i) {
        r.J[i][nq + i] = 1.0;
        r.J[nq + i] = lower[i];
    }
    return r;
}

yamsc::ir::System system_of(const Equations& eq) {
    yamsc::ir::System s = yamsc::lower::lower(eq);
    yamsc::passes::derive_jacobians(s);
    yamsc::passes::output_jacobians(s);
    return s;
}

yamsc::codegen::Module build_module(const Equations& eq, const yamsc::codegen::Options& o) {
    return yamsc::codegen::build_module(system_of(eq), o);
}

} // namespace codegen_test
