#include "resource_uri.hpp"

namespace yamsc::fmi {
namespace {

int hex_digit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

} // namespace

std::optional<std::string> folder_of_file_uri(const std::string& uri) {
    const std::string scheme = "file:";
    if (uri.compare(0, scheme.size(), scheme) != 0) return std::nullopt;
    std::string rest = uri.substr(scheme.size());
    if (rest.compare(0, 2, "//") == 0) {
        // An authority: empty or localhost only (the folder is on this machine).
        const std::size_t slash = rest.find('/', 2);
        const std::string host =
            rest.substr(2, slash == std::string::npos ? std::string::npos : slash - 2);
        if (!host.empty() && host != "localhost") return std::nullopt;
        rest = slash == std::string::npos ? std::string("/") : rest.substr(slash);
    }
    if (rest.empty() || rest[0] != '/') return std::nullopt;
    std::string path;
    for (std::size_t i = 0; i < rest.size(); ++i) {
        if (rest[i] != '%') {
            path += rest[i];
            continue;
        }
        if (i + 2 >= rest.size()) return std::nullopt;
        const int hi = hex_digit(rest[i + 1]), lo = hex_digit(rest[i + 2]);
        if (hi < 0 || lo < 0) return std::nullopt;
        path += static_cast<char>(hi * 16 + lo);
        i += 2;
    }
    if (path.back() != '/') path += '/';
    return path;
}

} // namespace yamsc::fmi
