#pragma once
// A model compiled for the tests of this folder, and its channels by name.
#include "analysis/loaded_model.hpp"

#include <doctest/doctest.h>

#include <sstream>
#include <string>
#include <vector>

namespace aero_test {

/// The model at `path` compiled with every routine of the ABI.
inline yamsc::analysis::Loaded load_model(const std::string& path) {
    std::ostringstream err;
    auto l = yamsc::analysis::load(path, {}, "", false, err, {}, yamsc::codegen::abi_routines());
    REQUIRE_MESSAGE(l, err.str());
    return std::move(*l);
}

/// The index of channel `name` among `names` (a test failure without one).
inline int index_of(const std::vector<std::string>& names, const std::string& name) {
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return static_cast<int>(i);
    FAIL("no channel " << name);
    return -1;
}

} // namespace aero_test
