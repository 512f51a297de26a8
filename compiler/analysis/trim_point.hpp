#pragma once
// Trim as `yamsc trim` and `yamsc lin --trim` use it: which DOFs are held, the
// Newton solve (yamsc/trim.hpp), and the error that names the DOFs left out
// of balance.
#include <yamsc/trim.hpp>

#include <string>
#include <vector>

namespace yamsc::analysis {

/// Trims from (q, q') at inputs u. Held: the DOFs named in `hold` and every
/// DOF with a nonzero rate at the start (a spinning rotor keeps its speed).
/// `adjust` names inputs trimmed with the DOFs (--adjust: the pitch or the
/// generator torque of steady operation); they balance the DOFs held for their
/// rate, one input per such DOF, so that nothing is left to hold the rotor.
/// Throws UserError for an unknown name in `hold` or `adjust`, a count of
/// adjusted inputs that does not match, and when Newton's method does not
/// converge (with the residual of each free DOF).
runtime::TrimResult trim_point(const runtime::ModelView& view, const std::vector<double>& q,
                               const std::vector<double>& qd, const std::vector<double>& u,
                               const std::vector<std::string>& hold,
                               const std::vector<std::string>& adjust = {},
                               const runtime::TrimSettings& settings = {});

} // namespace yamsc::analysis
