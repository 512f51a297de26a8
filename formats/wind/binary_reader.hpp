#pragma once
// A binary file read in order, little-endian, with the byte offset of what comes
// next, so that every error names where the file went wrong; a seekable stream
// tells its size first, so that a file declaring more data than it holds is
// rejected before anything is allocated.
#include <cstdint>
#include <cstring>
#include <istream>
#include <limits>
#include <stdexcept>
#include <string>

namespace yamsc::wind {

/// The stream read in order, with the byte offset of what comes next (errors).
class BinaryReader {
public:
    BinaryReader(std::istream& in, const std::string& source) : in_(in), source_(source) {
        // A seekable stream tells its size, so that a file declaring more data
        // than it holds is rejected before anything is allocated.
        const std::streampos here = in.tellg();
        if (here != std::streampos(-1) && in.seekg(0, std::ios::end)) {
            const std::streampos end = in.tellg();
            in.seekg(here);
            if (end != std::streampos(-1) && end >= here)
                size_ = static_cast<std::uint64_t>(end - here);
        }
        in.clear();
    }

    [[noreturn]] void fail(std::uint64_t at, const std::string& what) const {
        throw std::runtime_error(source_ + ": byte " + std::to_string(at) + ": " + what);
    }

    void read(void* to, std::size_t n, const char* what) {
        if (n == 0) return;
        if (!in_.read(static_cast<char*>(to), static_cast<std::streamsize>(n)))
            fail(offset_ + static_cast<std::uint64_t>(in_.gcount()),
                 std::string("the file ends in ") + what);
        offset_ += n;
    }

    template <class T> T get(const char* what) {
        unsigned char b[sizeof(T)];
        read(b, sizeof(T), what);
        // Little-endian whatever the host's order.
        std::uint64_t u = 0;
        for (std::size_t i = 0; i < sizeof(T); ++i) u |= std::uint64_t(b[i]) << (8 * i);
        if constexpr (sizeof(T) == 2) {
            const auto v = static_cast<std::uint16_t>(u);
            T t;
            std::memcpy(&t, &v, 2);
            return t;
        } else {
            const auto v = static_cast<std::uint32_t>(u);
            T t;
            std::memcpy(&t, &v, 4);
            return t;
        }
    }

    /// Fails unless `n` more bytes can be there (a seekable stream: they are).
    void require(std::uint64_t n, const char* what) const {
        if (size_ != unknown && n > size_ - offset_)
            fail(size_, std::string("the file ends in ") + what + " (" + std::to_string(n) +
                            " bytes declared from byte " + std::to_string(offset_) + ", " +
                            std::to_string(size_ - offset_) + " there)");
    }

    std::uint64_t offset() const { return offset_; }
    /// Whether the stream told its size (require() then checks).
    bool sized() const { return size_ != unknown; }

private:
    static constexpr std::uint64_t unknown = std::numeric_limits<std::uint64_t>::max();
    std::istream& in_;
    const std::string& source_;
    std::uint64_t offset_ = 0;
    std::uint64_t size_ = unknown;
};

} // namespace yamsc::wind
