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

/// The inertia shape integrals (mass, md, J, Ct, Cr, Me, Gr, Ge, Oe and the
/// geometric stiffness terms) of the part of `beam` beyond its SID node `node`
/// (0-based, root to tip), with zero Ke, De and no nodes: what the reaction of a
/// section (docs/language.md) needs. On an element centre of ElastoDyn's
/// discretization, half the element counts beyond the cut, as ElastoDyn's gauges.
/// Precondition: check_beam(beam) is nullopt and the node exists (else InternalError).
sid::Sid make_section_sid(const Beam& beam, int node);

} // namespace yamsc::beam
