#include "yamsc/output_target.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace yamsc::runtime {

namespace {

[[noreturn]] void refuse(const std::string& path, const std::string& why) {
    throw std::runtime_error("cannot write '" + path + "': " + why);
}

/// The text of the symbolic link `link`.
std::string read_link(const std::string& link) {
    std::vector<char> buffer(256);
    while (true) {
        const ssize_t n = ::readlink(link.c_str(), buffer.data(), buffer.size());
        if (n < 0)
            refuse(link, std::string("cannot read the symbolic link: ") + std::strerror(errno));
        if (static_cast<std::size_t>(n) < buffer.size())
            return std::string(buffer.data(), static_cast<std::size_t>(n));
        buffer.resize(buffer.size() * 2);
    }
}

/// `path` with every symbolic link followed, the last one possibly dangling
/// (a link to a file not written yet). Followed by hand rather than with
/// realpath() because the final target need not exist.
std::string final_target(const std::string& path) {
    constexpr int max_links = 40; // as the kernel's ELOOP limit
    std::string p = path;
    for (int links = 0; links < max_links; ++links) {
        struct stat st {};
        if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p;
        const std::string target = read_link(p);
        if (target.empty() || target[0] == '/') {
            p = target;
        } else {
            const auto slash = p.find_last_of('/');
            p = (slash == std::string::npos ? "" : p.substr(0, slash + 1)) + target;
        }
    }
    refuse(path, "too many levels of symbolic links");
}

} // namespace

OutputTarget resolve_output(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0) {
        if (S_ISREG(st.st_mode)) return {OutputTarget::Kind::file, final_target(path)};
        // The path itself, not its target: /dev/stdout is a link whose text
        // (`pipe:[...]`) is no path, but opening it works.
        if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)) return {OutputTarget::Kind::stream, path};
        if (S_ISDIR(st.st_mode)) refuse(path, "it is a folder");
        if (S_ISSOCK(st.st_mode)) refuse(path, "it is a socket, not a file");
        if (S_ISBLK(st.st_mode))
            refuse(path, "it is a block device (a disk); yamsc does not write to disks");
        refuse(path, "it is not a regular file");
    }
    if (errno == ELOOP) refuse(path, "too many levels of symbolic links");
    return {OutputTarget::Kind::file, final_target(path)};
}

} // namespace yamsc::runtime
