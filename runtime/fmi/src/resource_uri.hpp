#pragma once
// FMI 2.0 gives the resources folder as a URI (fmuResourceLocation); the
// load blocks read a native path.
#include <optional>
#include <string>

namespace yamsc::fmi {

/// The native folder of a file URI ("file:///a/b%20c", "file:/a/b", "file://localhost/a/b"),
/// ending with '/'; nullopt for another scheme, a remote host or a bad escape.
std::optional<std::string> folder_of_file_uri(const std::string& uri);

} // namespace yamsc::fmi
