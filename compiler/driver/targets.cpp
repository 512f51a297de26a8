#include "driver/targets.hpp"

#include "diag/errors.hpp"

namespace yamsc::driver {

const std::vector<const Target*>& targets() {
    static const std::vector<const Target*> all{&cpp_target, &c_target, &latex_target};
    return all;
}

const Target& target(Language language) {
    for (const Target* t : targets())
        if (t->language == language) return *t;
    throw diag::InternalError("no export target for that language");
}

const Target* target_for_extension(std::string_view extension) {
    for (const Target* t : targets())
        for (const std::string& e : t->extensions)
            if (e == extension) return t;
    return nullptr;
}

const Target* target_named(std::string_view name) {
    for (const Target* t : targets())
        if (name == t->name) return t;
    return nullptr;
}

std::string target_names(const char* separator) {
    std::string out;
    for (const Target* t : targets()) out += (out.empty() ? "" : separator) + std::string(t->name);
    return out;
}

} // namespace yamsc::driver
