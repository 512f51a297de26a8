#pragma once
// A minimal FMI host for the tests: the test unit opened with dlopen, its
// functions found by their standard names, the messages it logs collected.
#include "yamsc/fmi/fmi2_api.h"
#include "yamsc/fmi/fmi3_api.h"

#include <dlfcn.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace fmi_test {

class Library {
public:
    explicit Library(const char* path) : handle_(dlopen(path, RTLD_NOW | RTLD_LOCAL)) {
        if (!handle_) throw std::runtime_error(dlerror());
    }
    ~Library() { dlclose(handle_); }
    Library(const Library&) = delete;
    Library& operator=(const Library&) = delete;

    void* symbol(const char* name) const { return dlsym(handle_, name); }
    template <class F> F* get(const char* name) const {
        void* s = symbol(name);
        if (!s) throw std::runtime_error(std::string("the unit does not export ") + name);
        return reinterpret_cast<F*>(s);
    }

private:
    void* handle_;
};

/// The double pendulum's unit, opened once for all tests.
const Library& unit();
/// The four-bar linkage's unit (a model with constraint rows).
const Library& four_bar_unit();

/// The messages an instance logged (status, message).
struct Log {
    std::vector<std::pair<int, std::string>> messages;
    bool has_error() const {
        for (const auto& m : messages)
            if (m.first >= 3) return true;
        return false;
    }
};

void fmi3_log(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category,
              fmi3String message);
void fmi2_log(fmi2ComponentEnvironment env, fmi2String instance, fmi2Status status,
              fmi2String category, fmi2String message, ...);

#define FMI3(name) fmi_test::unit().get<decltype(name)>(#name)
#define FMI2(name) fmi_test::unit().get<decltype(name)>(#name)

inline constexpr const char* token = "{yamsc-test-double-pendulum}";

/// Value references of the double pendulum's unit (docs/fmi.md, Variables).
namespace vr {
inline constexpr unsigned time = 0, th1 = 1, th2 = 2, th1d = 3, th2d = 4, th1dd = 5, th2dd = 6,
                          tau = 7, f = 8, m1 = 9, k = 14, c = 15, x_tip = 16, z_tip = 17,
                          v_tip = 18, method = 19, step = 20;
}

} // namespace fmi_test
