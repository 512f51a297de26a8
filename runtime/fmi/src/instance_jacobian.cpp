// Directional and adjoint derivatives of an instance (instance.hpp): the
// blocks of the Jacobian of (x', y) with respect to (x, u),
//   A = dx'/dx  the view's rhs_jacobian (exact: generated, or the chain rule of
//               closed load blocks),
//   B = dx'/du  [0; M^-1 dF/du] from the generated jacobians and mass_matrix
//               (exact) for a model without constraints or block states,
//   C = dy/dx, D = dy/du  the generated output_matrices (exact) for the
//               model's own outputs when they do not depend on t itself
//               (output_matrices are evaluated at t = 0),
// and central differences (step 1e-6 (1 + |v|)) where the view lacks the
// exact ones: constrained models (B), closed load blocks (B, C, D).
#include "instance.hpp"

#include <Eigen/Dense>

#include <cmath>

namespace yamsc::fmi {
namespace {

// out (rows x v.size(), row-major) = d f / d v by central differences.
template <class F>
void central_differences(F&& f, std::vector<double> v, std::size_t rows, double* out) {
    std::vector<double> plus(rows), minus(rows);
    const std::size_t n = v.size();
    for (std::size_t j = 0; j < n; ++j) {
        const double v0 = v[j], h = 1e-6 * (1.0 + std::abs(v0));
        v[j] = v0 + h;
        f(v.data(), plus.data());
        v[j] = v0 - h;
        f(v.data(), minus.data());
        v[j] = v0;
        for (std::size_t i = 0; i < rows; ++i) out[i * n + j] = (plus[i] - minus[i]) / (2.0 * h);
    }
}

} // namespace

// The blocks of one evaluation point, each formed when first asked for.
struct Jacobian {
    Instance& in;
    std::size_t nx, nu, ny;
    std::vector<double> A, B, C, D;

    explicit Jacobian(Instance& instance)
        : in(instance), nx(instance.n_.x.size()), nu(instance.n_.u.size()),
          ny(static_cast<std::size_t>(instance.view_.ny)) {}

    const std::vector<double>& state_matrix() {
        if (!A.empty() || nx == 0) return A;
        A.resize(nx * nx);
        const runtime::ModelView& v = in.view_;
        if (v.rhs_jacobian)
            v.rhs_jacobian(in.n_.t, in.n_.x.data(), in.n_.u.data(), A.data());
        else
            central_differences(
                [&](const double* x, double* xdot) { v.rhs(in.n_.t, x, in.n_.u.data(), xdot); },
                in.n_.x, nx, A.data());
        return A;
    }

    const std::vector<double>& input_matrix() {
        if (!B.empty() || nx * nu == 0) return B;
        B.assign(nx * nu, 0.0);
        const runtime::ModelView& v = in.view_;
        const std::size_t nq = in.nq_;
        if (v.jacobians && v.mass_matrix && v.nz == 0 && v.nc == 0) {
            std::vector<double> M(nq * nq), dF_dq(nq * nq), dF_dqd(nq * nq), dF_du(nq * nu);
            const double* q = in.n_.x.data();
            v.mass_matrix(in.n_.t, q, in.n_.u.data(), M.data());
            v.jacobians(in.n_.t, q, q + nq, in.n_.u.data(), dF_dq.data(), dF_dqd.data(),
                        dF_du.data());
            using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
            const Eigen::Map<const Matrix> Mm(M.data(), Eigen::Index(nq), Eigen::Index(nq));
            const Eigen::Map<const Matrix> Fu(dF_du.data(), Eigen::Index(nq), Eigen::Index(nu));
            Eigen::Map<Matrix> lower(B.data() + nq * nu, Eigen::Index(nq), Eigen::Index(nu));
            lower = Mm.ldlt().solve(Fu);
        } else {
            central_differences(
                [&](const double* u, double* xdot) { v.rhs(in.n_.t, in.n_.x.data(), u, xdot); },
                in.n_.u, nx, B.data());
        }
        return B;
    }

    const std::vector<double>& output_state_matrix() {
        if (C.empty()) output_matrices();
        return C;
    }
    const std::vector<double>& output_input_matrix() {
        if (D.empty()) output_matrices();
        return D;
    }

    // The generated output_matrices are those of the operating point, at t = 0:
    // exact here only when neither the outputs nor the accelerations they may
    // read change with t itself at this point (prescribed motions do).
    bool free_of_time() const {
        if (in.n_.t == 0.0) return true;
        const runtime::ModelView& v = in.view_;
        const double* x = in.n_.x.data();
        const double* u = in.n_.u.data();
        std::vector<double> now(ny), zero(ny), xdot_now(nx), xdot_zero(nx);
        v.outputs(in.n_.t, x, x + in.nq_, u, now.data());
        v.outputs(0.0, x, x + in.nq_, u, zero.data());
        v.rhs(in.n_.t, x, u, xdot_now.data());
        v.rhs(0.0, x, u, xdot_zero.data());
        return now == zero && xdot_now == xdot_zero;
    }

    void output_matrices() {
        C.assign(ny * nx, 0.0);
        D.assign(ny * nu, 0.0);
        if (ny == 0) return;
        const runtime::ModelView& v = in.view_;
        const std::size_t nq = in.nq_;
        if (in.unit_.output_matrices && v.nz == 0 && ny == in.unit_.output_names.size() &&
            free_of_time()) {
            const double* q = in.n_.x.data();
            in.unit_.output_matrices(in.n_.p.data(), q, q + nq, in.n_.u.data(), C.data(), D.data());
            return;
        }
        central_differences(
            [&](const double* x, double* y) { v.outputs(in.n_.t, x, x + nq, in.n_.u.data(), y); },
            in.n_.x, ny, C.data());
        central_differences(
            [&](const double* u, double* y) {
                v.outputs(in.n_.t, in.n_.x.data(), in.n_.x.data() + nq, u, y);
            },
            in.n_.u, ny, D.data());
    }
};

Status Instance::directional_derivative(const std::uint32_t* unknowns, std::size_t n_unknowns,
                                        const std::uint32_t* knowns, std::size_t n_knowns,
                                        const double* seed, double* sensitivity, bool adjoint) {
    const char* what = adjoint ? "GetAdjointDerivative" : "GetDirectionalDerivative";
    if (!allowed(what, {Mode::initialization, Mode::event, Mode::continuous_time, Mode::step,
                        Mode::terminated}))
        return Status::error;
    refresh_view();
    const std::size_t nx = n_.x.size();
    // Rows: derivatives (0 .. nx) then outputs; columns: states then inputs.
    std::vector<std::size_t> rows(n_unknowns), cols(n_knowns);
    for (std::size_t i = 0; i < n_unknowns; ++i) {
        const Variable* v = variable(unknowns[i], what);
        if (!v) return Status::error;
        if (const auto k = derivative_index(*v))
            rows[i] = *k;
        else if (v->role == Role::output)
            rows[i] = nx + static_cast<std::size_t>(v->index);
        else
            return fail(std::string(what) + ": " + v->name + " is not a derivative or an output");
    }
    for (std::size_t j = 0; j < n_knowns; ++j) {
        const Variable* v = variable(knowns[j], what);
        if (!v) return Status::error;
        if (const auto k = state_index(*v))
            cols[j] = *k;
        else if (v->role == Role::input)
            cols[j] = nx + static_cast<std::size_t>(v->index);
        else
            return fail(std::string(what) + ": " + v->name + " is not a state or an input");
    }
    Jacobian J(*this);
    const std::size_t nu = n_.u.size();
    auto entry = [&](std::size_t r, std::size_t c) {
        if (r < nx)
            return c < nx ? J.state_matrix()[r * nx + c] : J.input_matrix()[r * nu + (c - nx)];
        const std::size_t o = r - nx;
        return c < nx ? J.output_state_matrix()[o * nx + c]
                      : J.output_input_matrix()[o * nu + (c - nx)];
    };
    if (adjoint) {
        for (std::size_t j = 0; j < n_knowns; ++j) {
            double s = 0.0;
            for (std::size_t i = 0; i < n_unknowns; ++i) s += entry(rows[i], cols[j]) * seed[i];
            sensitivity[j] = s;
        }
    } else {
        for (std::size_t i = 0; i < n_unknowns; ++i) {
            double s = 0.0;
            for (std::size_t j = 0; j < n_knowns; ++j) s += entry(rows[i], cols[j]) * seed[j];
            sensitivity[i] = s;
        }
    }
    return Status::ok;
}

} // namespace yamsc::fmi
