#pragma once
// The one change of representation of a model's equations: the GiNaC
// expressions of Kane's method (symbolic::Equations) become an ir::System.
// GiNaC stays the tool of the derivation; everything after it (derivatives,
// linearization, code) works on the IR.
#include "ir/system.hpp"
#include "symbolic/equations.hpp"
#include "symbolic/linearize.hpp"

namespace yamsc::lower {

/// The System of `eq`: its names and documentation, M (when derived), F, M a
/// (when assembled) and the outputs, in one graph whose variables are q, q',
/// u and p. Throws diag::InternalError on what the IR cannot hold (unknown
/// symbols, complex numbers, unsupported functions).
ir::System lower(const symbolic::Equations& eq);

/// As above, with the model's operating point (parameters only) as well.
ir::System lower(const symbolic::Equations& eq, const symbolic::OperatingPoint& point);

/// The arithmetic compiled code spends on `roots` (expressions of `eq`'s
/// symbols), every distinct IR node once: an operation per operand of a sum or
/// product beyond the first, per coefficient other than ±1 and per factor of an
/// integer power; 10 per function call (what libm costs). The IR is canonical,
/// so the count is the same in every process (symbolic::DeriveOptions::cost).
double operation_count(const symbolic::Equations& eq, const std::vector<GiNaC::ex>& roots);

} // namespace yamsc::lower
