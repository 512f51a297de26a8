#pragma once
// The page of `yamsc view`, embedded at build time (viewer/CMakeLists.txt).
#include <string_view>

namespace yamsc::viewer {

/// The page's HTML with the placeholders @TITLE@, @DATA@ and @SCRIPT@.
std::string_view page_template();

/// three.js and the page's code bundled into one script; empty in a build
/// without node and npm.
std::string_view page_script();

} // namespace yamsc::viewer
