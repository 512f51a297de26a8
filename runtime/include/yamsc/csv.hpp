#pragma once
// Simulation results as CSV (one header row of column names, then one row per
// output time) and as a short text summary for the terminal.
#include "yamsc/simulation.hpp"

#include <ostream>
#include <string>
#include <vector>

namespace yamsc::runtime {

/// Significant digits of every CSV value: enough to reproduce the run's
/// numbers far below any physical tolerance, short enough to stay readable.
inline constexpr int csv_significant_digits = 10;

/// One value as written in the CSV (shortest of fixed/scientific, like %.10g,
/// independent of the C locale).
std::string format_csv_value(double value);
/// The same text appended to `out` without a temporary string.
void append_csv_value(std::string& out, double value);
/// The same text written at `out` (at most csv_value_max_chars characters, no
/// terminating zero); returns the end.
inline constexpr int csv_value_max_chars = 32;
char* write_csv_value(char* out, double value);

/// Values and line ends into a 64 kB buffer, handed to a stream when nearly
/// full and on destruction: what the CSV writers use per row.
class CsvBuffer {
public:
    explicit CsvBuffer(std::ostream& out) : out_(out) {}
    CsvBuffer(const CsvBuffer&) = delete;
    CsvBuffer& operator=(const CsvBuffer&) = delete;
    ~CsvBuffer() { flush(); }

    /// A value, preceded by `separator` unless it is 0.
    void value(double v, char separator = 0) {
        if (end_ - at_ < csv_value_max_chars + 2) flush();
        if (separator) *at_++ = separator;
        at_ = write_csv_value(at_, v);
    }
    void end_line() {
        if (at_ == end_) flush();
        *at_++ = '\n';
    }
    void flush() {
        out_.write(buffer_, at_ - buffer_);
        at_ = buffer_;
    }

private:
    std::ostream& out_;
    char buffer_[65536];
    char* at_ = buffer_;
    char* const end_ = buffer_ + sizeof buffer_;
};

void write_csv(const SimulationResult& result, std::ostream& out);
/// Writes atomically (see atomic_file.hpp); throws std::runtime_error on failure.
void write_csv(const SimulationResult& result, const std::string& path);

struct ChannelSummary {
    std::string name;
    double min = 0.0, max = 0.0, final = 0.0;
};

/// Min, max and final value of every column but time; empty for an empty result.
std::vector<ChannelSummary> summarize(const SimulationResult& result);

/// A table: one line per channel with min, max and final value, preceded by a
/// line with the number of rows and the time span.
std::string format_summary(const SimulationResult& result);

} // namespace yamsc::runtime
