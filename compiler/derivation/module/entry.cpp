// The derivation module's two exported functions (derivation.hpp). Everything
// else in the module is hidden: it keeps its own copies of the stages it links.
#include "derivation/derivation.hpp"
#include "diag/errors.hpp"
#include "lower/lower.hpp"
#include "symbolic/derive.hpp"
#include "symbolic/linearize.hpp"

#include <chrono>
#include <exception>

namespace yamsc::derivation {
namespace {

void derive_system(const DerivationRequest& request, diag::Diagnostics& diags,
                   DerivationResult& result) {
    using clock = std::chrono::steady_clock;
    auto seconds_since = [](clock::time_point t) {
        return std::chrono::duration<double>(clock::now() - t).count();
    };
    const model::Model& m = *request.model;
    const auto start = clock::now();
    symbolic::DeriveOptions options;
    options.mass_matrix = request.mass_matrix;
    options.cost = lower::operation_count;
    std::optional<symbolic::Equations> eq = symbolic::derive(m, diags, options);
    result.derive_seconds = seconds_since(start);
    if (!eq || diags.has_errors()) return;
    eq->source_path = request.source_path;
    eq->source_digest = request.source_digest;
    const auto lowered = clock::now();
    result.system = lower::lower(*eq, symbolic::operating_point(m, *eq));
    result.lower_seconds = seconds_since(lowered);
}

} // namespace
} // namespace yamsc::derivation

extern "C" {

__attribute__((visibility("default"))) void
yamsc_derive_system(const yamsc::derivation::DerivationRequest& request,
                    yamsc::diag::Diagnostics& diags, yamsc::derivation::DerivationResult& result) {
    using Failure = yamsc::derivation::DerivationResult::Failure;
    try {
        yamsc::derivation::derive_system(request, diags, result);
    } catch (const yamsc::diag::InternalError& e) {
        result.failure = Failure::internal;
        result.message = e.what();
    } catch (const std::exception& e) {
        result.failure = Failure::other;
        result.message = e.what();
    } catch (...) {
        result.failure = Failure::internal;
        result.message = "the derivation failed with an unknown exception";
    }
}

__attribute__((visibility("default"))) const char* yamsc_derivation_identity() {
    static const std::string identity = yamsc::derivation::derivation_identity();
    return identity.c_str();
}

} // extern "C"
