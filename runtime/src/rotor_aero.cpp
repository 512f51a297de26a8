#include "yamsc/rotor_aero.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

namespace yamsc::runtime {
namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double deg_per_rad = 180.0 / pi;

int index_of(const std::vector<std::string>& names, const std::string& name,
             const std::string& what) {
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return static_cast<int>(i);
    throw std::invalid_argument("rotor aerodynamics: the model has no " + what + " '" + name + "'");
}

/// What the block needs of a point: the loads, and the effective inputs.
struct Closed {
    std::shared_ptr<const ModelView> base;
    std::shared_ptr<const RotorAero> aero;

    double pitch(const double* u) const {
        return aero->pitch_input < 0 ? 0.0 : u[aero->pitch_input];
    }

    /// y: the base outputs at (q, q', u).
    RotorLoads loads(const double* y, const double* u) const {
        const double v_rel = u[aero->wind_input] - y[aero->hub_velocity_output];
        return rotor_loads(*aero, v_rel, y[aero->speed_output], pitch(u));
    }

    /// The base outputs at (q, q', u) as far as the loads read them (rotor
    /// speed, hub velocity). Those are kinematic: outputs_from_qdd with
    /// q'' = NaN gives them without outputs' solve of M q'' = F, with the
    /// same numbers; a NaN in them would mean they read q'': then outputs.
    std::vector<double> load_outputs(double t, const double* q, const double* qd,
                                     const double* u) const {
        std::vector<double> y(static_cast<std::size_t>(base->ny));
        if (base->outputs_from_qdd) {
            const std::vector<double> unknown(static_cast<std::size_t>(base->nq),
                                              std::numeric_limits<double>::quiet_NaN());
            base->outputs_from_qdd(t, q, qd, unknown.data(), u, y.data());
            if (!std::isnan(y[aero->speed_output]) && !std::isnan(y[aero->hub_velocity_output]))
                return y;
        }
        base->outputs(t, q, qd, u, y.data());
        return y;
    }

    /// The block's outputs after the base's ny.
    void append_loads(const RotorLoads& l, double* y) const {
        const double extra[] = {l.thrust, l.torque, l.power, l.tsr, l.v_rel, l.cp, l.ct};
        for (int i = 0; i < 7; ++i) y[base->ny + i] = extra[i];
    }

    std::vector<double> effective_inputs(const RotorLoads& l, const double* u) const {
        std::vector<double> ue(u, u + base->nu);
        ue[static_cast<std::size_t>(aero->thrust_input)] += l.thrust;
        ue[static_cast<std::size_t>(aero->torque_input)] += l.torque;
        return ue;
    }

    /// d(thrust)/dx and d(torque)/dx (2 nq each) through the two outputs, and
    /// d/du (nu each) through the wind and pitch inputs.
    void load_gradients(double t, const double* q, const double* qd, const double* u,
                        const RotorLoads& l, std::vector<double>& dT_dx, std::vector<double>& dQ_dx,
                        std::vector<double>& dT_du, std::vector<double>& dQ_du) const {
        const int nq = base->nq;
        std::vector<double> x(q, q + nq);
        x.insert(x.end(), qd, qd + nq);
        dT_dx.assign(x.size(), 0.0);
        dQ_dx.assign(x.size(), 0.0);
        for (std::size_t j = 0; j < x.size(); ++j) {
            const double h = 1e-6 * (1.0 + std::fabs(x[j]));
            std::vector<double> xp = x, xm = x;
            xp[j] += h;
            xm[j] -= h;
            const auto yp = load_outputs(t, xp.data(), xp.data() + nq, u);
            const auto ym = load_outputs(t, xm.data(), xm.data() + nq, u);
            const double d_speed = (yp[aero->speed_output] - ym[aero->speed_output]) / (2 * h);
            const double d_hub =
                (yp[aero->hub_velocity_output] - ym[aero->hub_velocity_output]) / (2 * h);
            dT_dx[j] = l.dT_dOmega * d_speed - l.dT_dV * d_hub;
            dQ_dx[j] = l.dQ_dOmega * d_speed - l.dQ_dV * d_hub;
        }
        dT_du.assign(static_cast<std::size_t>(base->nu), 0.0);
        dQ_du.assign(static_cast<std::size_t>(base->nu), 0.0);
        dT_du[static_cast<std::size_t>(aero->wind_input)] += l.dT_dV;
        dQ_du[static_cast<std::size_t>(aero->wind_input)] += l.dQ_dV;
        if (aero->pitch_input >= 0) {
            dT_du[static_cast<std::size_t>(aero->pitch_input)] += l.dT_dpitch;
            dQ_du[static_cast<std::size_t>(aero->pitch_input)] += l.dQ_dpitch;
        }
    }
};

} // namespace

RotorLoads rotor_loads(const RotorAero& aero, double v_rel, double omega, double pitch_rad) {
    if (!(v_rel > 0))
        throw std::invalid_argument(
            "rotor aerodynamics: the relative wind at the hub is " + std::to_string(v_rel) +
            " m/s: it must be positive (is the wind input set, e.g. yamsc --wind?)");
    RotorLoads l;
    const double R = aero.radius;
    l.v_rel = v_rel;
    l.tsr = omega * R / v_rel;
    l.pitch_deg = pitch_rad * deg_per_rad;
    const Coefficient cp = interpolate(aero.table, aero.table.cp, l.tsr, l.pitch_deg);
    const Coefficient ct = interpolate(aero.table, aero.table.ct, l.tsr, l.pitch_deg);
    const Coefficient cq = interpolate(aero.table, aero.table.cq, l.tsr, l.pitch_deg);
    l.cp = cp.value;
    l.ct = ct.value;
    l.cq = cq.value;
    const double k = 0.5 * aero.density * pi * R * R; // T = k V^2 Ct, Q = k R V^2 Cq
    l.thrust = k * v_rel * v_rel * ct.value;
    l.torque = k * R * v_rel * v_rel * cq.value;
    l.power = l.torque * omega;
    // dlambda/dV = -lambda/V, dlambda/dOmega = R/V, dbeta_deg/dbeta = 180/pi
    l.dT_dV = k * (2 * v_rel * ct.value - v_rel * l.tsr * ct.d_tsr);
    l.dT_dOmega = k * R * v_rel * ct.d_tsr;
    l.dT_dpitch = k * v_rel * v_rel * ct.d_pitch * deg_per_rad;
    l.dQ_dV = k * R * (2 * v_rel * cq.value - v_rel * l.tsr * cq.d_tsr);
    l.dQ_dOmega = k * R * R * v_rel * cq.d_tsr;
    l.dQ_dpitch = k * R * v_rel * v_rel * cq.d_pitch * deg_per_rad;
    return l;
}

RotorAero bind_rotor_aero(const ModelView& view, PerformanceTable table, double radius,
                          double density, const std::string& wind, const std::string& pitch,
                          const std::string& thrust, const std::string& torque,
                          const std::string& speed, const std::string& hub_velocity) {
    if (!(radius > 0) || !(density > 0))
        throw std::invalid_argument("rotor aerodynamics: radius and density must be positive");
    RotorAero a;
    a.table = std::move(table);
    a.radius = radius;
    a.density = density;
    a.wind_input = index_of(view.input_names, wind, "input");
    a.pitch_input = pitch.empty() ? -1 : index_of(view.input_names, pitch, "input");
    a.thrust_input = index_of(view.input_names, thrust, "input");
    a.torque_input = index_of(view.input_names, torque, "input");
    a.speed_output = index_of(view.output_names, speed, "output");
    a.hub_velocity_output = index_of(view.output_names, hub_velocity, "output");
    return a;
}

ModelView with_rotor_aero(const ModelView& base_view, const RotorAero& aero_spec) {
    if (!base_view.outputs)
        throw std::invalid_argument("rotor aerodynamics: the model view has no outputs");
    // The closures share one copy of the base and the block.
    const Closed c{std::make_shared<const ModelView>(base_view),
                   std::make_shared<const RotorAero>(aero_spec)};
    const ModelView* base = c.base.get();
    ModelView v;
    v.nq = base->nq;
    v.nu = base->nu;
    v.dof_names = base->dof_names;
    v.input_names = base->input_names;
    v.output_names = base->output_names;
    for (const char* n : {"aero_thrust", "aero_torque_out", "aero_power", "aero_tsr", "aero_v_rel",
                          "aero_cp", "aero_ct"})
        v.output_names.emplace_back(n);
    v.ny = static_cast<int>(v.output_names.size());
    const int nq = v.nq;

    if (base->rhs)
        v.rhs = [c, nq](double t, const double* x, const double* u, double* xdot) {
            const RotorLoads l = c.loads(c.load_outputs(t, x, x + nq, u).data(), u);
            c.base->rhs(t, x, c.effective_inputs(l, u).data(), xdot);
        };
    if (base->mass_matrix)
        v.mass_matrix = [c](double t, const double* q, const double* u, double* M) {
            // M does not depend on the loads; u only for prescribed motion.
            c.base->mass_matrix(t, q, u, M);
        };
    if (base->forcing)
        v.forcing = [c](double t, const double* q, const double* qd, const double* u, double* F) {
            const RotorLoads l = c.loads(c.load_outputs(t, q, qd, u).data(), u);
            c.base->forcing(t, q, qd, c.effective_inputs(l, u).data(), F);
        };
    v.outputs = [c](double t, const double* q, const double* qd, const double* u, double* y) {
        // The loads from the kinematic outputs (rotor speed, hub velocity), then
        // every output again with the loads applied: those that read q'' or a
        // reaction load see the rotor's thrust and torque too.
        const RotorLoads l = c.loads(c.load_outputs(t, q, qd, u).data(), u);
        c.base->outputs(t, q, qd, c.effective_inputs(l, u).data(), y);
        c.append_loads(l, y);
    };
    // rhs's q'' is the base's at the effective inputs, as outputs uses them.
    if (base->outputs_from_qdd)
        v.outputs_from_qdd = [c](double t, const double* q, const double* qd, const double* qdd,
                                 const double* u, double* y) {
            const RotorLoads l = c.loads(c.load_outputs(t, q, qd, u).data(), u);
            c.base->outputs_from_qdd(t, q, qd, qdd, c.effective_inputs(l, u).data(), y);
            c.append_loads(l, y);
        };
    if (base->jacobians)
        v.jacobians = [c, nq](double t, const double* q, const double* qd, const double* u,
                              double* dF_dq, double* dF_dqd, double* dF_du) {
            const RotorLoads l = c.loads(c.load_outputs(t, q, qd, u).data(), u);
            const std::vector<double> ue = c.effective_inputs(l, u);
            c.base->jacobians(t, q, qd, ue.data(), dF_dq, dF_dqd, dF_du);
            std::vector<double> dT_dx, dQ_dx, dT_du, dQ_du;
            c.load_gradients(t, q, qd, u, l, dT_dx, dQ_dx, dT_du, dQ_du);
            const int nu = c.base->nu, ti = c.aero->thrust_input, qi = c.aero->torque_input;
            for (int r = 0; r < nq; ++r) {
                // dF/d(load) is F's column of the load's input (F is linear in it
                // when the model applies it as a force or torque; the column is
                // taken at the effective input either way).
                const double fT = dF_du[r * nu + ti], fQ = dF_du[r * nu + qi];
                for (int j = 0; j < nq; ++j) {
                    dF_dq[r * nq + j] += fT * dT_dx[j] + fQ * dQ_dx[j];
                    dF_dqd[r * nq + j] += fT * dT_dx[nq + j] + fQ * dQ_dx[nq + j];
                }
                for (int j = 0; j < nu; ++j)
                    if (j != ti && j != qi) dF_du[r * nu + j] += fT * dT_du[j] + fQ * dQ_du[j];
            }
            // The thrust and torque channels stay additive: their columns are unchanged.
        };
    if (base->rhs_jacobian && base->mass_matrix && base->jacobians)
        v.rhs_jacobian = [c, nq](double t, const double* x, const double* u, double* J) {
            const RotorLoads l = c.loads(c.load_outputs(t, x, x + nq, u).data(), u);
            const std::vector<double> ue = c.effective_inputs(l, u);
            c.base->rhs_jacobian(t, x, ue.data(), J);
            const int nu = c.base->nu, n = 2 * nq;
            std::vector<double> M(static_cast<std::size_t>(nq * nq)), dq(M.size()), dqd(M.size()),
                du(static_cast<std::size_t>(nq * nu));
            c.base->mass_matrix(t, x, ue.data(), M.data());
            c.base->jacobians(t, x, x + nq, ue.data(), dq.data(), dqd.data(), du.data());
            std::vector<double> dT_dx, dQ_dx, dT_du, dQ_du;
            c.load_gradients(t, x, x + nq, u, l, dT_dx, dQ_dx, dT_du, dQ_du);
            Eigen::MatrixXd Me(nq, nq), G(nq, n);
            for (int r = 0; r < nq; ++r) {
                for (int j = 0; j < nq; ++j) Me(r, j) = M[static_cast<std::size_t>(r * nq + j)];
                const double fT = du[static_cast<std::size_t>(r * nu + c.aero->thrust_input)];
                const double fQ = du[static_cast<std::size_t>(r * nu + c.aero->torque_input)];
                for (int j = 0; j < n; ++j)
                    G(r, j) = fT * dT_dx[static_cast<std::size_t>(j)] +
                              fQ * dQ_dx[static_cast<std::size_t>(j)];
            }
            const Eigen::MatrixXd add = Me.ldlt().solve(G); // d q''/dx through the loads
            for (int r = 0; r < nq; ++r)
                for (int j = 0; j < n; ++j) J[(nq + r) * n + j] += add(r, j);
        };
    return v;
}

} // namespace yamsc::runtime
