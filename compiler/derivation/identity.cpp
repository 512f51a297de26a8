#include "derivation/derivation.hpp"

namespace yamsc::derivation {

std::string derivation_identity() {
    // A module of another build: another version, or types of another layout.
    return std::string("yamsc ") + YAMSC_VERSION + " system " + std::to_string(sizeof(ir::System)) +
           " model " + std::to_string(sizeof(model::Model)) + " diagnostics " +
           std::to_string(sizeof(diag::Diagnostics)) + " request " +
           std::to_string(sizeof(DerivationRequest)) + " result " +
           std::to_string(sizeof(DerivationResult));
}

} // namespace yamsc::derivation
