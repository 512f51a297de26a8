#pragma once
// The frequency-domain response of a model's linear model in waves, as RAFT
// computes it (docs/hydrodynamics.md, "Frequency-domain response"): the linear
// model of the model with its blocks closed in still water, the excitation per
// unit wave amplitude from the same blocks evaluated in one regular wave at each
// frequency, and the response X(w) of yamsc/frequency_response.hpp.
#include "analysis/load_blocks.hpp"
#include "analysis/loaded_model.hpp"

#include <yamsc/frequency_response.hpp>
#include <yamsc/second_order.hpp>

#include <vector>

namespace yamsc::analysis {

struct WaveResponse {
    std::vector<double> omega;                         ///< rad/s
    std::vector<std::vector<runtime::Complex>> force;  ///< F(w) per frequency, per DOF
    std::vector<std::vector<runtime::Complex>> motion; ///< X(w) per frequency, per DOF
    runtime::SecondOrderModel linear;                  ///< M, C, K in still water
};

struct WaveResponseRequest {
    std::vector<double> omega; ///< rad/s, increasing, > 0
    double direction = 0;      ///< rad, the heading the waves travel toward
    /// The amplitude [m] the loads are sampled in: small, so that the drag
    /// (quadratic in the flow) adds only O(amplitude) to the unit excitation.
    double amplitude = 1e-4;
};

/// The response of `l` with the blocks `b` supplies (their `hydrodyn` blocks in
/// the request's waves, whatever b.sea_state says) at the point (q, q' = 0, u).
/// Throws diag::UserError when the closed view has block states (not linear in
/// this sense) or a frequency's impedance is singular.
WaveResponse wave_response(const Loaded& l, BlockOptions b, const std::vector<double>& q,
                           const std::vector<double>& u, const WaveResponseRequest& r);

} // namespace yamsc::analysis
