#include "entry.hpp"

namespace yamsc::fmi {

Instance* instantiate(Interface interface, const char* name, const char* token,
                      std::string resources, Logger logger, bool logging_on) noexcept {
    try {
        const UnitModel& unit = unit_model();
        const std::string instance_name = name ? name : "";
        if (!unit.settings.token.empty() && (!token || unit.settings.token != token)) {
            if (logger)
                logger(Status::error, "logStatusError",
                       "the instantiation token \"" + std::string(token ? token : "") +
                           "\" is not this unit's \"" + unit.settings.token +
                           "\" (a model description of another build?)");
            return nullptr;
        }
        return new Instance(unit, interface, instance_name, std::move(resources), std::move(logger),
                            logging_on);
    } catch (const std::exception& e) {
        try {
            if (logger)
                logger(Status::error, "logStatusError",
                       std::string("instantiation failed: ") + e.what());
        } catch (...) {
        }
    } catch (...) {
    }
    return nullptr;
}

Status unsupported(void* instance, const char* function) noexcept {
    return guarded(instance, function, [&](Instance& in) {
        return in.fail(std::string(function) + " is not provided by this unit (docs/fmi.md)");
    });
}

Status no_variables_of_type(void* instance, const char* function, std::size_t n) noexcept {
    return guarded(instance, function, [&](Instance& in) {
        if (n == 0) return Status::ok;
        return in.fail(std::string(function) + ": the unit has no variable of this type");
    });
}

} // namespace yamsc::fmi
