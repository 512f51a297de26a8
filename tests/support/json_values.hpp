#pragma once
// Numbers out of the JSON of `yamsc lin --json` and friends, for tests: a
// value found by its key, arrays of numbers and matrices as rows of them.
#include <doctest/doctest.h>

#include <cstdlib>
#include <string>
#include <vector>

namespace test_support {

/// The numbers of `[n, n, ...]` starting at `p`; `p` is left after the `]`.
inline std::vector<double> json_numbers(const char*& p) {
    REQUIRE(*p == '[');
    ++p;
    std::vector<double> out;
    while (*p != ']') {
        char* end = nullptr;
        out.push_back(std::strtod(p, &end));
        REQUIRE_MESSAGE(end != p, "not a number: " << std::string(p).substr(0, 40));
        p = end;
        if (*p == ',') ++p;
    }
    ++p;
    return out;
}

/// Where the value of the first `"key":` starts.
inline const char* json_value(const std::string& json, const std::string& key) {
    const auto at = json.find("\"" + key + "\":");
    REQUIRE_MESSAGE(at != std::string::npos, key << " in " << json.substr(0, 200));
    return json.c_str() + at + key.size() + 3;
}

/// The numbers of the first `"key":[...]` (an array of numbers).
inline std::vector<double> json_array(const std::string& json, const std::string& key) {
    const char* p = json_value(json, key);
    return json_numbers(p);
}

/// The rows of the first `"key":[[...],[...]]` (a matrix).
inline std::vector<std::vector<double>> json_matrix(const std::string& json,
                                                    const std::string& key) {
    const char* p = json_value(json, key);
    REQUIRE(*p == '[');
    ++p;
    std::vector<std::vector<double>> rows;
    while (*p == '[') {
        rows.push_back(json_numbers(p));
        if (*p == ',') ++p;
    }
    REQUIRE(*p == ']');
    return rows;
}

/// The first number after `"key":`.
inline double json_number(const std::string& json, const std::string& key) {
    const char* p = json_value(json, key);
    char* end = nullptr;
    const double v = std::strtod(p, &end);
    REQUIRE_MESSAGE(end != p, key << " is not a number");
    return v;
}

/// The number after every `"key":`, in order (a key of each object of an array).
inline std::vector<double> json_numbers_of(const std::string& json, const std::string& key) {
    const std::string quoted = "\"" + key + "\":";
    std::vector<double> out;
    for (auto at = json.find(quoted); at != std::string::npos; at = json.find(quoted, at + 1))
        out.push_back(std::strtod(json.c_str() + at + quoted.size(), nullptr));
    return out;
}

} // namespace test_support
