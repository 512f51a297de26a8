#include "yamsc/aero/rotor_cache.hpp"

#include "yamsc/aero/bem_rotor.hpp"

#include <algorithm>
#include <cstring>

namespace yamsc::aero {

namespace {

template <class M> double* put(double* key, const M& m) {
    return std::copy(m.data(), m.data() + m.size(), key);
}

// The key's length: the wind, the hub's motion, and per blade its root axes,
// its nodes' count, motion and axes, and its winds' count and winds.
std::size_t key_size(const RotorMotion& motion) {
    std::size_t n = 3 + 3 + 9 + 3;
    for (const RotorMotion::Blade& b : motion.blades)
        n += 9 + 1 + 3 * b.position.size() + 3 * b.velocity.size() + 9 * b.axes.size() + 1 +
             3 * b.wind.size();
    return n;
}

bool same(const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

} // namespace

namespace {

// Entries: 2 per slot, its quasi-steady result and its applied one.
int entry_of(std::size_t slot, bool applied) {
    return static_cast<int>(2 * slot) + (applied ? 1 : 0);
}

} // namespace

const RotorResult& RotorCache::entry(int id) const {
    const Slot& s = slots_[static_cast<std::size_t>(id / 2)];
    return id % 2 ? s.applied.front() : s.quasi_steady.front();
}

int RotorCache::recall(const RotorMotion& motion, const Eigen::Vector3d& wind) {
    key_.resize(key_size(motion)); // its storage is reused
    double* k = key_.data();
    k = put(k, wind);
    k = put(k, motion.hub_position);
    k = put(k, motion.hub_axes);
    k = put(k, motion.hub_angular_velocity);
    for (const RotorMotion::Blade& b : motion.blades) {
        k = put(k, b.root_axes);
        *k++ = static_cast<double>(b.position.size());
        for (const auto& p : b.position) k = put(k, p);
        for (const auto& v : b.velocity) k = put(k, v);
        for (const auto& a : b.axes) k = put(k, a);
        *k++ = static_cast<double>(b.wind.size());
        for (const auto& w : b.wind) k = put(k, w);
    }
    ++clock_;
    for (int i = 0; i < static_cast<int>(slots_.size()); ++i) {
        Slot& s = slots_[static_cast<std::size_t>(i)];
        if (!s.solved || !same(s.key, key_)) continue;
        s.used = clock_;
        current_ = i;
        return entry_of(static_cast<std::size_t>(i), false);
    }
    current_ = -1;
    return no_entry;
}

int RotorCache::keep(const RotorResult& result) {
    std::size_t oldest = 0;
    for (std::size_t i = 1; i < slots_.size(); ++i)
        if (slots_[i].used < slots_[oldest].used) oldest = i;
    Slot& s = slots_[oldest];
    s.key = key_;
    s.quasi_steady.resize(1);
    s.quasi_steady.front() = result; // into the storage of the last one
    s.solved = true;
    s.has_applied = false;
    s.used = clock_;
    current_ = static_cast<int>(oldest);
    return entry_of(oldest, false);
}

int RotorCache::recall_applied(std::uint64_t generation, const std::vector<double>& omega) const {
    if (current_ < 0) return no_entry;
    const Slot& s = slots_[static_cast<std::size_t>(current_)];
    if (!s.has_applied || s.generation != generation || !same(s.omega, omega)) return no_entry;
    return entry_of(static_cast<std::size_t>(current_), true);
}

int RotorCache::keep_applied(std::uint64_t generation, const std::vector<double>& omega,
                             const RotorResult& result) {
    if (current_ < 0) return no_entry;
    Slot& s = slots_[static_cast<std::size_t>(current_)];
    s.generation = generation;
    s.omega = omega;
    s.applied.resize(1);
    s.applied.front() = result;
    s.has_applied = true;
    return entry_of(static_cast<std::size_t>(current_), true);
}

void RotorCache::clear() {
    for (Slot& s : slots_) {
        s.solved = false;
        s.has_applied = false;
    }
    current_ = -1;
}

} // namespace yamsc::aero
