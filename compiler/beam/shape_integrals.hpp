#pragma once
// The inertia shape integrals of a beam (paper Appendix A, eq. A2-A14, expanded to
// first order in q as in Appendix D3), without geometric stiffness.
#include "beam/sampled_beam.hpp"
#include "sid/sid.hpp"

namespace yamsc::beam {

/// Fills mass, md_cm, J, Ct (m0), Cr, Me, Gr, Ge and Oe of `sid` (sid.nq set).
void add_inertia_integrals(const SampledBeam& b, sid::Sid& sid);

/// O_e,j as the 6-vector of eq. A14: [O11, O22, O33, O12+O21, O23+O32, O13+O31].
std::array<double, 6> oe_layout(const Mat3& o);

} // namespace yamsc::beam
