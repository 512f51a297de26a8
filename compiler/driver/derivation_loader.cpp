#include "driver/derivation_loader.hpp"

#include "diag/errors.hpp"

#include <cstdlib>
#include <dlfcn.h>
#include <mutex>
#include <stdexcept>
#include <unistd.h>
#include <vector>

namespace yamsc::driver {

std::string own_folder() {
    Dl_info info{};
    if (::dladdr(reinterpret_cast<void*>(&derivation_module_path), &info) == 0 ||
        info.dli_fname == nullptr)
        return "";
    std::string path = info.dli_fname;
    if (path.find('/') == std::string::npos) {
        char self[4096];
        const ssize_t n = ::readlink("/proc/self/exe", self, sizeof self - 1);
        if (n <= 0) return "";
        path.assign(self, static_cast<std::size_t>(n));
    }
    const auto slash = path.find_last_of('/');
    return slash == std::string::npos ? std::string(".") : path.substr(0, slash);
}

namespace {

std::vector<std::string> candidates() {
    if (const char* chosen = std::getenv("YAMSC_DERIVATION_MODULE"); chosen && *chosen)
        return {chosen};
    const std::string name = derivation::module_file_name;
    const std::string here = own_folder();
    std::vector<std::string> out;
    if (!here.empty()) {
        out.push_back(here + "/" + name);
        out.push_back(here + "/" + YAMSC_DERIVATION_FROM_BINDIR + "/" + name);
    }
    // A program or Python module still in the build tree takes the module built
    // beside it; an installed one the installed module.
    const std::string build_tree = YAMSC_BUILD_TREE;
    const bool in_build_tree = here.compare(0, build_tree.size() + 1, build_tree + "/") == 0;
    out.push_back(in_build_tree ? YAMSC_DERIVATION_BUILT : YAMSC_DERIVATION_INSTALLED);
    out.push_back(in_build_tree ? YAMSC_DERIVATION_INSTALLED : YAMSC_DERIVATION_BUILT);
    return out;
}

struct Module {
    derivation::DeriveFunction derive = nullptr;
    std::string error; // why there is none
};

Module load() {
    std::string tried;
    for (const std::string& path : candidates()) {
        if (::access(path.c_str(), R_OK) != 0) {
            tried += "\n  " + path + ": not found";
            continue;
        }
        void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            tried += "\n  " + path + ": " + ::dlerror();
            continue;
        }
        auto identity = reinterpret_cast<derivation::IdentityFunction>(
            ::dlsym(handle, derivation::identity_symbol));
        auto derive = reinterpret_cast<derivation::DeriveFunction>(
            ::dlsym(handle, derivation::derive_symbol));
        if (!identity || !derive) {
            tried += "\n  " + path + ": not a yamsc derivation module";
            ::dlclose(handle);
            continue;
        }
        if (derivation::derivation_identity() != identity()) {
            tried += "\n  " + path + ": built by another yamsc (" + identity() + ")";
            ::dlclose(handle);
            continue;
        }
        return {derive, ""}; // kept loaded for the life of the process
    }
    return {nullptr, "cannot find the derivation module (" +
                         std::string(derivation::module_file_name) + ") of this yamsc:" + tried};
}

const Module& module() {
    static std::once_flag once;
    static Module m;
    std::call_once(once, [] { m = load(); });
    return m;
}

} // namespace

std::string derivation_module_path() {
    for (const std::string& path : candidates())
        if (::access(path.c_str(), R_OK) == 0) return path;
    return "";
}

void derive_through_module(const derivation::DerivationRequest& request, diag::Diagnostics& diags,
                           derivation::DerivationResult& result) {
    const Module& m = module();
    if (!m.derive) throw diag::InternalError(m.error);
    m.derive(request, diags, result);
    using Failure = derivation::DerivationResult::Failure;
    if (result.failure == Failure::internal) throw diag::InternalError(result.message);
    if (result.failure == Failure::other) throw std::runtime_error(result.message);
}

} // namespace yamsc::driver
