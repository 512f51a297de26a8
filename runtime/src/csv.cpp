#include "yamsc/csv.hpp"

#include "yamsc/atomic_file.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iomanip>
#include <sstream>

namespace yamsc::runtime {

namespace {

static_assert(csv_significant_digits == 10, "the fast path below writes 10 digits");

// Exactly representable powers of ten, 1e0 .. 1e22.
constexpr double exact_powers[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                   1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                   1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

/// %.10g through std::to_chars (which never consults the locale, unlike printf).
char* slow_value(char* out, double value) {
    const auto [end, error] =
        std::to_chars(out, out + 40, value, std::chars_format::general, csv_significant_digits);
    if (error != std::errc()) {
        std::memcpy(out, "nan", 3);
        return out + 3;
    }
    return end;
}

/// The digits of %.10g by one scaling into [1e9, 1e10) and a rounding, about
/// 10x faster than std::to_chars with a precision. Exact: the scaling by an
/// exact power of ten errs by at most 1.1e-6 on a 10-digit integer, so the
/// rounding is decided unless the fraction lies within 1e-5 of 1/2; those
/// cases, values beyond the exact powers, zero and non-finite values take
/// std::to_chars (test_csv.cpp compares both on millions of values).
char* write_value(char* out, double value) {
    if (!std::isfinite(value) || value == 0.0) return slow_value(out, value);
    const double a = std::fabs(value);
    // floor(log10 a) from the binary exponent: floor(b log10 2) with
    // 78913 / 2^18 ~ log10 2; it may be one too small, which is fixed below.
    std::uint64_t bits = 0;
    std::memcpy(&bits, &a, sizeof bits);
    const int binary = static_cast<int>(bits >> 52) - 1023;
    if (binary < -1000) return slow_value(out, value); // subnormal
    int e = (binary * 78913) >> 18;
    double m = 0.0;
    for (int attempt = 0; attempt < 2; ++attempt) {
        const int shift = 9 - e;
        if (shift > 22 || shift < -22) return slow_value(out, value);
        m = shift >= 0 ? a * exact_powers[shift] : a / exact_powers[-shift];
        if (m < 1e9)
            --e;
        else if (m >= 1e10)
            ++e;
        else
            break;
    }
    if (!(m >= 1e9 && m < 1e10)) return slow_value(out, value);
    auto digits = static_cast<std::uint64_t>(m); // m > 0: truncation is floor
    const double fraction = m - static_cast<double>(digits);
    if (std::fabs(fraction - 0.5) < 1e-5) return slow_value(out, value);
    digits += fraction > 0.5 ? 1 : 0;
    if (digits == 10000000000ULL) {
        digits = 1000000000ULL;
        ++e;
    }
    // The 10 digits, two at a time.
    static constexpr char pairs[] = "00010203040506070809101112131415161718192021222324"
                                    "25262728293031323334353637383940414243444546474849"
                                    "50515253545556575859606162636465666768697071727374"
                                    "75767778798081828384858687888990919293949596979899";
    char d[10];
    auto halves = {static_cast<std::uint32_t>(digits / 100000),
                   static_cast<std::uint32_t>(digits % 100000)};
    int at = 0;
    for (std::uint32_t half : halves) {
        d[at] = static_cast<char>('0' + half / 10000);
        const std::uint32_t rest = half % 10000;
        std::memcpy(d + at + 1, pairs + 2 * (rest / 100), 2);
        std::memcpy(d + at + 3, pairs + 2 * (rest % 100), 2);
        at += 5;
    }
    int count = 10; // significant digits left after dropping trailing zeros
    while (count > 1 && d[count - 1] == '0') --count;
    if (value < 0) *out++ = '-';
    if (e >= -4 && e < 10) {
        if (e >= 0) {
            for (int i = 0; i <= e; ++i) *out++ = d[i];
            if (count > e + 1) {
                *out++ = '.';
                for (int i = e + 1; i < count; ++i) *out++ = d[i];
            }
        } else {
            *out++ = '0';
            *out++ = '.';
            for (int i = -1; i > e; --i) *out++ = '0';
            for (int i = 0; i < count; ++i) *out++ = d[i];
        }
        return out;
    }
    *out++ = d[0];
    if (count > 1) {
        *out++ = '.';
        for (int i = 1; i < count; ++i) *out++ = d[i];
    }
    *out++ = 'e';
    *out++ = e < 0 ? '-' : '+';
    const int x = e < 0 ? -e : e;
    if (x >= 100) *out++ = static_cast<char>('0' + x / 100);
    *out++ = static_cast<char>('0' + x / 10 % 10);
    *out++ = static_cast<char>('0' + x % 10);
    return out;
}

} // namespace

char* write_csv_value(char* out, double value) {
    return write_value(out, value);
}

std::string format_csv_value(double value) {
    char buffer[64];
    return std::string(buffer, write_value(buffer, value));
}

void append_csv_value(std::string& out, double value) {
    char buffer[64];
    out.append(buffer, write_value(buffer, value));
}

void write_csv(const SimulationResult& result, std::ostream& out) {
    for (std::size_t j = 0; j < result.columns.size(); ++j)
        out << (j ? "," : "") << result.columns[j];
    out << '\n';
    // Rows are formatted into one buffer, written out when it is nearly full.
    CsvBuffer text(out);
    const auto nx = static_cast<std::size_t>(result.nx), ny = static_cast<std::size_t>(result.ny);
    for (std::size_t row = 0; row < result.rows(); ++row) {
        text.value(result.time[row]);
        const double* x = result.state_row(row);
        for (std::size_t j = 0; j < nx; ++j) text.value(x[j], ',');
        const double* y = ny ? result.output_row(row) : nullptr;
        for (std::size_t j = 0; j < ny; ++j) text.value(y[j], ',');
        text.end_line();
    }
}

void write_csv(const SimulationResult& result, const std::string& path) {
    write_file_atomically(path, [&](std::ostream& out) { write_csv(result, out); });
}

std::vector<ChannelSummary> summarize(const SimulationResult& result) {
    std::vector<ChannelSummary> channels;
    if (result.rows() == 0) return channels;
    for (std::size_t j = 1; j < result.column_count(); ++j)
        channels.push_back({result.columns[j], result.value(0, j), result.value(0, j),
                            result.value(result.rows() - 1, j)});
    // Row by row through the stored arrays (not value(), which decides per call
    // whether a column is a state or an output).
    const auto nx = static_cast<std::size_t>(result.nx), ny = static_cast<std::size_t>(result.ny);
    if (channels.size() != nx + ny) { // a table not in simulate()'s shape
        for (std::size_t j = 1; j < result.column_count(); ++j)
            for (std::size_t row = 1; row < result.rows(); ++row) {
                const double v = result.value(row, j);
                channels[j - 1].min = std::min(channels[j - 1].min, v);
                channels[j - 1].max = std::max(channels[j - 1].max, v);
            }
        return channels;
    }
    for (std::size_t row = 1; row < result.rows(); ++row) {
        const double* x = result.state_row(row);
        for (std::size_t j = 0; j < nx; ++j) {
            channels[j].min = std::min(channels[j].min, x[j]);
            channels[j].max = std::max(channels[j].max, x[j]);
        }
        const double* y = ny ? result.output_row(row) : nullptr;
        for (std::size_t j = 0; j < ny; ++j) {
            channels[nx + j].min = std::min(channels[nx + j].min, y[j]);
            channels[nx + j].max = std::max(channels[nx + j].max, y[j]);
        }
    }
    return channels;
}

std::string format_summary(const SimulationResult& result) {
    std::ostringstream out;
    if (result.rows() == 0) return "no samples\n";
    out << result.rows() << " samples, t = " << format_csv_value(result.time.front()) << " .. "
        << format_csv_value(result.time.back()) << " s"
        << (result.completed ? "" : " (stopped early)") << '\n';
    const auto channels = summarize(result);
    std::size_t width = 7;
    for (const auto& c : channels) width = std::max(width, c.name.size());
    const int name_width = static_cast<int>(width);
    out << std::left << std::setw(name_width) << "channel" << std::right;
    for (const char* heading : {"min", "max", "final"}) out << ' ' << std::setw(17) << heading;
    out << '\n';
    for (const auto& c : channels) {
        out << std::left << std::setw(name_width) << c.name << std::right;
        for (double v : {c.min, c.max, c.final}) out << ' ' << std::setw(17) << format_csv_value(v);
        out << '\n';
    }
    return out.str();
}

} // namespace yamsc::runtime
