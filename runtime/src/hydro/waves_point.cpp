// A fixed point's flow tabulated on SeaState's time grid (t_j = j WaveDT, one period)
// by inverse FFTs, as SeaState tabulates its grid's nodes, and interpolated in time
// as SeaState's GridInterp does along its periodic time axis: the cubic through the
// four nearest samples with Catmull-Rom's end slopes. Wheeler stretching moves the evaluation
// depth with the surface, so it is not tabulated: those points evaluate exactly.
#include "../wind/turbulence_fft.hpp"
#include "waves_linear.hpp"

#include <array>
#include <cmath>

namespace yamsc::runtime::hydro {

namespace {

// Real series Re(sum_m c_m exp(2 pi i m j / n)) and the same of d, by one complex
// transform of the Hermitian halves of c and i d.
void two_series(const Fft& fft, int first, const std::vector<std::complex<double>>& c,
                const std::vector<std::complex<double>>& d, std::vector<double>& x,
                std::vector<double>& y) {
    const int n = fft.size();
    std::vector<std::complex<double>> in(static_cast<std::size_t>(n)), out(in.size());
    const std::complex<double> i1(0, 1);
    for (std::size_t q = 0; q < c.size(); ++q) {
        const int m = first + static_cast<int>(q);
        in[static_cast<std::size_t>(m)] += 0.5 * (c[q] + i1 * d[q]);
        in[static_cast<std::size_t>(n - m)] += 0.5 * (std::conj(c[q]) + i1 * std::conj(d[q]));
    }
    fft.inverse(in.data(), out.data());
    x.resize(static_cast<std::size_t>(n) + 1);
    y.resize(x.size());
    for (int j = 0; j < n; ++j) {
        x[static_cast<std::size_t>(j)] = out[static_cast<std::size_t>(j)].real();
        y[static_cast<std::size_t>(j)] = out[static_cast<std::size_t>(j)].imag();
    }
    x[static_cast<std::size_t>(n)] = x[0]; // SeaState repeats the first value as the last
    y[static_cast<std::size_t>(n)] = y[0];
}

struct Series {
    std::vector<double> u, w, du, dw, p;
};

class TabulatedPoint final : public PointWaves {
public:
    TabulatedPoint(const LinearWaveField& field, const Vec3& p)
        : dt_(field.time_step()), period_(field.period()), z_(p[2]), cos_(field.cos_dir()),
          sin_(field.sin_dir()), stretching_(field.stretching()) {
        const double h = field.water().depth;
        const double xp = p[0] * cos_ + p[1] * sin_;
        wet_ = z_ >= -h && (stretching_ != Stretching::none || z_ <= 0);
        slope_ = stretching_ == Stretching::extrapolation && z_ > 0;
        const auto& terms = field.terms();
        const Fft fft(field.steps());
        const double rho_g = field.water().density * field.water().gravity;
        const double ze = std::min(z_, 0.0);
        const std::size_t nt = terms.size();
        std::vector<std::complex<double>> a(nt), u(nt), w(nt), du(nt), dw(nt), pr(nt);
        const std::complex<double> i1(0, 1);
        auto fill = [&](bool slope) {
            for (std::size_t q = 0; q < nt; ++q) {
                const auto& m = terms[q];
                a[q] = m.amplitude * std::polar(1.0, -m.k * xp);
                const auto [ch_sh, sh_sh, ch_ch] = LinearWaveField::depth_factors(m, ze, h, slope);
                u[q] = m.omega * ch_sh * a[q];
                w[q] = i1 * m.omega * sh_sh * a[q];
                du[q] = i1 * m.omega * u[q];
                dw[q] = i1 * m.omega * w[q];
                pr[q] = rho_g * ch_ch * a[q];
            }
        };
        fill(false);
        if (wet_) {
            two_series(fft, field.first_index(), a, pr, eta_, value_.p);
            two_series(fft, field.first_index(), u, w, value_.u, value_.w);
            two_series(fft, field.first_index(), du, dw, value_.du, value_.dw);
        } else {
            std::vector<double> unused;
            two_series(fft, field.first_index(), a, a, eta_, unused);
        }
        if (slope_) {
            fill(true);
            std::vector<double> unused;
            two_series(fft, field.first_index(), u, w, slope_values_.u, slope_values_.w);
            two_series(fft, field.first_index(), du, dw, slope_values_.du, slope_values_.dw);
            two_series(fft, field.first_index(), pr, pr, slope_values_.p, unused);
        }
        pack(value_, rows_);
        if (slope_) pack(slope_values_, slope_rows_);
    }

    double elevation(double t) const override {
        Stencil st;
        locate(t, st);
        return at(eta_, st);
    }

    FlowAt flow(double t) const override {
        if (!wet_) return {};
        Stencil st;
        locate(t, st);
        if (stretching_ != Stretching::none && z_ > at(eta_, st)) return {};
        std::array<double, fields> v = at_row(rows_, st);
        if (slope_) {
            const std::array<double, fields> d = at_row(slope_rows_, st);
            for (std::size_t c = 0; c < fields; ++c) v[c] += z_ * d[c];
        }
        const double u = v[0], w = v[1], du = v[2], dw = v[3], p = v[4];
        FlowAt r;
        r.velocity = {u * cos_, u * sin_, w};
        r.acceleration = {du * cos_, du * sin_, dw};
        r.dynamic_pressure = p;
        return r;
    }

private:
    struct Stencil {
        std::array<std::size_t, 4> j;
        std::array<double, 4> w;
    };
    void locate(double t, Stencil& st) const {
        double tr = std::fmod(t, period_);
        if (tr < 0) tr += period_;
        const double s = tr / dt_;
        const auto n = eta_.size() - 1;
        const double fl = std::min(std::floor(s), static_cast<double>(n - 1));
        const auto j = static_cast<std::size_t>(fl);
        const double f = s - fl, f2 = f * f, f3 = f2 * f;
        st.j = {(j + n - 1) % n, j, (j + 1) % n, (j + 2) % n};
        st.w = {-0.5 * f3 + f2 - 0.5 * f, 1.5 * f3 - 2.5 * f2 + 1, -1.5 * f3 + 2 * f2 + 0.5 * f,
                0.5 * f3 - 0.5 * f2};
    }
    static double at(const std::vector<double>& v, const Stencil& st) {
        return st.w[0] * v[st.j[0]] + st.w[1] * v[st.j[1]] + st.w[2] * v[st.j[2]] +
               st.w[3] * v[st.j[3]];
    }

    // u, w, du, dw, p of one time sample side by side: a flow reads four
    // samples, four cache lines instead of twenty.
    static constexpr std::size_t fields = 5;
    static void pack(Series& s, std::vector<double>& rows) {
        rows.resize(fields * s.u.size());
        for (std::size_t j = 0; j < s.u.size(); ++j) {
            double* r = &rows[fields * j];
            r[0] = s.u[j], r[1] = s.w[j], r[2] = s.du[j], r[3] = s.dw[j], r[4] = s.p[j];
        }
        s = Series{};
    }
    static std::array<double, fields> at_row(const std::vector<double>& rows, const Stencil& st) {
        std::array<double, fields> v;
        const double* r[4];
        for (std::size_t k = 0; k < 4; ++k) r[k] = &rows[fields * st.j[k]];
        for (std::size_t c = 0; c < fields; ++c)
            v[c] = st.w[0] * r[0][c] + st.w[1] * r[1][c] + st.w[2] * r[2][c] + st.w[3] * r[3][c];
        return v;
    }

    double dt_, period_, z_, cos_, sin_;
    Stretching stretching_;
    bool wet_ = false, slope_ = false;
    std::vector<double> eta_;
    Series value_, slope_values_; // while tabulating; then packed in rows_, slope_rows_
    std::vector<double> rows_, slope_rows_;
};

} // namespace

std::shared_ptr<const PointWaves> LinearWaveField::at(const Vec3& p) const {
    if (stretching_ == Stretching::wheeler || terms_.empty()) return WaveField::at(p);
    return std::make_shared<TabulatedPoint>(*this, p);
}

} // namespace yamsc::runtime::hydro
