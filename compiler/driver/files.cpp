#include "driver/files.hpp"

#include "diag/read_text.hpp"

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
    return diag::read_text_file(path, diags);
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
