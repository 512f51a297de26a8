#include "yamsc/atomic_file.hpp"

#include "yamsc/output_target.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <ostream>
#include <stdexcept>
#include <streambuf>

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

/// An open file descriptor, closed on destruction.
class Descriptor {
public:
    explicit Descriptor(int fd) : fd_(fd) {}
    ~Descriptor() {
        if (fd_ >= 0) ::close(fd_);
    }
    Descriptor(const Descriptor&) = delete;
    Descriptor& operator=(const Descriptor&) = delete;

    int get() const { return fd_; }
    /// Closes now and returns close()'s errno (0 on success): a regular file
    /// can report a lost write only here.
    int close() {
        const int result = ::close(fd_);
        fd_ = -1;
        return result == 0 ? 0 : errno;
    }

private:
    int fd_;
};

/// A stream buffer writing to a file descriptor with plain write() calls: the
/// same code for a temporary file, a device and a FIFO, and no O_TRUNC on
/// either (std::ofstream would truncate).
class DescriptorBuffer : public std::streambuf {
public:
    explicit DescriptorBuffer(int fd) : fd_(fd) { setp(buffer_, buffer_ + sizeof buffer_); }
    int error() const { return error_; }

protected:
    int_type overflow(int_type c) override {
        if (!drain()) return traits_type::eof();
        if (!traits_type::eq_int_type(c, traits_type::eof())) {
            *pptr() = traits_type::to_char_type(c);
            pbump(1);
        }
        return traits_type::not_eof(c);
    }
    int sync() override { return drain() ? 0 : -1; }

private:
    bool drain() {
        const char* p = pbase();
        auto left = static_cast<std::size_t>(pptr() - pbase());
        while (left > 0) {
            const ssize_t n = ::write(fd_, p, left);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) {
                error_ = n < 0 ? errno : EIO;
                return false;
            }
            p += n;
            left -= static_cast<std::size_t>(n);
        }
        setp(buffer_, buffer_ + sizeof buffer_);
        return true;
    }

    int fd_;
    int error_ = 0;
    char buffer_[1 << 16];
};

/// Calls `write` on a stream into `fd`; throws naming `path` on a write error.
void write_to(const std::string& path, int fd, const std::function<void(std::ostream&)>& write) {
    DescriptorBuffer buffer(fd);
    std::ostream out(&buffer);
    write(out);
    out.flush();
    if (!out) fail(path, "write error", buffer.error());
}

/// The temporary file of one regular target: created beside it (O_EXCL, so an
/// existing name is never written through), removed unless renamed.
class TemporaryFile {
public:
    TemporaryFile(const std::string& path, const std::string& target)
        : path_(temporary_path_for(target)), target_(target) {
        // The new file keeps the permission bits of the one it replaces: a
        // private (0600) file must not become readable by everyone.
        struct stat old {};
        const bool replacing = ::stat(target.c_str(), &old) == 0;
        const int fd = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd < 0) fail(path, "cannot create the temporary file '" + path_ + "'", errno);
        created_ = true;
        fd_ = std::make_unique<Descriptor>(fd);
        if (replacing && ::fchmod(fd, old.st_mode & 07777) != 0) {
            const int error = errno;
            ::unlink(path_.c_str()); // the destructor does not run after a throw here
            fail(path, "cannot set the permissions of '" + path_ + "'", error);
        }
    }
    ~TemporaryFile() {
        fd_.reset();
        if (created_ && !committed_) ::unlink(path_.c_str());
    }
    TemporaryFile(const TemporaryFile&) = delete;
    TemporaryFile& operator=(const TemporaryFile&) = delete;

    /// Writes the content and closes the file.
    void write(const std::string& path, const std::function<void(std::ostream&)>& write) {
        write_to(path, fd_->get(), write);
        if (const int error = fd_->close()) fail(path, "write error on close", error);
    }
    /// Renames the temporary file over the target.
    void commit(const std::string& path) {
        if (std::rename(path_.c_str(), target_.c_str()) != 0)
            fail(path, "cannot replace it with the temporary file", errno);
        committed_ = true;
    }

private:
    std::string path_, target_;
    std::unique_ptr<Descriptor> fd_;
    bool created_ = false, committed_ = false;
};

/// Writes into a character device or a FIFO in place. Opening a FIFO waits for
/// its reader, as any writer's would.
void write_stream(const std::string& path, const std::function<void(std::ostream&)>& write) {
    Descriptor fd(::open(path.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC));
    if (fd.get() < 0) fail(path, "cannot open it for writing", errno);
    // It may have been replaced since it was classified: never write into the
    // start of a regular file without truncating it.
    struct stat st {};
    if (::fstat(fd.get(), &st) != 0 || !(S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)))
        fail(path, "it changed from a device or FIFO while being written", 0);
    write_to(path, fd.get(), write);
    if (const int error = fd.close()) fail(path, "write error on close", error);
}

} // namespace

void write_file_atomically(const std::string& path,
                           const std::function<void(std::ostream&)>& write) {
    const OutputTarget target = resolve_output(path);
    if (target.kind == OutputTarget::Kind::stream) return write_stream(path, write);
    TemporaryFile temporary(path, target.path);
    temporary.write(path, write);
    temporary.commit(path);
}

void write_files_atomically(const std::vector<std::pair<std::string, std::string>>& files) {
    std::vector<OutputTarget> targets;
    for (const auto& file : files) targets.push_back(resolve_output(file.first));
    // Every regular file's content is complete before anything is replaced or
    // streamed; then, in order, each is renamed or written.
    std::vector<std::unique_ptr<TemporaryFile>> temporaries(files.size());
    for (std::size_t i = 0; i < files.size(); ++i) {
        if (targets[i].kind != OutputTarget::Kind::file) continue;
        const auto& [path, content] = files[i];
        temporaries[i] = std::make_unique<TemporaryFile>(path, targets[i].path);
        temporaries[i]->write(path, [&](std::ostream& out) { out << content; });
    }
    for (std::size_t i = 0; i < files.size(); ++i) {
        const auto& [path, content] = files[i];
        if (temporaries[i])
            temporaries[i]->commit(path);
        else
            write_stream(path, [&](std::ostream& out) { out << content; });
    }
}

void write_file_atomically(const std::string& path, const std::string& content) {
    write_file_atomically(path, [&](std::ostream& out) { out << content; });
}

} // namespace yamsc::runtime
