#include "yamsc/csv.hpp"

#include "yamsc/atomic_file.hpp"

#include <algorithm>
#include <charconv>
#include <iomanip>
#include <sstream>

namespace yamsc::runtime {

std::string format_csv_value(double value) {
    char buffer[64];
    // std::to_chars never consults the locale, unlike printf("%g").
    const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value,
                                            std::chars_format::general, csv_significant_digits);
    if (error != std::errc()) return "nan";
    return std::string(buffer, end);
}

void write_csv(const SimulationResult& result, std::ostream& out) {
    for (std::size_t j = 0; j < result.columns.size(); ++j)
        out << (j ? "," : "") << result.columns[j];
    out << '\n';
    std::string line;
    for (std::size_t row = 0; row < result.rows(); ++row) {
        line.clear();
        for (std::size_t j = 0; j < result.column_count(); ++j) {
            if (j) line += ',';
            line += format_csv_value(result.value(row, j));
        }
        line += '\n';
        out << line;
    }
}

void write_csv(const SimulationResult& result, const std::string& path) {
    write_file_atomically(path, [&](std::ostream& out) { write_csv(result, out); });
}

std::vector<ChannelSummary> summarize(const SimulationResult& result) {
    std::vector<ChannelSummary> channels;
    if (result.rows() == 0) return channels;
    for (std::size_t j = 1; j < result.column_count(); ++j) {
        ChannelSummary channel{result.columns[j], result.value(0, j), result.value(0, j),
                               result.value(result.rows() - 1, j)};
        for (std::size_t row = 1; row < result.rows(); ++row) {
            const double v = result.value(row, j);
            channel.min = std::min(channel.min, v);
            channel.max = std::max(channel.max, v);
        }
        channels.push_back(channel);
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
