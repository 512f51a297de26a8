#include "driver/values.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace yamsc::driver {

namespace {

std::string trim(const std::string& s) {
    std::size_t b = s.find_first_not_of(" \t");
    std::size_t e = s.find_last_not_of(" \t");
    return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

std::vector<std::string> split(const std::string& text, char sep) {
    std::vector<std::string> out;
    std::size_t start = 0;
    while (true) {
        std::size_t pos = text.find(sep, start);
        out.push_back(trim(text.substr(start, pos - start)));
        if (pos == std::string::npos) break;
        start = pos + 1;
    }
    return out;
}

} // namespace

double parse_value(const std::string& raw, const std::string& option) {
    std::string text = trim(raw);
    bool degrees = false;
    if (text.size() > 3 && text.compare(text.size() - 3, 3, "deg") == 0) {
        degrees = true;
        text = trim(text.substr(0, text.size() - 3));
    }
    char* end = nullptr;
    double v = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(v))
        throw UsageError(option + ": '" + raw + "' is not a number");
    return degrees ? v * M_PI / 180.0 : v;
}

std::vector<double> parse_list(const std::string& text, const std::string& option) {
    std::vector<double> out;
    for (const auto& item : split(text, ',')) out.push_back(parse_value(item, option));
    return out;
}

std::vector<Assignment> parse_assignments(const std::string& text, const std::string& option) {
    std::vector<Assignment> out;
    for (const auto& item : split(text, ',')) {
        std::size_t eq = item.find('=');
        if (eq == std::string::npos || eq == 0)
            throw UsageError(option + ": expected name=value, got '" + item + "'");
        Assignment a;
        a.name = trim(item.substr(0, eq));
        while (!a.name.empty() && a.name.back() == '\'') {
            a.name.pop_back();
            ++a.primes;
        }
        if (a.name.empty()) throw UsageError(option + ": missing name in '" + item + "'");
        a.value = parse_value(item.substr(eq + 1), option);
        out.push_back(a);
    }
    return out;
}

Sweep parse_sweep(const std::string& text) {
    const auto eq = text.find('=');
    const auto c1 = text.find(':', eq == std::string::npos ? 0 : eq);
    const auto c2 = c1 == std::string::npos ? c1 : text.find(':', c1 + 1);
    if (eq == std::string::npos || eq == 0 || c1 == std::string::npos || c2 == std::string::npos)
        throw UsageError("--sweep takes NAME=FROM:STEP:TO, not '" + text + "'");
    Sweep s;
    s.name = text.substr(0, eq);
    const double from = parse_value(text.substr(eq + 1, c1 - eq - 1), "--sweep");
    const double step = parse_value(text.substr(c1 + 1, c2 - c1 - 1), "--sweep");
    const double to = parse_value(text.substr(c2 + 1), "--sweep");
    if (!(step > 0) || to < from)
        throw UsageError("--sweep needs a positive STEP and FROM <= TO, not '" + text + "'");
    const double count = std::floor((to - from) / step + 1e-9) + 1;
    if (count > 10000) throw UsageError("--sweep has more than 10000 values");
    for (int k = 0; k < static_cast<int>(count); ++k) {
        // 0.1 * 3 is 0.30000000000000004: keep the 12 digits the user meant.
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%.12g", from + k * step);
        s.values.push_back(std::strtod(buffer, nullptr));
    }
    return s;
}

} // namespace yamsc::driver
