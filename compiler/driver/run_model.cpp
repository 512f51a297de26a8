// `yamsc sim` and `yamsc lin`: the model's generated code, compiled on the fly,
// driven by the runtime.
#include "driver/bindings.hpp"
#include "driver/commands.hpp"
#include "driver/jit.hpp"
#include "driver/json.hpp"
#include "driver/pipeline.hpp"
#include "driver/sid_values.hpp"

#include <yamsc/csv.hpp>
#include <yamsc/modal.hpp>
#include <yamsc/simulation.hpp>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <ostream>

namespace yamsc::driver {

namespace {

/// A model compiled and bound to its parameters, ready to run.
struct Loaded {
    std::unique_ptr<runtime::SharedModel> library;
    runtime::ModelView view;
    std::vector<double> params;
};

std::optional<Loaded> load(const std::string& path, const std::vector<Assignment>& set,
                           const std::string& sid_spec, bool verbose, std::ostream& err) {
    diag::Diagnostics diags;
    auto progress = [&](const std::string& s) {
        if (verbose) err << "yamsc: " << s << "\n";
    };
    FrontEnd fe = run_front_end(path, Until::jacobians, diags, progress);
    err << diags.render();
    if (diags.has_errors()) return std::nullopt;
    JitOptions jit;
    jit.progress = progress;
    Loaded l;
    l.library = load_compiled_model(*fe.equations, jit);
    std::vector<std::optional<double>> defaults;
    for (double v : l.library->default_params())
        defaults.push_back(std::isnan(v) ? std::nullopt : std::optional<double>(v));
    // --sid values first, so that --set still overrides them.
    std::vector<Assignment> all =
        sid_spec.empty() ? std::vector<Assignment>{} : sid_parameter_values(*fe.model, sid_spec);
    all.insert(all.end(), set.begin(), set.end());
    l.params = bind_named(l.library->param_names(), defaults, all, "parameter");
    l.view = l.library->view(l.params);
    return l;
}

std::vector<double> inputs_of(const runtime::ModelView& v, const std::vector<Assignment>& u) {
    return bind_named(v.input_names, std::vector<std::optional<double>>(v.input_names.size(), 0.0),
                      u, "input");
}

using Dense = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

std::vector<std::vector<double>> rows(const Dense& m) {
    std::vector<std::vector<double>> out(static_cast<std::size_t>(m.rows()));
    for (Eigen::Index i = 0; i < m.rows(); ++i)
        for (Eigen::Index j = 0; j < m.cols(); ++j)
            out[static_cast<std::size_t>(i)].push_back(m(i, j));
    return out;
}

} // namespace

int sim(const SimOptions& o, std::ostream& out, std::ostream& err) {
    auto loaded = load(o.model, o.set, o.sid, o.verbose, err);
    if (!loaded) return 1;
    const runtime::ModelView& v = loaded->view;
    std::vector<double> q, qd;
    bind_state(v.dof_names, o.ic, q, qd, "--ic");
    runtime::SimulationOptions s;
    s.t_end = o.tmax;
    s.dt = o.dt;
    s.method = o.method == "cvode" ? runtime::Method::cvode : runtime::Method::rk4;
    s.rtol = o.rtol;
    s.atol = o.atol;
    s.x0 = q;
    s.x0.insert(s.x0.end(), qd.begin(), qd.end());
    s.u = inputs_of(v, o.u);
    int last_percent = -1;
    auto progress = [&](double t, double t_end) {
        int percent = static_cast<int>(100.0 * t / t_end);
        if (o.verbose && percent / 10 != last_percent / 10) {
            err << "yamsc: simulated " << percent << " %\n";
            last_percent = percent;
        }
        return true;
    };
    runtime::SimulationResult result = runtime::simulate(v, s, progress);
    if (!o.output.empty()) runtime::write_csv(result, o.output);
    out << runtime::format_summary(result);
    if (!o.output.empty()) out << "wrote " << result.rows() << " rows to " << o.output << "\n";
    return 0;
}

int lin(const LinOptions& o, std::ostream& out, std::ostream& err) {
    auto loaded = load(o.model, o.set, o.sid, false, err);
    if (!loaded) return 1;
    const runtime::ModelView& v = loaded->view;
    const int nq = v.nq, nu = v.nu;
    std::vector<double> q, qd;
    bind_state(v.dof_names, o.at, q, qd, "--at");
    std::vector<double> u = inputs_of(v, o.u);
    const double t = 0.0;
    const double* up = nu ? u.data() : nullptr;

    Dense M(nq, nq), dq(nq, nq), dqd(nq, nq), du(nq, std::max(nu, 1));
    Eigen::VectorXd F(nq);
    v.mass_matrix(t, q.data(), up, M.data());
    v.forcing(t, q.data(), qd.data(), up, F.data());
    v.jacobians(t, q.data(), qd.data(), up, dq.data(), dqd.data(), du.data());
    Eigen::LDLT<Eigen::MatrixXd> ldlt(M);
    Eigen::VectorXd qdd = ldlt.solve(F);
    std::vector<double> x0 = q;
    x0.insert(x0.end(), qd.begin(), qd.end());
    std::vector<double> A = runtime::state_matrix_from_view(v, x0, u, t);
    // Linear matrices of eq. 25 at the point: M0 δq'' + C0 δq' + K0 δq = Q0 δu, from the
    // state matrix so that K0 includes -∂(M q''0)/∂q when q''0 != 0.
    Dense C0 = -dqd, Q0 = du.leftCols(nu);
    Dense A_lower(nq, nq);
    for (int i = 0; i < nq; ++i)
        for (int j = 0; j < nq; ++j)
            A_lower(i, j) = A[static_cast<std::size_t>((nq + i) * 2 * nq + j)];
    Dense K0 = -(M * A_lower);
    Dense B = Dense::Zero(2 * nq, nu);
    if (nu) B.bottomRows(nq) = ldlt.solve(Eigen::MatrixXd(Q0));
    std::vector<runtime::Mode> modes = runtime::modal_analysis(A, nq);
    double residual = qdd.cwiseAbs().maxCoeff();

    if (o.json) {
        Dense Am = Eigen::Map<Dense>(A.data(), 2 * nq, 2 * nq);
        out << "{\"dofs\":" << json::strings(v.dof_names)
            << ",\"inputs\":" << json::strings(v.input_names) << ",\"M0\":" << json::matrix(rows(M))
            << ",\"C0\":" << json::matrix(rows(C0)) << ",\"K0\":" << json::matrix(rows(K0))
            << ",\"Q0\":" << json::matrix(rows(Q0)) << ",\"A\":" << json::matrix(rows(Am))
            << ",\"B\":" << json::matrix(rows(B))
            << ",\"equilibrium_residual\":" << json::number(residual) << ",\"modes\":[";
        for (std::size_t i = 0; i < modes.size(); ++i) {
            const auto& m = modes[i];
            out << (i ? "," : "") << "{\"freq_hz\":" << json::number(m.freq_hz)
                << ",\"damping_ratio\":" << json::number(m.damping_ratio)
                << ",\"rigid_body\":" << (m.rigid_body ? "true" : "false") << "}";
        }
        out << "]}\n";
        return 0;
    }
    if (residual > 1e-9)
        err << "yamsc: warning: the operating point is not an equilibrium (max |q''| = " << residual
            << "); the linear model is about a moving point\n";
    char line[160];
    out << "mode  frequency [Hz]  damping ratio  shape (largest DOF)\n";
    for (std::size_t i = 0; i < modes.size(); ++i) {
        const auto& m = modes[i];
        std::size_t big = 0;
        for (std::size_t k = 0; k < m.shape.size(); ++k)
            if (std::abs(m.shape[k]) > std::abs(m.shape[big])) big = k;
        std::string dof = m.shape.empty() ? "" : v.dof_names[big];
        if (m.rigid_body)
            std::snprintf(line, sizeof line, "%4zu  %14s  %13s  %s (rigid-body mode)\n", i + 1, "0",
                          "-", dof.c_str());
        else
            std::snprintf(line, sizeof line, "%4zu  %14.6g  %13.4g  %s%s\n", i + 1, m.freq_hz,
                          std::fabs(m.damping_ratio) < 1e-12 ? 0.0 : m.damping_ratio, dof.c_str(),
                          m.real ? " (non-oscillating)" : "");
        out << line;
    }
    return 0;
}

} // namespace yamsc::driver
