#include "analysis/sim_case.hpp"

#include "analysis/constrained_model.hpp"
#include "analysis/controller_loop.hpp"
#include "analysis/load_blocks.hpp"
#include "analysis/wind_input.hpp"

#include <yamsc/csv.hpp>
#include <yamsc/linear_view.hpp>
#include <yamsc/modal.hpp>

#include <ostream>

namespace yamsc::analysis {

using driver::Channels;
using driver::SimMethod;
using driver::SimOptions;

namespace {

/// The linear model of --linear: about the model's `linearize` point, moved by --at/--u.
runtime::ModelView linear_model(const Loaded& l, const SimOptions& o, std::ostream& out) {
    std::vector<double> q0, qd0, u0;
    operating_point(l, l.params, o.at, o.u, q0, qd0, u0);
    std::vector<double> x0 = q0;
    x0.insert(x0.end(), qd0.begin(), qd0.end());
    // About a point on the constraints: the linear model in all coordinates then
    // moves on their tangent plane.
    consistent_start(l.view, 0.0, x0, u0, false, out);
    const runtime::LinearSystem system = runtime::linearize_view(l.view, x0, u0);
    if (o.verbose) {
        out << "linear model about q0 = (";
        for (std::size_t i = 0; i < x0.size(); ++i)
            out << (i == q0.size() ? "), q0' = (" : i ? ", " : "") << x0[i];
        out << "); modes [Hz]:";
        for (const runtime::Mode& m : runtime::modal_analysis(system.A, l.view.nq))
            if (!m.rigid_body) out << ' ' << m.freq_hz;
        out << "\n";
    }
    return runtime::linear_view(l.view, system);
}

} // namespace

codegen::RoutineSet sim_routines(const SimOptions& o) {
    // rhs and outputs; CVODE's Newton iterations use the exact rhs_jacobian,
    // and --linear linearizes with M and the Jacobians of F.
    using codegen::RoutineId;
    codegen::RoutineSet routines{RoutineId::rhs, RoutineId::outputs};
    if (o.method == SimMethod::cvode) routines.insert(RoutineId::rhs_jacobian);
    if (o.linear) routines.insert({RoutineId::mass_matrix, RoutineId::jacobians});
    add_block_routines(block_options(o), o.method == SimMethod::cvode, routines);
    return routines;
}

SimRun simulate_case(const Loaded& l, const SimOptions& o, std::ostream& out, std::ostream& err) {
    std::vector<double> q, qd;
    initial_state(l, o.ic, q, qd);
    SimRun run;
    run.view = o.linear ? linear_model(l, o, out) : with_load_blocks(l, sim_block_options(o));
    const runtime::ModelView& v = run.view;
    runtime::SimulationOptions s;
    s.t_end = o.tmax;
    s.dt = o.dt;
    s.dt_out = o.dt_out;
    s.method = o.method == SimMethod::cvode  ? runtime::Method::cvode
               : o.method == SimMethod::abm4 ? runtime::Method::abm4
                                             : runtime::Method::rk4;
    s.rtol = o.rtol;
    s.atol = o.atol;
    s.x0 = q;
    s.x0.insert(s.x0.end(), qd.begin(), qd.end());
    s.x0.insert(s.x0.end(), v.block_initial_states.begin(), v.block_initial_states.end());
    s.u = inputs_of(v, o.u);
    if (!o.wind.empty()) s.u_of_t = wind_inputs(l, v, s.u, o.wind);
    // The rows: the run's view's, or with --linear the nonlinear model's.
    const runtime::ModelView& rows = o.linear ? l.view : v;
    if (rows.nc > 0) {
        std::vector<double> u0 = s.u;
        if (s.u_of_t) s.u_of_t(s.t_start, u0.data());
        consistent_start(rows, s.t_start, s.x0, u0, o.verbose, err);
    }
    int last_percent = -1;
    auto progress = [&](double t, double t_end) {
        int percent = static_cast<int>(100.0 * t / t_end);
        if (o.verbose && percent / 10 != last_percent / 10) {
            err << "yamsc: simulated " << percent << " %\n";
            last_percent = percent;
        }
        return true;
    };
    run.result = o.controller.empty()
                     ? runtime::simulate(v, s, progress)
                     : simulate_with_controller(v, s, o.controller, o.controller_input,
                                                output_root_of(o.output), actuators_of(l));
    if (o.verbose && v.nc > 0 && run.result.rows() > 0) {
        // The drift left after the last step's projection (docs/constraints.md).
        std::vector<double> u(static_cast<std::size_t>(v.nu));
        if (s.u_of_t)
            s.u_of_t(run.result.time.back(), u.data());
        else
            u = s.u;
        const runtime::ConstraintResiduals e = runtime::constraint_residual_norms(
            v, run.result.time.back(), run.result.state_row(run.result.rows() - 1), u.data());
        err << "yamsc: constraints at t = " << run.result.time.back()
            << " s: max |phi| = " << e.position << ", max |r| = " << e.velocity << "\n";
    }
    return run;
}

Table sim_table(const SimRun& run, Channels channels) {
    return channels == Channels::openfast ? openfast_table(run.result, 1 + run.view.nx())
                                          : table_of(run.result);
}

void write_sim_csv(const SimRun& run, Channels channels, const std::string& path) {
    if (channels == Channels::openfast)
        write_openfast_csv(run.result, 1 + run.view.nx(), path);
    else
        runtime::write_csv(run.result, path);
}

} // namespace yamsc::analysis
