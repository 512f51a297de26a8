#include "yamsc/atomic_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <stdexcept>

namespace yamsc::runtime {

std::string temporary_path_for(const std::string& path) {
    return path + ".tmp." + std::to_string(static_cast<long>(::getpid()));
}

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what, int error) {
    std::string message = "cannot write '" + path + "': " + what;
    if (error != 0) message += ": " + std::string(std::strerror(error));
    throw std::runtime_error(message);
}

// Removes the temporary file unless the rename succeeded.
class TemporaryFile {
public:
    explicit TemporaryFile(std::string path) : path_(std::move(path)) {}
    ~TemporaryFile() {
        if (!committed_) std::remove(path_.c_str());
    }
    TemporaryFile(const TemporaryFile&) = delete;
    TemporaryFile& operator=(const TemporaryFile&) = delete;

    const std::string& path() const { return path_; }
    void commit() { committed_ = true; }

private:
    std::string path_;
    bool committed_ = false;
};

// Writes the temporary file of `path`; `temporary` removes it unless committed.
void write_temporary(const std::string& path, const TemporaryFile& temporary,
                     const std::function<void(std::ostream&)>& write) {
    errno = 0;
    std::ofstream out(temporary.path(), std::ios::binary | std::ios::trunc);
    if (!out) fail(path, "cannot create the temporary file '" + temporary.path() + "'", errno);
    write(out);
    out.flush();
    if (!out) fail(path, "write error", errno);
    out.close();
    if (!out) fail(path, "write error on close", errno);
}

void replace(const std::string& path, TemporaryFile& temporary) {
    if (std::rename(temporary.path().c_str(), path.c_str()) != 0)
        fail(path, "cannot replace it with the temporary file", errno);
    temporary.commit();
}

} // namespace

void write_file_atomically(const std::string& path,
                           const std::function<void(std::ostream&)>& write) {
    TemporaryFile temporary(temporary_path_for(path));
    write_temporary(path, temporary, write);
    replace(path, temporary);
}

void write_files_atomically(const std::vector<std::pair<std::string, std::string>>& files) {
    std::vector<std::unique_ptr<TemporaryFile>> temporaries;
    for (const auto& [path, content] : files) {
        temporaries.push_back(std::make_unique<TemporaryFile>(temporary_path_for(path)));
        write_temporary(path, *temporaries.back(), [&](std::ostream& out) { out << content; });
    }
    for (std::size_t i = 0; i < files.size(); ++i) replace(files[i].first, *temporaries[i]);
}

void write_file_atomically(const std::string& path, const std::string& content) {
    write_file_atomically(path, [&](std::ostream& out) { out << content; });
}

} // namespace yamsc::runtime
