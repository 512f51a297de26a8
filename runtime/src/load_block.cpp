#include "yamsc/load_block.hpp"

#include "added_mass.hpp"
#include "held_loads.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <utility>

namespace yamsc::runtime {

using Vec = std::vector<double>;

namespace {

std::size_t at(int i) {
    return static_cast<std::size_t>(i);
}

/// A central-difference step for a value of this size.
double step(double v) {
    return 1e-6 * (1.0 + std::fabs(v));
}

/// One block closed around a view: what its closures share.
struct Closed {
    std::shared_ptr<const ModelView> base;
    std::shared_ptr<const LoadBlock> block;
    int nq = 0, nxb = 0, nz = 0, nro = 0, nr = 0, nl = 0, nout = 0;

    /// The block at one point: the values it read, its loads, rates and outputs.
    struct Point {
        Vec r, loads, rates, out;
    };

    /// The base outputs at (q, q', u) as far as the block reads them. Those
    /// read the motion: outputs_from_qdd with q'' = NaN gives them without
    /// outputs' solve of M q'' = F, with the same numbers; a NaN in them
    /// would mean they read q'': then outputs.
    Vec read_outputs(double t, const double* q, const double* qd, const double* u) const {
        Vec y(at(base->ny));
        const std::vector<int>& read = block->ports().outputs_read;
        if (base->outputs_from_qdd) {
            const Vec unknown(at(nq), std::numeric_limits<double>::quiet_NaN());
            base->outputs_from_qdd(t, q, qd, unknown.data(), u, y.data());
            bool known = true;
            for (int i : read) known = known && !std::isnan(y[at(i)]);
            if (known) return y;
        }
        base->outputs(t, q, qd, u, y.data());
        return y;
    }

    Vec reads(double t, const double* q, const double* qd, const double* u) const {
        const BlockPorts& p = block->ports();
        Vec r(at(nr));
        if (nro) {
            const Vec y = read_outputs(t, q, qd, u);
            for (int i = 0; i < nro; ++i) r[at(i)] = y[at(p.outputs_read[at(i)])];
        }
        for (int i = nro; i < nr; ++i) {
            const int c = p.inputs_read[at(i - nro)];
            r[at(i)] = c < 0 ? 0.0 : u[c];
        }
        return r;
    }

    /// The block's states: after the base's states, which follow q' (ModelView::nz).
    const double* states(const double* qd) const { return nz ? qd + nq + base->nz : nullptr; }

    /// Loose coupling's history (null: tight).
    std::shared_ptr<detail::HeldLoads> held;

    /// The block evaluated at time t with its states of q' and the values `r` it reads.
    Point evaluate_reading(double t, const double* qd, Vec r) const {
        Point p{std::move(r), Vec(at(nl)), Vec(at(nz)), Vec(at(nout))};
        block->evaluate(t, states(qd), p.r.data(), p.loads.data(), p.rates.data(), p.out.data());
        return p;
    }

    /// The last evaluation: the added mass of a block closed outside this one
    /// asks for its base's q'' at the same motion with other loads, and those
    /// do not change what this block reads (its states, time and reads equal).
    struct Memo {
        std::mutex mutex;
        bool valid = false;
        double t = 0;
        Vec z;
        Point p;
    };
    std::shared_ptr<Memo> memo;

    /// The block evaluated at this point (the last evaluation again when it was
    /// at the same time, states and reads: a block's loads are a function of them,
    /// unless it has discrete states, which are never memoised).
    Point evaluate_here(double t, const double* q, const double* qd, const double* u) const {
        Vec r = reads(t, q, qd, u);
        if (!memo) return evaluate_reading(t, qd, std::move(r));
        const double* z = states(qd);
        {
            const std::lock_guard<std::mutex> lock(memo->mutex);
            if (memo->valid && memo->t == t && memo->p.r == r &&
                std::equal(memo->z.begin(), memo->z.end(), z))
                return memo->p;
        }
        Point p = evaluate_reading(t, qd, std::move(r));
        const std::lock_guard<std::mutex> lock(memo->mutex);
        memo->valid = true;
        memo->t = t;
        memo->z.assign(z, z + nz);
        memo->p = p;
        return p;
    }

    void hold(double t, const Point& p) const {
        Vec values = p.loads;
        values.insert(values.end(), p.out.begin(), p.out.end());
        held->push(t, values.data(), values.size(), p.r);
    }

    /// The block's loads and outputs at this point: evaluated here, or with loose
    /// coupling those of the history at t (a point before it starts it anew:
    /// the run's start, or a new run).
    Point evaluate(double t, const double* q, const double* qd, const double* u) const {
        if (!held) return evaluate_here(t, q, qd, u);
        if (held->empty() || t < held->newest_time()) {
            held->clear();
            Point p = evaluate_here(t, q, qd, u);
            hold(t, p);
            return p;
        }
        Point p{{}, Vec(at(nl)), {}, Vec(at(nout))};
        Vec values(at(nl + nout));
        held->at(t, values.data());
        std::copy(values.begin(), values.begin() + nl, p.loads.begin());
        std::copy(values.begin() + nl, values.end(), p.out.begin());
        return p;
    }

    /// Whether the block's loads depend on the accelerations (LoadBlock::added_mass).
    bool added_mass = false;
    /// The last added-mass matrix evaluated, for loose coupling (whose held
    /// points do not read the motion again).
    std::shared_ptr<Vec> last_added_mass;

    /// The added-mass matrix A (nl x nl) at a point evaluated here, or with
    /// loose coupling the last one.
    Vec added_mass_at(double t, const double* qd, const Point& p) const {
        if (p.r.empty() && last_added_mass && !last_added_mass->empty()) return *last_added_mass;
        const Vec r = p.r.empty() ? Vec(at(nr), 0.0) : p.r;
        Vec A(at(nl * nl), 0.0);
        block->added_mass(t, states(qd), r.data(), A.data());
        if (last_added_mass) *last_added_mass = A;
        return A;
    }

    /// The base's state [q, q', base states] from q and q' given apart (its
    /// states after q', ModelView's convention).
    Vec base_state(const double* q, const double* qd) const {
        Vec x(q, q + nq);
        x.insert(x.end(), qd, qd + (nxb - nq));
        return x;
    }

    /// The base's q'' at state x and inputs ue.
    Vec base_qdd(double t, const Vec& x, const Vec& ue) const {
        Vec xdot(at(nxb));
        base->rhs(t, x.data(), ue.data(), xdot.data());
        return Vec(xdot.begin() + nq, xdot.begin() + 2 * nq);
    }

    /// W = M^-1 G and G of the added-mass algebra at state x with inputs ue (the
    /// base's q'' at ue is qdd0), from one base rhs per load.
    detail::AddedMassTerms added_mass_terms(double t, const Vec& x, const Vec& ue,
                                            const Vec& qdd0) const {
        const std::vector<int>& loads = block->ports().loads;
        std::vector<Vec> qdd_k;
        Vec h(at(nl));
        for (int k = 0; k < nl; ++k) {
            Vec up = ue;
            const std::size_t c = at(loads[at(k)]);
            h[at(k)] = 1.0 + std::fabs(ue[c]); // exact at any step: F is affine in its loads
            up[c] += h[at(k)];
            qdd_k.push_back(base_qdd(t, x, up));
        }
        Vec M(at(nq * nq));
        base->mass_matrix(t, x.data(), ue.data(), M.data());
        return detail::added_mass_terms(nq, nl, M.data(), qdd0, qdd_k, h);
    }

    /// Adds the loads' acceleration part, -A s with s = G^T q'' of the coupled
    /// solution, to p's loads (rhs and outputs, which see the loads applied).
    void accelerate(double t, const double* q, const double* qd, const double* u, Point& p) const {
        const Vec x = base_state(q, qd);
        const Vec ue = effective_inputs(p, u);
        const Vec qdd0 = base_qdd(t, x, ue);
        const detail::AddedMassTerms terms = added_mass_terms(t, x, ue, qdd0);
        const Vec A = added_mass_at(t, qd, p);
        subtract_added_loads(A, detail::coupled_accelerations(terms, A.data(), qdd0), p);
    }

    /// The same, with q'' given (outputs_from_qdd): s = G^T q''.
    void accelerate_with(double t, const double* q, const double* qd, const double* qdd,
                         const double* u, Point& p) const {
        for (int i = 0; i < nq; ++i)
            if (std::isnan(qdd[i])) return; // the caller reads the motion only
        const Vec x = base_state(q, qd);
        const Vec ue = effective_inputs(p, u);
        const detail::AddedMassTerms terms = added_mass_terms(t, x, ue, base_qdd(t, x, ue));
        Vec s(at(nl), 0.0);
        for (int k = 0; k < nl; ++k)
            for (int r = 0; r < nq; ++r) s[at(k)] += terms.G[at(r * nl + k)] * qdd[r];
        subtract_added_loads(added_mass_at(t, qd, p), s, p);
    }

    void subtract_added_loads(const Vec& A, const Vec& s, Point& p) const {
        for (int k = 0; k < nl; ++k)
            for (int j = 0; j < nl; ++j) p.loads[at(k)] -= A[at(k * nl + j)] * s[at(j)];
    }

    /// The point as rhs and outputs apply it: with the acceleration part.
    Point evaluate_accelerated(double t, const double* q, const double* qd, const double* u) const {
        Point p = evaluate(t, q, qd, u);
        if (added_mass) accelerate(t, q, qd, u, p);
        return p;
    }

    /// Whether an outputs_from_qdd call asks for the outputs that read the motion
    /// alone (q'' unknown, read_outputs' call): then the block need not be
    /// evaluated (held loads keep their history's order: evaluated as before).
    bool motion_only(const double* qdd) const {
        if (held) return false;
        for (int i = 0; i < nq; ++i)
            if (!std::isnan(qdd[i])) return false;
        return true;
    }

    /// The outputs that read the motion alone: the base's with the block's loads
    /// unknown (NaN), the block's own NaN. An output that reads the loads, q''
    /// or the block comes out NaN, and read_outputs then asks for outputs.
    void motion_outputs(double t, const double* q, const double* qd, const double* qdd,
                        const double* u, double* y) const {
        Vec ue(u, u + base->nu);
        for (int k : block->ports().loads) ue[at(k)] = std::numeric_limits<double>::quiet_NaN();
        base->outputs_from_qdd(t, q, qd, qdd, ue.data(), y);
        for (int i = 0; i < nout; ++i) y[base->ny + i] = std::numeric_limits<double>::quiet_NaN();
    }

    Vec effective_inputs(const Point& p, const double* u) const {
        Vec ue(u, u + base->nu);
        const std::vector<int>& loads = block->ports().loads;
        for (int k = 0; k < nl; ++k) ue[at(loads[at(k)])] += p.loads[at(k)];
        return ue;
    }

    /// d(outputs read)/d(base state), nro x nxb, by central differences.
    Vec read_outputs_x(double t, const double* x, const double* u) const {
        Vec d(at(nro * nxb));
        const std::vector<int>& read = block->ports().outputs_read;
        for (int j = 0; j < nxb && nro; ++j) {
            const double h = step(x[j]);
            Vec xp(x, x + nxb), xm = xp;
            xp[at(j)] += h;
            xm[at(j)] -= h;
            const Vec yp = read_outputs(t, xp.data(), xp.data() + nq, u);
            const Vec ym = read_outputs(t, xm.data(), xm.data() + nq, u);
            for (int i = 0; i < nro; ++i) {
                const std::size_t o = at(read[at(i)]);
                d[at(i * nxb + j)] = (yp[o] - ym[o]) / (2 * h);
            }
        }
        return d;
    }

    /// Rows d(v)/d(base state, z), (rows x (nxb + nz)), of loads or rates
    /// v(z, r(x)): through the outputs read, and the states.
    Vec chain(const Vec& v_r, const Vec& v_z, int rows, const Vec& dy_dx) const {
        const int n = nxb + nz;
        Vec d(at(rows * n), 0.0);
        for (int k = 0; k < rows; ++k) {
            for (int j = 0; j < nxb; ++j) {
                double s = 0.0;
                for (int i = 0; i < nro; ++i) s += v_r[at(k * nr + i)] * dy_dx[at(i * nxb + j)];
                d[at(k * n + j)] = s;
            }
            for (int j = 0; j < nz; ++j) d[at(k * n + nxb + j)] = v_z[at(k * nz + j)];
        }
        return d;
    }

    /// d(loads)/du (nl x nu) through the inputs read.
    Vec loads_u(const BlockJacobian& bj) const {
        const int nu = base->nu;
        Vec d(at(nl * nu), 0.0);
        for (int k = 0; k < nl; ++k)
            for (int i = nro; i < nr; ++i) {
                const int c = block->ports().inputs_read[at(i - nro)];
                if (c >= 0) d[at(k * nu + c)] += bj.loads_r[at(k * nr + i)];
            }
        return d;
    }

    BlockJacobian derivatives(double t, const double* qd, const Point& p) const {
        BlockJacobian bj;
        bj.loads_z.assign(at(nl * nz), 0.0);
        bj.loads_r.assign(at(nl * nr), 0.0);
        bj.rates_z.assign(at(nz * nz), 0.0);
        bj.rates_r.assign(at(nz * nr), 0.0);
        block->derivatives(t, states(qd), p.r.data(), bj);
        return bj;
    }

    bool is_load(int column) const {
        for (int c : block->ports().loads)
            if (c == column) return true;
        return false;
    }

    void jacobians(double t, const double* q, const double* qd, const double* u, double* dF_dq,
                   double* dF_dqd, double* dF_du) const;
    void rhs_jacobian(double t, const double* x, const double* u, double* J) const;
};

void Closed::jacobians(double t, const double* q, const double* qd, const double* u, double* dF_dq,
                       double* dF_dqd, double* dF_du) const {
    const Point p = evaluate_here(t, q, qd, u);
    const Vec ue = effective_inputs(p, u);
    base->jacobians(t, q, qd, ue.data(), dF_dq, dF_dqd, dF_du);
    Vec x(q, q + nq);
    x.insert(x.end(), qd, qd + nq);
    const BlockJacobian bj = derivatives(t, qd, p);
    const Vec dL_dx = chain(bj.loads_r, bj.loads_z, nl, read_outputs_x(t, x.data(), u));
    const Vec dL_du = loads_u(bj);
    const std::vector<int>& loads = block->ports().loads;
    const int nu = base->nu, n = 2 * nq;
    Vec f(at(nl));
    for (int r = 0; r < nq; ++r) {
        // dF/d(load) is F's column of the load's input (F is linear in it when
        // the model applies it as a force or torque; taken at the effective
        // input either way).
        for (int k = 0; k < nl; ++k) f[at(k)] = dF_du[r * nu + loads[at(k)]];
        for (int j = 0; j < nq; ++j) {
            double sq = 0.0, sqd = 0.0;
            for (int k = 0; k < nl; ++k) {
                sq += f[at(k)] * dL_dx[at(k * n + j)];
                sqd += f[at(k)] * dL_dx[at(k * n + nq + j)];
            }
            dF_dq[r * nq + j] += sq;
            dF_dqd[r * nq + j] += sqd;
        }
        // The load channels stay additive: their columns are unchanged.
        for (int j = 0; j < nu; ++j) {
            if (is_load(j)) continue;
            double s = 0.0;
            for (int k = 0; k < nl; ++k) s += f[at(k)] * dL_du[at(k * nu + j)];
            dF_du[r * nu + j] += s;
        }
    }
}

void Closed::rhs_jacobian(double t, const double* x, const double* u, double* J) const {
    const Point p = evaluate_here(t, x, x + nq, u);
    const Vec ue = effective_inputs(p, u);
    const int n = nxb + nz, nu = base->nu;
    Vec Jb(at(nxb * nxb));
    base->rhs_jacobian(t, x, ue.data(), Jb.data());
    for (int r = 0; r < n; ++r)
        for (int j = 0; j < n; ++j) J[r * n + j] = r < nxb && j < nxb ? Jb[at(r * nxb + j)] : 0.0;
    const BlockJacobian bj = derivatives(t, x + nq, p);
    const Vec dy_dx = read_outputs_x(t, x, u);
    const Vec dL = chain(bj.loads_r, bj.loads_z, nl, dy_dx);
    const Vec dR = chain(bj.rates_r, bj.rates_z, nz, dy_dx);
    for (int r = 0; r < nz; ++r)
        for (int j = 0; j < n; ++j) J[(nxb + r) * n + j] = dR[at(r * n + j)];
    const std::vector<int>& loads = block->ports().loads;
    if (base->nz == 0 && base->mass_matrix && base->jacobians) {
        // d q''/d(x, z) through the loads: M^-1 dF/d(load) d(load)/d(x, z).
        const std::size_t m = at(nq * nq);
        Vec M(m), dq(m), dqd(m), du(at(nq * nu));
        base->mass_matrix(t, x, ue.data(), M.data());
        base->jacobians(t, x, x + nq, ue.data(), dq.data(), dqd.data(), du.data());
        Eigen::MatrixXd Me(nq, nq), G(nq, n);
        for (int r = 0; r < nq; ++r) {
            for (int j = 0; j < nq; ++j) Me(r, j) = M[at(r * nq + j)];
            for (int j = 0; j < n; ++j) {
                double s = 0.0;
                for (int k = 0; k < nl; ++k) s += du[at(r * nu + loads[at(k)])] * dL[at(k * n + j)];
                G(r, j) = s;
            }
        }
        const Eigen::MatrixXd add = Me.ldlt().solve(G);
        for (int r = 0; r < nq; ++r)
            for (int j = 0; j < n; ++j) J[(nq + r) * n + j] += add(r, j);
        return;
    }
    // A base with states of its own: its rates' derivatives in the loads by
    // central differences of its rhs.
    Vec up = ue, xdp(at(nxb)), xdm(at(nxb));
    for (int k = 0; k < nl; ++k) {
        const std::size_t c = at(loads[at(k)]);
        const double h = step(ue[c]);
        up[c] = ue[c] + h;
        base->rhs(t, x, up.data(), xdp.data());
        up[c] = ue[c] - h;
        base->rhs(t, x, up.data(), xdm.data());
        up[c] = ue[c];
        for (int r = 0; r < nxb; ++r) {
            const double d = (xdp[at(r)] - xdm[at(r)]) / (2 * h);
            for (int j = 0; j < n; ++j) J[r * n + j] += d * dL[at(k * n + j)];
        }
    }
}

ModelView close_one(const ModelView& base_view, const std::shared_ptr<const LoadBlock>& block,
                    const BlockCoupling& coupling) {
    if (!base_view.outputs)
        throw std::invalid_argument("load block: the model view has no outputs");
    const BlockPorts& ports = block->ports();
    for (int i : ports.outputs_read)
        if (i < 0 || i >= base_view.ny)
            throw std::invalid_argument("load block: an output read is out of range");
    for (int i : ports.inputs_read)
        if (i >= base_view.nu)
            throw std::invalid_argument("load block: an input read is out of range");
    for (int i : ports.loads)
        if (i < 0 || i >= base_view.nu)
            throw std::invalid_argument("load block: a load's input is out of range");
    Closed c;
    c.base = std::make_shared<const ModelView>(base_view);
    c.block = block;
    const ModelView* base = c.base.get();
    c.nq = base->nq;
    c.nxb = base->nx();
    c.nz = static_cast<int>(block->state_names().size());
    c.nro = static_cast<int>(ports.outputs_read.size());
    c.nr = c.nro + static_cast<int>(ports.inputs_read.size());
    c.nl = static_cast<int>(ports.loads.size());
    const std::vector<std::string> out_names = block->output_names();
    c.nout = static_cast<int>(out_names.size());
    c.added_mass = block->has_added_mass();
    if (c.added_mass) {
        if (!base_view.rhs || !base_view.mass_matrix)
            throw std::invalid_argument("load block: an added mass needs the view's rhs and mass "
                                        "matrix");
        c.last_added_mass = std::make_shared<Vec>();
    }
    if (!block->has_discrete_states()) c.memo = std::make_shared<Closed::Memo>();
    if (coupling.mode == Coupling::loose) {
        if (c.nz > 0)
            throw std::invalid_argument("load block: a block with continuous states couples "
                                        "tightly only (its states are integrated at every stage)");
        c.held = std::make_shared<detail::HeldLoads>(coupling.interp_order);
    }

    ModelView v;
    v.nq = base->nq;
    v.nu = base->nu;
    v.dof_names = base->dof_names;
    v.input_names = base->input_names;
    v.output_names = base->output_names;
    v.output_names.insert(v.output_names.end(), out_names.begin(), out_names.end());
    v.ny = static_cast<int>(v.output_names.size());
    // The constraint rows read q, q' and u only, as before the block.
    v.nh = base->nh;
    v.nc = base->nc;
    v.constraint_names = base->constraint_names;
    v.constraint_dependent = base->constraint_dependent;
    v.constraint_sources = base->constraint_sources;
    v.constraint_residuals = base->constraint_residuals;
    v.constraint_matrix = base->constraint_matrix;
    v.constraint_bias = base->constraint_bias;
    v.constraint_jacobians = base->constraint_jacobians;
    v.project = base->project;
    v.nz = base->nz + c.nz;
    v.block_state_names = base->block_state_names;
    v.block_initial_states = base->block_initial_states;
    const std::vector<std::string> z_names = block->state_names();
    const Vec z0 = block->initial_states();
    if (z0.size() != z_names.size())
        throw std::invalid_argument("load block: initial states do not match its states");
    v.block_state_names.insert(v.block_state_names.end(), z_names.begin(), z_names.end());
    v.block_initial_states.insert(v.block_initial_states.end(), z0.begin(), z0.end());
    const int nq = v.nq, nxb = c.nxb;

    // A block without loads or states (outputs only, the wave elevation) changes
    // neither rhs nor forcing: evaluated for the outputs alone.
    const bool outputs_only = c.nl == 0 && c.nz == 0 && !c.held;
    if (base->rhs && outputs_only)
        v.rhs = base->rhs;
    else if (base->rhs)
        v.rhs = [c, nq, nxb](double t, const double* x, const double* u, double* xdot) {
            const Closed::Point p = c.evaluate_accelerated(t, x, x + nq, u);
            c.base->rhs(t, x, c.effective_inputs(p, u).data(), xdot);
            for (int i = 0; i < c.nz; ++i) xdot[nxb + i] = p.rates[at(i)];
        };
    if (base->mass_matrix)
        v.mass_matrix = [c](double t, const double* q, const double* u, double* M) {
            // M does not depend on the loads (u only for prescribed motion), but
            // an added mass adds G A G^T, at rest (G depends on q only).
            c.base->mass_matrix(t, q, u, M);
            if (!c.added_mass) return;
            // q' = 0, then the base's and the block's states at their start.
            Vec z(at(c.nq), 0.0);
            z.insert(z.end(), c.base->block_initial_states.begin(),
                     c.base->block_initial_states.end());
            const Vec z0 = c.block->initial_states();
            z.insert(z.end(), z0.begin(), z0.end());
            const Closed::Point p = c.evaluate_here(t, q, z.data(), u);
            const Vec x = c.base_state(q, z.data()), ue = c.effective_inputs(p, u);
            const detail::AddedMassTerms terms = c.added_mass_terms(t, x, ue, c.base_qdd(t, x, ue));
            detail::add_added_mass(terms, c.added_mass_at(t, z.data(), p).data(), M);
        };
    const bool second_order = v.nz == 0;
    if (base->forcing && second_order && outputs_only)
        v.forcing = base->forcing;
    else if (base->forcing && second_order)
        v.forcing = [c](double t, const double* q, const double* qd, const double* u, double* F) {
            const Closed::Point p = c.evaluate(t, q, qd, u);
            c.base->forcing(t, q, qd, c.effective_inputs(p, u).data(), F);
        };
    v.outputs = [c](double t, const double* q, const double* qd, const double* u, double* y) {
        // The loads from the outputs read, then every output again with the
        // loads applied: those that read q'' or a reaction load see them too.
        const Closed::Point p = c.evaluate_accelerated(t, q, qd, u);
        c.base->outputs(t, q, qd, c.effective_inputs(p, u).data(), y);
        for (int i = 0; i < c.nout; ++i) y[c.base->ny + i] = p.out[at(i)];
    };
    // rhs's q'' is the base's at the effective inputs, as outputs uses them.
    if (base->outputs_from_qdd)
        v.outputs_from_qdd = [c](double t, const double* q, const double* qd, const double* qdd,
                                 const double* u, double* y) {
            if (c.motion_only(qdd)) {
                c.motion_outputs(t, q, qd, qdd, u, y);
                return;
            }
            Closed::Point p = c.evaluate(t, q, qd, u);
            if (c.added_mass) c.accelerate_with(t, q, qd, qdd, u, p);
            c.base->outputs_from_qdd(t, q, qd, qdd, c.effective_inputs(p, u).data(), y);
            for (int i = 0; i < c.nout; ++i) y[c.base->ny + i] = p.out[at(i)];
        };
    if (base->jacobians && second_order)
        v.jacobians = [c](double t, const double* q, const double* qd, const double* u,
                          double* dF_dq, double* dF_dqd,
                          double* dF_du) { c.jacobians(t, q, qd, u, dF_dq, dF_dqd, dF_du); };
    const bool exact = base->nz == 0 && base->mass_matrix && base->jacobians;
    // With an added mass the integrators take their own differences of rhs.
    if (base->rhs_jacobian && (exact || base->rhs) && !c.added_mass)
        v.rhs_jacobian = [c](double t, const double* x, const double* u, double* J) {
            c.rhs_jacobian(t, x, u, J);
        };
    if (base->update_discrete || block->has_discrete_states() || c.held)
        v.update_discrete = [c](double t, const double* x, const double* u, double t_next,
                                const double* x_next, const double* u_next) {
            if (c.base->update_discrete) c.base->update_discrete(t, x, u, t_next, x_next, u_next);
            if (!c.block->has_discrete_states() && !c.held) return;
            Vec r_next = c.reads(t_next, x_next, x_next + c.nq, u_next);
            if (c.block->has_discrete_states()) {
                const Vec* held_r = c.held ? c.held->reads_at(t) : nullptr;
                const Vec r = held_r ? *held_r : c.reads(t, x, x + c.nq, u);
                c.block->update_discrete_states(t, c.states(x + c.nq), r.data(), t_next,
                                                c.states(x_next + c.nq), r_next.data());
            }
            // The step's end, with the new discrete states (CalcOutput after
            // UpdateStates): what the next step's stages extrapolate.
            if (c.held)
                c.hold(t_next, c.evaluate_reading(t_next, x_next + c.nq, std::move(r_next)));
        };
    if (v.update_discrete)
        v.reset_discrete = [c] {
            if (c.base->reset_discrete) c.base->reset_discrete();
            c.block->reset_discrete_states();
            if (c.held) c.held->clear();
        };
    return v;
}

} // namespace

Vec LoadBlock::initial_states() const {
    return Vec(state_names().size(), 0.0);
}

void LoadBlock::derivatives(double t, const double* z, const double* r, BlockJacobian& j) const {
    central_differences(*this, t, z, r, j, 1e-6);
}

void central_differences(const LoadBlock& block, double t, const double* z, const double* r,
                         BlockJacobian& j, double relative_step) {
    const BlockPorts& p = block.ports();
    const int nz = static_cast<int>(block.state_names().size()),
              nl = static_cast<int>(p.loads.size());
    const int nr = static_cast<int>(p.outputs_read.size() + p.inputs_read.size());
    const int nout = static_cast<int>(block.output_names().size());
    Vec zv(z, z + nz), rv(r, r + nr), lp(at(nl)), lm(at(nl)), rp(at(nz)), rm(at(nz)), out(at(nout));
    // Column `col` of d(loads)/dv and d(rates)/dv by a central difference in v[i].
    auto column = [&](Vec& v, int i, std::vector<double>& dl, std::vector<double>& dr, int ncol) {
        const double v0 = v[at(i)], h = relative_step * (1.0 + std::fabs(v0));
        v[at(i)] = v0 + h;
        block.evaluate(t, zv.data(), rv.data(), lp.data(), rp.data(), out.data());
        v[at(i)] = v0 - h;
        block.evaluate(t, zv.data(), rv.data(), lm.data(), rm.data(), out.data());
        v[at(i)] = v0;
        for (int k = 0; k < nl; ++k) dl[at(k * ncol + i)] = (lp[at(k)] - lm[at(k)]) / (2 * h);
        for (int k = 0; k < nz; ++k) dr[at(k * ncol + i)] = (rp[at(k)] - rm[at(k)]) / (2 * h);
    };
    j.loads_z.assign(at(nl * nz), 0.0);
    j.rates_z.assign(at(nz * nz), 0.0);
    j.loads_r.assign(at(nl * nr), 0.0);
    j.rates_r.assign(at(nz * nr), 0.0);
    for (int i = 0; i < nz; ++i) column(zv, i, j.loads_z, j.rates_z, nz);
    for (int i = 0; i < nr; ++i) column(rv, i, j.loads_r, j.rates_r, nr);
}

ModelView close_blocks(const ModelView& base, const LoadBlocks& blocks, BlockCoupling coupling) {
    ModelView v = base;
    for (const auto& b : blocks) v = close_one(v, b, coupling);
    return v;
}

} // namespace yamsc::runtime
