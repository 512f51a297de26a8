#include "driver/files.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>

namespace yamsc::driver {

std::shared_ptr<const diag::SourceFile> read_source(const std::string& path,
                                                    diag::Diagnostics& diags) {
    struct stat info {};
    if (::stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode)) {
        diags.error(diag::Kind::Io, diag::Location{}, "cannot read '" + path + "': it is a folder");
        return nullptr;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        diags.error(diag::Kind::Io, diag::Location{},
                    "cannot read '" + path + "': " + std::strerror(errno));
        return nullptr;
    }
    // No reader accepts more than 256 MiB (SID files; models far less): stop there
    // instead of exhausting memory on /dev/zero or an endless pipe.
    constexpr std::size_t max_bytes = std::size_t{256} << 20;
    std::string text;
    char buffer[1 << 16];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
        text.append(buffer, static_cast<std::size_t>(in.gcount()));
        if (text.size() > max_bytes) {
            diags.error(diag::Kind::Limit, diag::Location{},
                        "'" + path + "' is larger than " + std::to_string(max_bytes >> 20) +
                            " MiB, more than any input yamsc reads");
            return nullptr;
        }
    }
    if (in.bad()) {
        diags.error(diag::Kind::Io, diag::Location{}, "cannot read '" + path + "'");
        return nullptr;
    }
    return std::make_shared<diag::SourceFile>(path, std::move(text));
}

std::string digest(const std::string& text) {
    std::uint64_t h = 1469598103934665603ull;
    for (unsigned char c : text) {
        h ^= c;
        h *= 1099511628211ull;
    }
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
}

} // namespace yamsc::driver
