#include "fmi_host.hpp"

#include <cstdarg>
#include <cstdio>

namespace fmi_test {

const Library& unit() {
    static const Library library(YAMSC_FMI_TEST_UNIT);
    return library;
}

const Library& four_bar_unit() {
    static const Library library(YAMSC_FMI_TEST_FOUR_BAR_UNIT);
    return library;
}

void fmi3_log(fmi3InstanceEnvironment env, fmi3Status status, fmi3String, fmi3String message) {
    static_cast<Log*>(env)->messages.emplace_back(static_cast<int>(status), message);
}

void fmi2_log(fmi2ComponentEnvironment env, fmi2String, fmi2Status status, fmi2String,
              fmi2String message, ...) {
    char text[1024];
    va_list args;
    va_start(args, message);
    std::vsnprintf(text, sizeof text, message, args);
    va_end(args);
    static_cast<Log*>(env)->messages.emplace_back(static_cast<int>(status), text);
}

} // namespace fmi_test
