#pragma once
// The progress of `yamsc batch` on stderr, from any thread.
#include <chrono>
#include <cstddef>
#include <iosfwd>
#include <mutex>

namespace yamsc::analysis {

/// At most one line a second, and the last: cases done and failed, time
/// elapsed, the time left at the rate so far.
class Progress {
public:
    Progress(std::ostream& err, std::size_t total, bool quiet);
    void finished(bool ok);
    std::size_t done();

private:
    using Clock = std::chrono::steady_clock;
    std::ostream& err_;
    std::mutex mutex_;
    std::size_t total_, done_ = 0, failed_ = 0;
    bool quiet_;
    Clock::time_point start_, last_;
};

} // namespace yamsc::analysis
