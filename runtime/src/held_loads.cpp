#include "held_loads.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace yamsc::runtime::detail {

HeldLoads::HeldLoads(int interp_order) : order_(interp_order) {
    if (interp_order < 0 || interp_order > 2)
        throw std::invalid_argument("loose coupling: the interpolation order is 0, 1 or 2, not " +
                                    std::to_string(interp_order));
}

void HeldLoads::push(double t, const double* values, std::size_t n,
                     const std::vector<double>& reads) {
    newest_ = count_ == 0 ? 0 : (newest_ + 1) % entries_.size();
    Entry& e = entries_[newest_];
    e.t = t;
    e.values.assign(values, values + n);
    e.reads = reads;
    count_ = std::min(count_ + 1, static_cast<std::size_t>(order_) + 1);
}

const std::vector<double>* HeldLoads::reads_at(double t) const {
    return count_ > 0 && entries_[newest_].t == t ? &entries_[newest_].reads : nullptr;
}

void HeldLoads::at(double t, double* values) const {
    const std::size_t n = entries_[newest_].values.size();
    const Entry* used[3];
    for (std::size_t i = 0; i < count_; ++i)
        used[i] = &entries_[(newest_ + entries_.size() - i) % entries_.size()];
    // A step's own time (the grid's times differ by rounding only from a stage's).
    const double span = count_ > 1 ? used[0]->t - used[1]->t : 1.0;
    for (std::size_t i = 0; i < count_; ++i)
        if (std::abs(t - used[i]->t) <= 1e-9 * std::abs(span)) {
            std::copy(used[i]->values.begin(), used[i]->values.end(), values);
            return;
        }
    double weight[3];
    for (std::size_t i = 0; i < count_; ++i) {
        weight[i] = 1.0;
        for (std::size_t j = 0; j < count_; ++j)
            if (j != i) weight[i] *= (t - used[j]->t) / (used[i]->t - used[j]->t);
    }
    for (std::size_t k = 0; k < n; ++k) {
        double v = 0.0;
        for (std::size_t i = 0; i < count_; ++i) v += weight[i] * used[i]->values[k];
        values[k] = v;
    }
}

} // namespace yamsc::runtime::detail
