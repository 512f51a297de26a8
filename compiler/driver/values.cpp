#include "driver/values.hpp"

#include <cmath>
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

} // namespace yamsc::driver
