#include "yamsc/hydro/regular_wave.hpp"

#include <cmath>
#include <stdexcept>

namespace yamsc::runtime::hydro {

namespace {

class RegularWave final : public WaveField {
public:
    RegularWave(const Water& water, double omega, std::complex<double> amplitude, double direction)
        : water_(water), direction_(direction) {
        if (!(omega > 0)) throw std::invalid_argument("regular_wave: the frequency must be > 0");
        if (!(water.depth > 0)) throw std::invalid_argument("regular_wave: the depth must be > 0");
        components_.push_back({omega, wave_number(omega, water.gravity, water.depth), amplitude});
    }

    const Water& water() const override { return water_; }
    const std::vector<WaveComponent>& components() const override { return components_; }
    double direction() const override { return direction_; }

    double elevation(double t, double x, double y) const override {
        return (components_[0].amplitude * phase(t, x, y)).real();
    }

    FlowAt flow(double t, const Vec3& p) const override {
        FlowAt f;
        const double h = water_.depth, z = p[2];
        if (z > 0 || z < -h) return f;
        const WaveComponent& c = components_[0];
        const double k = c.wave_number, w = c.omega;
        // cosh(k(z+h))/sinh(kh), sinh(k(z+h))/sinh(kh), cosh(k(z+h))/cosh(kh) in
        // exponentials that do not overflow in deep water.
        const double up = std::exp(k * z), down = std::exp(-k * (z + 2 * h)),
                     e = std::exp(-2 * k * h);
        const double ch_sh = (up + down) / (1 - e), sh_sh = (up - down) / (1 - e),
                     ch_ch = (up + down) / (1 + e);
        const std::complex<double> eta = c.amplitude * phase(t, p[0], p[1]);
        const std::complex<double> iw(0, w);
        const std::complex<double> horizontal = w * ch_sh * eta, vertical = iw * sh_sh * eta;
        const double cd = std::cos(direction_), sd = std::sin(direction_);
        f.velocity = {horizontal.real() * cd, horizontal.real() * sd, vertical.real()};
        const std::complex<double> ah = iw * horizontal, av = iw * vertical;
        f.acceleration = {ah.real() * cd, ah.real() * sd, av.real()};
        f.dynamic_pressure = water_.density * water_.gravity * ch_ch * eta.real();
        return f;
    }

private:
    std::complex<double> phase(double t, double x, double y) const {
        const WaveComponent& c = components_[0];
        return std::polar(1.0, c.omega * t - c.wave_number * (x * std::cos(direction_) +
                                                              y * std::sin(direction_)));
    }

    Water water_;
    double direction_;
    std::vector<WaveComponent> components_;
};

} // namespace

std::shared_ptr<const WaveField> regular_wave(const Water& water, double omega,
                                              std::complex<double> amplitude, double direction) {
    return std::make_shared<RegularWave>(water, omega, amplitude, direction);
}

} // namespace yamsc::runtime::hydro
