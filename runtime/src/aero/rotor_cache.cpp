#include "yamsc/aero/rotor_cache.hpp"

#include "yamsc/aero/bem_rotor.hpp"

#include <cstring>

namespace yamsc::aero {

namespace {

template <class M> void append(std::vector<double>& key, const M& m) {
    key.insert(key.end(), m.data(), m.data() + m.size());
}

bool same(const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

} // namespace

bool RotorCache::recall(const RotorMotion& motion, const Eigen::Vector3d& wind,
                        RotorResult& result) {
    key_.clear();
    append(key_, wind);
    append(key_, motion.hub_position);
    append(key_, motion.hub_axes);
    append(key_, motion.hub_angular_velocity);
    for (const RotorMotion::Blade& b : motion.blades) {
        append(key_, b.root_axes);
        key_.push_back(static_cast<double>(b.position.size()));
        for (const auto& p : b.position) append(key_, p);
        for (const auto& v : b.velocity) append(key_, v);
        for (const auto& a : b.axes) append(key_, a);
        key_.push_back(static_cast<double>(b.wind.size()));
        for (const auto& w : b.wind) append(key_, w);
    }
    ++clock_;
    for (int i = 0; i < static_cast<int>(slots_.size()); ++i) {
        Slot& s = slots_[static_cast<std::size_t>(i)];
        if (!s.solved || !same(s.key, key_)) continue;
        s.used = clock_;
        current_ = i;
        result = s.quasi_steady.front();
        return true;
    }
    current_ = -1;
    return false;
}

void RotorCache::keep(const RotorResult& result) {
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
}

bool RotorCache::recall_applied(std::uint64_t generation, const std::vector<double>& omega,
                                RotorResult& result) const {
    if (current_ < 0) return false;
    const Slot& s = slots_[static_cast<std::size_t>(current_)];
    if (!s.has_applied || s.generation != generation || !same(s.omega, omega)) return false;
    result = s.applied.front();
    return true;
}

void RotorCache::keep_applied(std::uint64_t generation, const std::vector<double>& omega,
                              const RotorResult& result) {
    if (current_ < 0) return;
    Slot& s = slots_[static_cast<std::size_t>(current_)];
    s.generation = generation;
    s.omega = omega;
    s.applied.resize(1);
    s.applied.front() = result;
    s.has_applied = true;
}

void RotorCache::clear() {
    for (Slot& s : slots_) {
        s.solved = false;
        s.has_applied = false;
    }
    current_ = -1;
}

} // namespace yamsc::aero
