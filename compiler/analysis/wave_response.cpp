#include "analysis/wave_response.hpp"

#include "diag/errors.hpp"

#include <yamsc/hydro/regular_wave.hpp>

#include <cmath>
#include <stdexcept>

namespace yamsc::analysis {

namespace {

/// q'' of the view at (t, q, q' = 0, u).
std::vector<double> accelerations(const runtime::ModelView& v, double t,
                                  const std::vector<double>& q, const std::vector<double>& u) {
    const std::size_t nq = q.size();
    std::vector<double> x(2 * nq, 0.0), xdot(2 * nq);
    std::copy(q.begin(), q.end(), x.begin());
    v.rhs(t, x.data(), u.data(), xdot.data());
    return std::vector<double>(xdot.begin() + static_cast<std::ptrdiff_t>(nq), xdot.end());
}

} // namespace

WaveResponse wave_response(const Loaded& l, BlockOptions b, const std::vector<double>& q,
                           const std::vector<double>& u, const WaveResponseRequest& r) {
    WaveResponse out;
    out.omega = r.omega;
    b.waves = [](const runtime::hydro::Water&) {
        return std::shared_ptr<const runtime::hydro::WaveField>();
    };
    const runtime::ModelView still = with_load_blocks(l, b);
    if (still.nz > 0)
        throw diag::UserError("the frequency response needs blocks without states of their own "
                              "(the closed model has " +
                              std::to_string(still.nz) + ")");
    const std::size_t nq = q.size();
    const std::vector<double> zero(nq, 0.0);
    out.linear = runtime::second_order_model(still, q, zero, u);
    const runtime::LinearDynamics model{still.nq, out.linear.M0, out.linear.C0, out.linear.K0};
    const std::vector<double> at_rest = accelerations(still, 0, q, u);
    const double a = r.amplitude;
    for (double omega : r.omega) {
        b.waves = [omega, a, &r](const runtime::hydro::Water& water) {
            return runtime::hydro::regular_wave(water, omega, a, r.direction);
        };
        const runtime::ModelView wavy = with_load_blocks(l, b);
        // The elevation a cos(w t): the loads a Re(F e^{i w t}), Re F at t = 0 and
        // -Im F a quarter period later.
        const std::vector<double> now = accelerations(wavy, 0, q, u);
        const std::vector<double> later = accelerations(wavy, M_PI / (2 * omega), q, u);
        std::vector<runtime::Complex> f(nq);
        for (std::size_t i = 0; i < nq; ++i) {
            double re = 0, im = 0;
            for (std::size_t j = 0; j < nq; ++j) {
                re += out.linear.M0[i * nq + j] * (now[j] - at_rest[j]);
                im -= out.linear.M0[i * nq + j] * (later[j] - at_rest[j]);
            }
            f[i] = runtime::Complex(re, im) / a;
        }
        try {
            out.motion.push_back(runtime::frequency_response(model, omega, {f}));
        } catch (const std::invalid_argument& e) {
            throw diag::UserError(e.what());
        }
        out.force.push_back(std::move(f));
    }
    return out;
}

} // namespace yamsc::analysis
