// The wave fields: still water, and linear fields as sums of SeaState's components,
// evaluated exactly at any (t, p) (SeaState's IFFT gives the same values on its time
// grid), with SeaState's stretching rules above and below the still-water level.
#include "waves_linear.hpp"

#include <atomic>
#include <cmath>
#include <stdexcept>

namespace yamsc::runtime::hydro {

namespace {
constexpr double two_pi = 6.28318530717958647692;

class StillWater final : public WaveField {
public:
    explicit StillWater(const Water& water) : water_(water) {}
    const Water& water() const override { return water_; }
    double elevation(double, double, double) const override { return 0; }
    FlowAt flow(double, const Vec3&) const override { return {}; }

private:
    Water water_;
};

// The flow quantities of one point by the default route (no tabulation).
class EvaluatedPoint final : public PointWaves {
public:
    EvaluatedPoint(std::shared_ptr<const WaveField> field, const Vec3& p)
        : field_(std::move(field)), p_(p) {}
    double elevation(double t) const override { return field_->elevation(t, p_[0], p_[1]); }
    FlowAt flow(double t) const override { return field_->flow(t, p_); }

private:
    std::shared_ptr<const WaveField> field_;
    Vec3 p_;
};
} // namespace

const std::vector<WaveComponent>& WaveField::components() const {
    static const std::vector<WaveComponent> none;
    return none;
}

std::shared_ptr<const PointWaves> WaveField::at(const Vec3& p) const {
    // A field owned by a shared_ptr (make_wave_field's) is kept alive by its points; one
    // that is not must outlive them.
    std::shared_ptr<const WaveField> self = weak_from_this().lock();
    if (!self) self = std::shared_ptr<const WaveField>(std::shared_ptr<const WaveField>{}, this);
    return std::make_shared<EvaluatedPoint>(std::move(self), p);
}

namespace {
std::uint64_t next_field_id() {
    static std::atomic<std::uint64_t> next{1};
    return next++;
}
} // namespace

LinearWaveField::LinearWaveField(const WaveSettings& s)
    : water_(s.water), direction_(s.direction), stretching_(s.stretching), dt_(s.dt),
      id_(next_field_id()) {
    if (!(water_.depth > 0)) throw std::invalid_argument("waves: the water depth must be > 0");
    if (!(water_.gravity > 0)) throw std::invalid_argument("waves: gravity must be > 0");
    n_ = wave_time_steps(s.t_max, s.dt);
    period_ = n_ * s.dt;
    d_omega_ = two_pi / period_;
    const auto amplitudes = sea_state_amplitudes(s, n_);
    cos_dir_ = std::cos(direction_);
    sin_dir_ = std::sin(direction_);
    // Only the span of nonzero components is kept; m = 0 carries no wave (k = 0).
    int lo = -1, hi = -1;
    for (int m = 1; m < static_cast<int>(amplitudes.size()); ++m)
        if (amplitudes[static_cast<std::size_t>(m)] != 0.0) {
            if (lo < 0) lo = m;
            hi = m;
        }
    if (lo < 0) return;
    first_ = lo;
    for (int m = lo; m <= hi; ++m) {
        Term c;
        c.omega = m * d_omega_;
        c.k = wave_number(c.omega, water_.gravity, water_.depth);
        c.amplitude = amplitudes[static_cast<std::size_t>(m)];
        c.e2kh = 2 * c.k * water_.depth > 700 ? 0.0 : std::exp(-2 * c.k * water_.depth);
        c.tanh_kh = (1 - c.e2kh) / (1 + c.e2kh);
        terms_.push_back(c);
        if (c.amplitude != 0.0) components_.push_back({c.omega, c.k, c.amplitude});
    }
}

// exp(i omega_m t) for the kept span by the recurrence exp(i (m + 1) dw t) =
// exp(i m dw t) exp(i dw t): one sincos a call, rounding growing as the span's length.
void LinearWaveField::time_phasors(double t, std::vector<std::complex<double>>& out) const {
    const double tr = std::fmod(t, period_);
    const std::complex<double> step = std::polar(1.0, d_omega_ * tr);
    std::complex<double> e = std::polar(1.0, first_ * d_omega_ * tr);
    out.resize(terms_.size());
    for (std::size_t i = 0; i < terms_.size(); ++i) {
        out[i] = e;
        e *= step;
        if ((i & 63) == 63)
            e = std::polar(1.0, (first_ + static_cast<double>(i) + 1) * d_omega_ * tr);
    }
}

double LinearWaveField::elevation(double t, double x, double y) const {
    if (terms_.empty()) return 0;
    thread_local std::vector<std::complex<double>> e;
    time_phasors(t, e);
    const double xp = x * cos_dir_ + y * sin_dir_;
    // The space phasors of the last point asked for: an elevation output asks at
    // one point every time (one sine and cosine per component saved).
    thread_local struct {
        std::uint64_t field = 0;
        double xp = 0;
        std::vector<std::complex<double>> phasors;
    } space;
    if (space.field != id_ || space.xp != xp || space.phasors.size() != terms_.size()) {
        space.phasors.resize(terms_.size());
        for (std::size_t i = 0; i < terms_.size(); ++i)
            space.phasors[i] = std::polar(1.0, -terms_[i].k * xp);
        space.field = id_;
        space.xp = xp;
    }
    double eta = 0;
    for (std::size_t i = 0; i < terms_.size(); ++i)
        eta += (terms_[i].amplitude * e[i] * space.phasors[i]).real();
    return eta;
}

// Written with exp(-2kh) so that deep water neither overflows nor loses digits; the
// exponentials below exp(-700) are zero, taken before the library's slow underflow.
LinearWaveField::DepthFactors LinearWaveField::depth_factors(const Term& m, double z, double h,
                                                             bool slope) {
    if (slope) return {m.k, m.k / m.tanh_kh, m.k * m.tanh_kh};
    auto small_exp = [](double x) { return x < -700 ? 0.0 : std::exp(x); };
    const double ez = small_exp(m.k * z), ed = small_exp(-m.k * (z + 2 * h));
    return {(ez + ed) / (1 - m.e2kh), (ez - ed) / (1 - m.e2kh), (ez + ed) / (1 + m.e2kh)};
}

// The unstretched Airy kinematics at depth z (-h <= z <= 0) as horizontal (along the
// heading) and vertical parts; with `slope`, their z-derivatives at z = 0 instead.
LinearWaveField::Column LinearWaveField::column(double t, double xp, double z, bool slope) const {
    Column c;
    if (terms_.empty()) return c;
    thread_local std::vector<std::complex<double>> e;
    time_phasors(t, e);
    const double h = water_.depth, rho_g = water_.density * water_.gravity;
    for (std::size_t i = 0; i < terms_.size(); ++i) {
        const Term& m = terms_[i];
        const auto [ch_sh, sh_sh, ch_ch] = depth_factors(m, z, h, slope);
        if (ch_sh == 0 && ch_ch == 0) continue; // a short wave, deep below
        const std::complex<double> a = m.amplitude * e[i] * std::polar(1.0, -m.k * xp);
        const double w = m.omega;
        c.u += w * a.real() * ch_sh;
        c.w += -w * a.imag() * sh_sh;
        c.du += -w * w * a.imag() * ch_sh;
        c.dw += -w * w * a.real() * sh_sh;
        c.p += rho_g * a.real() * ch_ch;
    }
    return c;
}

FlowAt LinearWaveField::to_flow(const Column& c) const {
    FlowAt f;
    f.velocity = {c.u * cos_dir_, c.u * sin_dir_, c.w};
    f.acceleration = {c.du * cos_dir_, c.du * sin_dir_, c.dw};
    f.dynamic_pressure = c.p;
    return f;
}

FlowAt LinearWaveField::flow(double t, const Vec3& p) const {
    const double h = water_.depth, z = p[2];
    if (terms_.empty() || z < -h) return {};
    const double xp = p[0] * cos_dir_ + p[1] * sin_dir_;
    if (stretching_ == Stretching::none) return z > 0 ? FlowAt{} : to_flow(column(t, xp, z, false));
    const double eta = elevation(t, p[0], p[1]);
    if (z > eta) return {};
    switch (stretching_) {
    case Stretching::wheeler:
        return to_flow(column(t, xp, std::min(h * (z - eta) / (h + eta), 0.0), false));
    case Stretching::extrapolation:
        if (z > 0) {
            Column c = column(t, xp, 0, false);
            const Column d = column(t, xp, 0, true);
            c.u += z * d.u, c.w += z * d.w, c.du += z * d.du, c.dw += z * d.dw, c.p += z * d.p;
            return to_flow(c);
        }
        break;
    default:
        break;
    }
    return to_flow(column(t, xp, std::min(z, 0.0), false));
}

std::shared_ptr<const WaveField> make_wave_field(const WaveSettings& s) {
    if (s.kind == WaveKind::still) {
        if (!(s.water.depth > 0)) throw std::invalid_argument("waves: the water depth must be > 0");
        return std::make_shared<StillWater>(s.water);
    }
    if (!(s.height > 0)) throw std::invalid_argument("waves: the wave height must be > 0");
    return std::make_shared<LinearWaveField>(s);
}

} // namespace yamsc::runtime::hydro
