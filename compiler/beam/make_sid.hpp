#pragma once
// The Standard Input Data of a straight beam (paper Appendix A, B, C, D3): shape
// integrals, unit geometric stiffness matrices in the first-order terms, and one SID
// node per integration station. docs/beam-preprocessing.md gives every formula.
#include "beam/beam.hpp"

#include <optional>
#include <string>

namespace yamsc::beam {

/// The first problem that makes `beam` unusable (a message for the user), or nullopt.
std::optional<std::string> check_beam(const Beam& beam);

/// The SID of `beam`. Precondition: check_beam(beam) is nullopt (else InternalError).
sid::Sid make_sid(const Beam& beam);

} // namespace yamsc::beam
