#include "seastate/seastate_input.hpp"

#include "elastodyn/file.hpp"

namespace yamsc::seastate {

diag::Location Input::location(const std::string& key) const {
    for (const auto& [name, at] : entries)
        if (elastodyn::same_key(name, key)) return at;
    return diag::Location{file, 0, 0};
}

} // namespace yamsc::seastate
