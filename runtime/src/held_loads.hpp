#pragma once
// A loosely coupled block's loads and outputs at the accepted steps' ends, and
// their polynomial extrapolation to a stage's time (OpenFAST's glue code with
// ModCoupling 1: a module's outputs are computed once per step, at its end, and
// the inputs a module takes within the next step are extrapolated from the last
// InterpOrder + 1 of them, as FAST_ExtrapInterpMods does). Internal to the runtime.
#include <array>
#include <cstddef>
#include <vector>

namespace yamsc::runtime::detail {

class HeldLoads {
public:
    explicit HeldLoads(int interp_order);

    /// Forgets the history (a new run, or time going back).
    void clear() { count_ = 0; }
    bool empty() const { return count_ == 0; }
    /// The time of the newest entry (not empty()).
    double newest_time() const { return entries_[newest_].t; }
    /// Adds the values at t after the newest (older beyond the order are dropped),
    /// with the values the block read for them.
    void push(double t, const double* values, std::size_t n, const std::vector<double>& reads);
    /// What the block read for the newest values, if they are of time t, else null:
    /// the inputs AeroDyn's UpdateStates takes at a step's start are those its
    /// CalcOutput took there, not the controller's demand applied since.
    const std::vector<double>* reads_at(double t) const;
    /// The values at t: an entry's own when t is its time, else the Lagrange
    /// polynomial through the newest min(order + 1, size) entries.
    void at(double t, double* values) const;

private:
    struct Entry {
        double t = 0;
        std::vector<double> values, reads;
    };
    int order_;
    std::array<Entry, 3> entries_; // a ring of the newest order + 1
    std::size_t newest_ = 0, count_ = 0;
};

} // namespace yamsc::runtime::detail
