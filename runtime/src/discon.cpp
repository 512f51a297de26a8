#include "yamsc/discon.hpp"

#include <dlfcn.h>

#include <stdexcept>
#include <vector>

namespace yamsc::runtime {

namespace {
using Discon = void (*)(float*, int*, const char*, char*, char*);
constexpr int swap_size = 2000; // room for ROSCO's extended records (1001..)
constexpr int message_size = 1024;
} // namespace

struct DisconController::Impl {
    void* handle = nullptr;
    Discon discon = nullptr;
    std::string input_file, output_name;
    std::vector<float> swap = std::vector<float>(swap_size, 0.0f);
    bool started = false;
};

DisconController::DisconController(const std::string& library, std::string input_file,
                                   std::string output_name)
    : impl_(std::make_unique<Impl>()) {
    impl_->input_file = std::move(input_file);
    impl_->output_name = std::move(output_name);
    impl_->handle = dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!impl_->handle)
        throw std::runtime_error("--controller: cannot load '" + library + "': " + dlerror());
    impl_->discon = reinterpret_cast<Discon>(dlsym(impl_->handle, "DISCON"));
    if (!impl_->discon) {
        dlclose(impl_->handle);
        throw std::runtime_error("--controller: '" + library + "' has no DISCON function");
    }
}

DisconController::~DisconController() {
    if (impl_ && impl_->handle) dlclose(impl_->handle);
}

ControllerDemands DisconController::call(const ControllerMeasurements& m, bool last) {
    std::vector<float>& s = impl_->swap;
    auto set = [&](int record, double value) {
        s[static_cast<std::size_t>(record - 1)] = static_cast<float>(value);
    };
    set(1, last ? -1 : (impl_->started ? 1 : 0));
    set(2, m.time);
    set(3, m.step);
    set(4, m.pitch);
    set(33, m.pitch);
    set(34, m.pitch);
    set(10, 0); // pitch position actuator
    set(14, m.mech_power);
    set(15, m.power);
    set(20, m.gen_speed);
    set(21, m.rotor_speed);
    set(23, m.gen_torque);
    set(27, m.wind);
    set(28, 0); // collective pitch
    set(49, message_size);
    set(50, static_cast<double>(impl_->input_file.size() + 1));
    set(51, static_cast<double>(impl_->output_name.size() + 1));
    set(53, m.tower_top_fa_acc);
    set(54, m.tower_top_ss_acc);
    set(60, m.azimuth);
    set(61, 3);
    set(129, swap_size);
    int fail = 0;
    std::vector<char> out(impl_->output_name.begin(), impl_->output_name.end());
    out.push_back('\0');
    std::vector<char> msg(message_size + 1, '\0');
    impl_->discon(s.data(), &fail, impl_->input_file.c_str(), out.data(), msg.data());
    impl_->started = true;
    if (fail < 0)
        throw std::runtime_error("the controller failed at t = " + std::to_string(m.time) +
                                 " s: " + std::string(msg.data()));
    return {s[44], s[46]};
}

} // namespace yamsc::runtime
