#include "driver/json.hpp"

#include "text/number.hpp"

#include <cmath>
#include <cstdio>

namespace yamsc::driver::json {

std::string quote(const std::string& s) {
    std::string out = "\"";
    for (unsigned char c : s) {
        switch (c) {
        case '"':
            out += "\\\"";
            break;
        case '\\':
            out += "\\\\";
            break;
        case '\n':
            out += "\\n";
            break;
        case '\t':
            out += "\\t";
            break;
        default:
            if (c < 0x20) {
                char buf[8];
                std::snprintf(buf, sizeof buf, "\\u%04x", c);
                out += buf;
            } else {
                out += static_cast<char>(c);
            }
        }
    }
    return out + "\"";
}

std::string number(double v) {
    if (!std::isfinite(v)) return "null";
    if (v == 0) return "0"; // no "-0"
    return text::shortest_printf(v, 15);
}

std::string array(const std::vector<double>& v) {
    std::string out = "[";
    for (std::size_t i = 0; i < v.size(); ++i) out += (i ? "," : "") + number(v[i]);
    return out + "]";
}

std::string matrix(const std::vector<std::vector<double>>& m) {
    std::string out = "[";
    for (std::size_t i = 0; i < m.size(); ++i) out += (i ? "," : "") + array(m[i]);
    return out + "]";
}

std::string strings(const std::vector<std::string>& v) {
    std::string out = "[";
    for (std::size_t i = 0; i < v.size(); ++i) out += (i ? "," : "") + quote(v[i]);
    return out + "]";
}

} // namespace yamsc::driver::json
