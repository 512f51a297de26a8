#include <yamsc/hydro/potential_flow.hpp>

#include "platform_point.hpp"

#include <cmath>
#include <deque>
#include <stdexcept>

namespace yamsc::runtime::hydro {
namespace {

using detail::Matrix6;
using detail::Vector6;

const char* const components[6] = {"Fxi", "Fyi", "Fzi", "Mxi", "Myi", "Mzi"};

/// The velocities of the reference point at multiples of the kernel's step,
/// Conv_Radiation's XDHistory: the newest at `last`, at most kernel-size kept.
class VelocityHistory {
public:
    explicit VelocityHistory(std::size_t size) : size_(size) {}
    bool empty() const { return samples_.empty(); }
    void clear() {
        samples_.clear();
        last_ = -1;
    }
    /// Starts at step `index` with velocity v.
    void start(long index, const Vector6& v) {
        samples_.assign(1, v);
        last_ = index;
    }
    void push(const Vector6& v) {
        samples_.push_back(v);
        if (samples_.size() > size_) samples_.pop_front();
        ++last_;
    }
    long last() const { return last_; }
    const Vector6& back() const { return samples_.back(); }
    /// -dt sum K(t_M - t_k) v_k by the trapezoid rule over the samples held
    /// (Conv_Rdtn_CalcOutput; with one sample both halves fall on it).
    Vector6 force(const std::vector<Matrix6>& K, double dt) const {
        const std::size_t m = samples_.size() - 1;
        Vector6 f = -0.5 * K[m] * samples_.front() - 0.5 * K[0] * samples_[m];
        for (std::size_t k = 1; k < m; ++k) f -= K[m - k] * samples_[k];
        return dt * f;
    }

private:
    std::size_t size_;
    std::deque<Vector6> samples_;
    long last_ = -1;
};

class PotentialFlowBlock final : public LoadBlock {
public:
    explicit PotentialFlowBlock(PotentialFlowSetup s)
        : s_(std::move(s)), history_(s_.radiation_kernel.size()) {
        if (s_.frame_outputs.size() != 18 || s_.loads.size() != 6)
            throw std::invalid_argument("potential flow: a body role has 18 frame outputs and 6 "
                                        "frame inputs");
        if (s_.kernel_dt > 0 && s_.radiation_kernel.empty())
            throw std::invalid_argument("potential flow: a radiation step without a kernel");
        ports_.outputs_read = s_.frame_outputs;
        ports_.loads = s_.loads;
        added_mass_ = detail::to_eigen(s_.added_mass_infinite);
        for (const Mat6& k : s_.radiation_kernel) kernel_.push_back(detail::to_eigen(k));
        prepare_excitation();
    }

    const BlockPorts& ports() const override { return ports_; }

    std::vector<std::string> output_names() const override {
        std::vector<std::string> n;
        for (const char* part : {"Wvs", "HdS", "Rdt", "Add"})
            for (const char* c : components) n.push_back(s_.output_prefix + part + c);
        return n;
    }

    void evaluate(double t, const double*, const double* r, double* loads, double*,
                  double* out) const override {
        const detail::PointState p = detail::point_state(r, s_.reference, s_.origin_at_rest);
        const Vector6 waves = excitation(t);
        const Vector6 hydrostatic = hydrostatics(p.motion);
        const Vector6 qd = Eigen::Map<const Vector6>(p.motion.qd.data());
        const Vector6 radiation = radiation_force(qd);
        const std::array<double, 6> add = platform_matrices_load(s_.additional, p.motion);
        const Vector6 additional = Eigen::Map<const Vector6>(add.data());
        // The rate terms of the point's acceleration under the added mass: w x (w x arm).
        Vector6 rates = Vector6::Zero();
        rates.head<3>() = p.frame.w.cross(p.frame.w.cross(p.arm_ground));
        const Vector6 total = waves + hydrostatic + radiation + additional - added_mass_ * rates;
        for (int i = 0; i < 6; ++i) loads[i] = 0;
        detail::to_body_loads(p, total, loads);
        const Vector6* parts[4] = {&waves, &hydrostatic, &radiation, &additional};
        for (int k = 0; k < 4; ++k)
            for (int i = 0; i < 6; ++i) out[6 * k + i] = (*parts[k])[i];
    }

    bool has_added_mass() const override { return !added_mass_.isZero(0); }

    void added_mass(double, const double*, const double* r, double* A) const override {
        const detail::PointState p = detail::point_state(r, s_.reference, s_.origin_at_rest);
        const Matrix6 J = detail::point_jacobian(p);
        using RowMajor6 = Eigen::Matrix<double, 6, 6, Eigen::RowMajor>;
        Eigen::Map<RowMajor6> out(A);
        out = J.transpose() * added_mass_ * J;
    }

    bool has_discrete_states() const override { return s_.kernel_dt > 0; }

    // Conv_Rdtn_UpdateDiscState: the point's velocity at each multiple of RdtnDT
    // in (t, t_next], linear between the step's ends (one per step when the step
    // is RdtnDT, as in OpenFAST).
    void update_discrete_states(double t, const double*, const double* r, double t_next,
                                const double*, const double* r_next) const override {
        if (!(s_.kernel_dt > 0)) return;
        const Vector6 v0 = velocity(r), v1 = velocity(r_next);
        const double dt = s_.kernel_dt;
        if (history_.empty())
            history_.start(static_cast<long>(std::floor(t / dt * (1 + 1e-12))), v0);
        const long last = static_cast<long>(std::floor(t_next / dt * (1 + 1e-12) + 1e-9));
        while (history_.last() < last) {
            const double tk = static_cast<double>(history_.last() + 1) * dt;
            const double s =
                t_next > t ? std::min(1.0, std::max(0.0, (tk - t) / (t_next - t))) : 1.0;
            history_.push((1 - s) * v0 + s * v1);
        }
        // Constant until the next update: the newest sample is that of the last
        // multiple of RdtnDT, not the current velocity.
        radiation_ = history_.force(kernel_, dt);
    }

    void reset_discrete_states() const override {
        history_.clear();
        radiation_.setZero();
    }

private:
    Vector6 velocity(const double* r) const {
        const detail::PointState p = detail::point_state(r, s_.reference, s_.origin_at_rest);
        return Eigen::Map<const Vector6>(p.motion.qd.data());
    }

    Vector6 radiation_force(const Vector6& qd) const {
        if (!(s_.kernel_dt > 0)) return Vector6::Zero();
        // Before the first step (and in `lin`) HydroDyn's history holds the
        // initial velocity alone.
        if (history_.empty()) {
            VelocityHistory start(kernel_.size());
            start.start(0, qd);
            return start.force(kernel_, s_.kernel_dt);
        }
        return radiation_;
    }

    // WAMIT.f90's F_HS: -C q on heave, roll and pitch plus the buoyancy at rest
    // (rho g V0 and its moment about the point), in the frame turned by the yaw
    // angle, then to ground axes.
    Vector6 hydrostatics(const PlatformMotion& m) const {
        const double rho_g_v = s_.water.density * s_.water.gravity * s_.displaced_volume;
        Vector6 h = Vector6::Zero();
        for (std::size_t i = 2; i < 5; ++i)
            for (std::size_t j = 2; j < 5; ++j)
                h[static_cast<int>(i)] -= s_.hydrostatic[6 * i + j] * m.q[j];
        h[2] += rho_g_v;
        h[3] += rho_g_v * (s_.cob_y - s_.reference[1]);
        h[4] -= rho_g_v * (s_.cob_x - s_.reference[0]);
        const double c = std::cos(m.q[5]), sn = std::sin(m.q[5]);
        Vector6 g;
        for (int k = 0; k < 2; ++k) {
            g[3 * k] = c * h[3 * k] - sn * h[3 * k + 1];
            g[3 * k + 1] = sn * h[3 * k] + c * h[3 * k + 1];
            g[3 * k + 2] = h[3 * k + 2];
        }
        return g;
    }

    void prepare_excitation() {
        if (s_.excitation.omega.empty() || !s_.waves) return;
        const std::vector<WaveComponent>& waves = s_.waves->components();
        omegas_.reserve(waves.size());
        forces_.reserve(waves.size());
        for (const WaveComponent& w : waves) {
            omegas_.push_back(w.omega);
            const auto x = s_.excitation.at(w.omega, s_.waves->direction());
            std::array<std::complex<double>, 6> f;
            for (std::size_t i = 0; i < 6; ++i) f[i] = x[i] * w.amplitude;
            forces_.push_back(f);
        }
        const double dt = s_.waves->time_step(), period = s_.waves->period();
        if (!(dt > 0)) return;
        if (!(period >= dt) || period / dt > 1e8)
            throw std::invalid_argument("potential flow: the excitation's period must hold its "
                                        "step (at most 1e8 times)");
        const std::size_t n = static_cast<std::size_t>(std::llround(period / dt));
        table_.assign(n, Vector6::Zero());
        for (std::size_t c = 0; c < forces_.size(); ++c) {
            const std::complex<double> step = std::polar(1.0, omegas_[c] * dt);
            std::complex<double> rot = 1;
            for (std::size_t k = 0; k < n; ++k) {
                // Restart the rotation now and then: its rounding grows with k.
                if (k % 1024 == 0) rot = std::polar(1.0, omegas_[c] * static_cast<double>(k) * dt);
                for (int i = 0; i < 6; ++i)
                    table_[k][i] += (forces_[c][static_cast<std::size_t>(i)] * rot).real();
                rot *= step;
            }
        }
    }

    Vector6 excitation(double t) const {
        Vector6 f = Vector6::Zero();
        if (forces_.empty()) return f;
        if (table_.empty()) {
            for (std::size_t c = 0; c < forces_.size(); ++c) {
                const std::complex<double> rot = std::polar(1.0, omegas_[c] * t);
                for (int i = 0; i < 6; ++i)
                    f[i] += (forces_[c][static_cast<std::size_t>(i)] * rot).real();
            }
            return f;
        }
        const double dt = s_.waves->time_step();
        const double period = dt * static_cast<double>(table_.size());
        double x = std::fmod(t, period);
        if (x < 0) x += period;
        const double u = x / dt;
        const std::size_t k = std::min(table_.size() - 1, static_cast<std::size_t>(u));
        const double s = u - static_cast<double>(k);
        return (1 - s) * table_[k] + s * table_[(k + 1) % table_.size()];
    }

    PotentialFlowSetup s_;
    BlockPorts ports_;
    Matrix6 added_mass_;
    std::vector<Matrix6> kernel_;
    std::vector<double> omegas_;                              // the components' frequencies
    std::vector<std::array<std::complex<double>, 6>> forces_; // X a per wave component
    std::vector<Vector6> table_;                              // the excitation on its grid
    mutable VelocityHistory history_;
    mutable Vector6 radiation_ = Vector6::Zero(); // the history's force
};

} // namespace

std::shared_ptr<const LoadBlock> potential_flow_block(PotentialFlowSetup setup) {
    return std::make_shared<const PotentialFlowBlock>(std::move(setup));
}

} // namespace yamsc::runtime::hydro
