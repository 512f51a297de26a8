#include "analysis/zip_store.hpp"

#include <array>
#include <limits>
#include <set>
#include <stdexcept>

namespace yamsc::analysis {

namespace {

const std::array<std::uint32_t, 256>& crc_table() {
    static const std::array<std::uint32_t, 256> table = [] {
        std::array<std::uint32_t, 256> t{};
        for (std::uint32_t n = 0; n < 256; ++n) {
            std::uint32_t c = n;
            for (int k = 0; k < 8; ++k) c = (c & 1U) ? 0xEDB88320U ^ (c >> 1) : c >> 1;
            t[n] = c;
        }
        return t;
    }();
    return table;
}

void put16(std::string& out, std::uint32_t v) {
    out += static_cast<char>(v & 0xFFU);
    out += static_cast<char>((v >> 8) & 0xFFU);
}

void put32(std::string& out, std::uint32_t v) {
    put16(out, v & 0xFFFFU);
    put16(out, v >> 16);
}

void check_name(const std::string& name, std::set<std::string>& seen) {
    const bool bad = name.empty() || name.size() > 0xFFFF || name[0] == '/' ||
                     name.find('\\') != std::string::npos ||
                     ("/" + name + "/").find("/../") != std::string::npos;
    if (bad) throw std::invalid_argument("zip: the entry name '" + name + "' is not allowed");
    if (!seen.insert(name).second)
        throw std::invalid_argument("zip: the entry '" + name + "' is given twice");
}

// 1980-01-01 00:00, the first date ZIP can express: the same input gives the same bytes.
constexpr std::uint32_t dos_time = 0, dos_date = (0U << 9) | (1U << 5) | 1U;
// Made by: UNIX (3), APPNOTE 2.0; the external attributes then carry the mode bits.
constexpr std::uint32_t made_by = (3U << 8) | 20U, needed = 20U;
constexpr std::uint32_t utf8_names = 1U << 11;

} // namespace

std::uint32_t crc32(const std::string& data) {
    std::uint32_t c = 0xFFFFFFFFU;
    for (unsigned char byte : data) c = crc_table()[(c ^ byte) & 0xFFU] ^ (c >> 8);
    return c ^ 0xFFFFFFFFU;
}

std::string zip_stored(const std::vector<ZipEntry>& entries) {
    constexpr std::uint64_t limit = std::numeric_limits<std::uint32_t>::max();
    if (entries.size() >= 0xFFFF) throw std::invalid_argument("zip: too many entries (ZIP64)");
    std::set<std::string> seen;
    std::string archive, directory;
    for (const ZipEntry& e : entries) {
        check_name(e.name, seen);
        const bool folder = e.name.back() == '/';
        if (folder && !e.data.empty())
            throw std::invalid_argument("zip: the folder entry '" + e.name + "' has data");
        if (e.data.size() >= limit || archive.size() + e.data.size() + 30 + e.name.size() >= limit)
            throw std::invalid_argument("zip: the archive would exceed 4 GiB (ZIP64)");
        const auto offset = static_cast<std::uint32_t>(archive.size());
        const std::uint32_t crc = crc32(e.data);
        const auto size = static_cast<std::uint32_t>(e.data.size());
        const auto name_length = static_cast<std::uint32_t>(e.name.size());
        auto common = [&](std::string& out) {
            put16(out, needed);
            put16(out, utf8_names);
            put16(out, 0); // stored
            put16(out, dos_time);
            put16(out, dos_date);
            put32(out, crc);
            put32(out, size); // compressed
            put32(out, size); // uncompressed
            put16(out, name_length);
            put16(out, 0); // extra field
        };
        put32(archive, 0x04034B50U);
        common(archive);
        archive += e.name;
        archive += e.data;

        const std::uint32_t mode = folder ? 040755U : e.executable ? 0100755U : 0100644U;
        put32(directory, 0x02014B50U);
        put16(directory, made_by);
        common(directory);
        put16(directory, 0); // comment
        put16(directory, 0); // disk
        put16(directory, 0); // internal attributes
        put32(directory, (mode << 16) | (folder ? 0x10U : 0U));
        put32(directory, offset);
        directory += e.name;
    }
    if (archive.size() + directory.size() >= limit)
        throw std::invalid_argument("zip: the archive would exceed 4 GiB (ZIP64)");
    const auto directory_offset = static_cast<std::uint32_t>(archive.size());
    archive += directory;
    put32(archive, 0x06054B50U);
    put16(archive, 0);
    put16(archive, 0);
    put16(archive, static_cast<std::uint32_t>(entries.size()));
    put16(archive, static_cast<std::uint32_t>(entries.size()));
    put32(archive, static_cast<std::uint32_t>(directory.size()));
    put32(archive, directory_offset);
    put16(archive, 0); // comment
    return archive;
}

} // namespace yamsc::analysis
