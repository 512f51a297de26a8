#pragma once
// Values given on the command line: `name=v,name=v` assignments (with `deg`) and
// `v,v,v` lists. Errors are usage errors (exit 2) with a message.
#include "diag/errors.hpp"

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace yamsc::driver {

using diag::UsageError; // diag/errors.hpp

/// "1.5", "-2e3", "5deg", "5 deg" -> value in SI (deg converted to rad).
double parse_value(const std::string& text, const std::string& option);

/// "v,v,v" -> values.
std::vector<double> parse_list(const std::string& text, const std::string& option);

/// One `name=value` (name may end in primes: psi'=0.5).
struct Assignment {
    std::string name;
    int primes = 0;
    double value = 0;
};
std::vector<Assignment> parse_assignments(const std::string& text, const std::string& option);

/// `--sweep NAME=FROM:STEP:TO` (values accept `deg`). Throws UsageError when malformed.
struct Sweep {
    std::string name;
    std::vector<double> values; // FROM, FROM + STEP, ..., up to TO (included within rounding)
};
Sweep parse_sweep(const std::string& text);

} // namespace yamsc::driver
