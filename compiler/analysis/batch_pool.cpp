#include "analysis/batch_pool.hpp"

#include <algorithm>
#include <sched.h>
#include <thread>

namespace yamsc::analysis {

namespace {

volatile std::sig_atomic_t stop_requested = 0;
extern "C" void request_stop(int) {
    stop_requested = 1;
}

std::size_t usable_cores() {
    cpu_set_t set;
    if (::sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) > 0)
        return static_cast<std::size_t>(CPU_COUNT(&set));
    return std::max(1u, std::thread::hardware_concurrency());
}

} // namespace

std::size_t thread_count(int requested, std::size_t jobs) {
    const std::size_t wanted = requested > 0 ? static_cast<std::size_t>(requested) : usable_cores();
    return std::max<std::size_t>(1, std::min<std::size_t>(wanted, jobs));
}

StopOnSignal::StopOnSignal(bool enabled) : enabled_(enabled) {
    stop_requested = 0;
    if (!enabled_) return;
    for (int i = 0; i < 2; ++i) {
        old_[i] = std::signal(signals_[i], request_stop);
        if (old_[i] == SIG_IGN) std::signal(signals_[i], SIG_IGN);
    }
}

StopOnSignal::~StopOnSignal() {
    if (enabled_)
        for (int i = 0; i < 2; ++i) std::signal(signals_[i], old_[i]);
}

bool StopOnSignal::stopped() const {
    return stop_requested != 0;
}

} // namespace yamsc::analysis
