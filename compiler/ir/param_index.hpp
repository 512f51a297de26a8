#pragma once
// A parameter of a System by name (--sensitivities names them).
#include "ir/system.hpp"

#include <cstddef>
#include <optional>
#include <string>

namespace yamsc::ir {

/// The index of the parameter `name` in s.params; none when it has none.
inline std::optional<std::size_t> param_index(const System& s, const std::string& name) {
    for (std::size_t i = 0; i < s.params.size(); ++i)
        if (s.params[i].name == name) return i;
    return std::nullopt;
}

} // namespace yamsc::ir
