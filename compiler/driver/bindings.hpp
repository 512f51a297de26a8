#pragma once
// Numeric values for a model's named quantities from command-line assignments:
// parameters (defaults overridden by --set), DOFs and their rates (--q/--qd lists
// or --ic/--at assignments), inputs (--u).
#include "driver/values.hpp"

#include <optional>
#include <stdexcept>

namespace yamsc::driver {

using diag::UserError; // diag/errors.hpp

/// Values for `names` starting from `defaults` (nullopt: no default), overridden by
/// `assignments` (no primes allowed). Throws UserError for an unknown name or a
/// value still missing, naming it.
std::vector<double> bind_named(const std::vector<std::string>& names,
                               const std::vector<std::optional<double>>& defaults,
                               const std::vector<Assignment>& assignments, const std::string& what);

/// q and q' from assignments such as `q=1, psi'=0.5` (missing: 0).
void bind_state(const std::vector<std::string>& dofs, const std::vector<Assignment>& assignments,
                std::vector<double>& q, std::vector<double>& qd, const std::string& option);

/// A list given positionally must have exactly n values.
std::vector<double> sized(const std::vector<double>& v, std::size_t n, const std::string& option);

} // namespace yamsc::driver
