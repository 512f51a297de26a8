// The .bts files of `yamsc dlc`: each TurbSim input run through `yamsc
// turbulence`'s function, so that a file is the one that command writes, on
// threads (the generator keeps no state between calls).
#include "analysis/batch_pool.hpp"
#include "analysis/commands.hpp"
#include "analysis/dlc.hpp"

#include <atomic>
#include <exception>
#include <mutex>
#include <ostream>
#include <sstream>
#include <thread>

namespace yamsc::analysis {

void generate_winds(const std::vector<WindFile>& winds, int threads, std::ostream& err) {
    std::atomic<std::size_t> next{0};
    std::mutex lock;
    std::exception_ptr failure;
    auto worker = [&] {
        for (std::size_t i = next++; i < winds.size(); i = next++) {
            {
                const std::lock_guard<std::mutex> hold(lock);
                if (failure) return;
                err << "yamsc: dlc: wind " << i + 1 << "/" << winds.size() << ": " << winds[i].bts
                    << "\n"
                    << std::flush;
            }
            try {
                driver::TurbulenceOptions o;
                o.input = winds[i].input;
                o.output = winds[i].bts;
                // Its summary and progress would bury the line per wind.
                std::ostringstream summary, progress;
                turbulence(o, summary, progress);
            } catch (...) {
                const std::lock_guard<std::mutex> hold(lock);
                if (!failure) failure = std::current_exception();
                return;
            }
        }
    };
    std::vector<std::thread> pool;
    const std::size_t n = thread_count(threads, winds.size());
    for (std::size_t t = 1; t < n; ++t) pool.emplace_back(worker);
    worker();
    for (std::thread& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);
}

} // namespace yamsc::analysis
