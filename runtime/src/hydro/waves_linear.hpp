#pragma once
// The linear (Airy) field of SeaState's components, shared by the exact evaluation
// (waves_field.cpp) and the points tabulated on the time grid (waves_point.cpp).
#include "yamsc/hydro/waves.hpp"

#include <cstdint>

namespace yamsc::runtime::hydro {

class LinearWaveField final : public WaveField {
public:
    explicit LinearWaveField(const WaveSettings& s);
    const Water& water() const override { return water_; }
    double elevation(double t, double x, double y) const override;
    FlowAt flow(double t, const Vec3& p) const override;
    const std::vector<WaveComponent>& components() const override { return components_; }
    double direction() const override { return direction_; }
    double period() const override { return period_; }
    double time_step() const override { return dt_; }
    std::shared_ptr<const PointWaves> at(const Vec3& p) const override;

    /// Unstretched kinematics along the heading (u, du) and vertical (w, dw), dynamic
    /// pressure p; or their z-derivatives at z = 0.
    struct Column {
        double u = 0, w = 0, du = 0, dw = 0, p = 0;
    };
    Column column(double t, double xp, double z, bool slope) const;
    FlowAt to_flow(const Column& c) const;
    Stretching stretching() const { return stretching_; }
    int steps() const { return n_; }

    struct Term {
        double omega = 0, k = 0, e2kh = 0, tanh_kh = 0;
        std::complex<double> amplitude;
    };
    /// cosh(k(z+h))/sinh(kh), sinh(k(z+h))/sinh(kh), cosh(k(z+h))/cosh(kh), or with
    /// `slope` their z-derivatives at z = 0.
    struct DepthFactors {
        double ch_sh = 0, sh_sh = 0, ch_ch = 0;
    };
    static DepthFactors depth_factors(const Term& m, double z, double h, bool slope);
    const std::vector<Term>& terms() const { return terms_; }
    int first_index() const { return first_; }
    double cos_dir() const { return cos_dir_; }
    double sin_dir() const { return sin_dir_; }

private:
    void time_phasors(double t, std::vector<std::complex<double>>& out) const;
    Water water_;
    double direction_ = 0, cos_dir_ = 1, sin_dir_ = 0;
    Stretching stretching_ = Stretching::none;
    double dt_ = 0, period_ = 0, d_omega_ = 0;
    int n_ = 0;
    int first_ = 0;           // grid index m of terms_[0]
    std::vector<Term> terms_; // m = first_, first_ + 1, ... (zeros inside the span kept)
    std::uint64_t id_;        // this field among all made (elevation's cache of phasors)
    std::vector<WaveComponent> components_;
};

} // namespace yamsc::runtime::hydro
