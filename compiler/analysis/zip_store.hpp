#pragma once
// A ZIP archive (PKWARE APPNOTE 6.3) whose entries are stored, not
// compressed: what an FMU is (the FMI standard requires a ZIP file and allows
// the "stored" method). Our own few lines rather than a library: an FMU's bulk
// is one shared library that deflate shrinks by about half, no FMU needs
// ZIP64, and the entries are written with a fixed date and in the given order,
// so the same unit gives the same bytes (reproducible builds, caches).
#include <cstdint>
#include <string>
#include <vector>

namespace yamsc::analysis {

struct ZipEntry {
    std::string name; // '/'-separated, relative; a folder ends with '/' and has no data
    std::string data; // the file's bytes
    bool executable = false;
};

/// CRC-32 (ISO 3309, the polynomial ZIP uses) of `data`.
std::uint32_t crc32(const std::string& data);

/// The archive's bytes. Throws std::invalid_argument for a name that is empty,
/// absolute, has "..", a backslash or is longer than 65535 bytes, a duplicate
/// name, and for an archive that would need ZIP64 (4 GiB, 65535 entries).
std::string zip_stored(const std::vector<ZipEntry>& entries);

} // namespace yamsc::analysis
