#include "analysis/batch_progress.hpp"

#include <cstdio>
#include <ostream>

namespace yamsc::analysis {

namespace {

double since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

Progress::Progress(std::ostream& err, std::size_t total, bool quiet)
    : err_(err), total_(total), quiet_(quiet), start_(Clock::now()), last_(start_) {}

void Progress::finished(bool ok) {
    std::lock_guard<std::mutex> lock(mutex_);
    ++done_;
    if (!ok) ++failed_;
    if (quiet_ || (done_ < total_ && since(last_) < 1.0)) return;
    last_ = Clock::now();
    const double elapsed = since(start_);
    const double eta = elapsed / static_cast<double>(done_) * static_cast<double>(total_ - done_);
    char line[160];
    std::snprintf(line, sizeof line,
                  "yamsc: batch: %zu/%zu done, %zu failed, %.1f s elapsed, ETA %.0f s\n", done_,
                  total_, failed_, elapsed, eta);
    err_ << line << std::flush;
}

std::size_t Progress::done() {
    std::lock_guard<std::mutex> lock(mutex_);
    return done_;
}

} // namespace yamsc::analysis
