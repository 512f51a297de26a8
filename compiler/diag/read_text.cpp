#include "diag/read_text.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sys/stat.h>

namespace yamsc::diag {

std::shared_ptr<const SourceFile> read_text_file(const std::string& path, Diagnostics& diags,
                                                 const Location& where) {
    struct stat info {};
    if (::stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode)) {
        diags.error(Kind::Io, where, "cannot read '" + path + "': it is a folder");
        return nullptr;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        diags.error(Kind::Io, where, "cannot read '" + path + "': " + std::strerror(errno));
        return nullptr;
    }
    std::string text;
    char buffer[1 << 16];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
        text.append(buffer, static_cast<std::size_t>(in.gcount()));
        if (text.size() > max_input_bytes) {
            diags.error(Kind::Limit, where,
                        "'" + path + "' is larger than " + std::to_string(max_input_bytes >> 20) +
                            " MiB, more than any input yamsc reads");
            return nullptr;
        }
    }
    if (in.bad()) {
        diags.error(Kind::Io, where, "cannot read '" + path + "'");
        return nullptr;
    }
    return std::make_shared<SourceFile>(path, std::move(text));
}

} // namespace yamsc::diag
