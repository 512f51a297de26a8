#pragma once
// What both C layers share: instances made and every call guarded, so no
// exception crosses the C boundary (each becomes a logged error status).
#include "instance.hpp"

#include <exception>
#include <memory>
#include <new>
#include <string>

namespace yamsc::fmi {

/// Runs f(instance), the standard's call `function`; an exception is logged
/// as an error of that call. A null instance is an error (nothing to log to).
template <class F> Status guarded(void* instance, const char* function, F&& f) noexcept {
    if (!instance) return Status::error;
    auto& in = *static_cast<Instance*>(instance);
    try {
        return f(in);
    } catch (const std::exception& e) {
        try {
            return in.fail(std::string(function) + ": " + e.what());
        } catch (...) {
            return Status::error;
        }
    } catch (...) {
        return Status::error;
    }
}

/// A new instance, or null after logging why through `logger`; `token` is
/// checked against the unit's (UnitSettings::token).
Instance* instantiate(Interface interface, const char* name, const char* token,
                      std::string resources, Logger logger, bool logging_on) noexcept;

/// An error status logged for an optional function the unit does not provide.
Status unsupported(void* instance, const char* function) noexcept;

/// An error unless n is 0: the unit has no variable of this type.
Status no_variables_of_type(void* instance, const char* function, std::size_t n) noexcept;

} // namespace yamsc::fmi
