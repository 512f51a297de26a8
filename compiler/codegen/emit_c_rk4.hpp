#pragma once
// The C output's fixed-step integrator: `<prefix>_rk4_step`, one classical
// Runge-Kutta step of x' = rhs(t, x, u) in place, with fixed-size local arrays
// (no allocation, no globals), for a controller's loop on a target without the
// runtime. Its arithmetic is that of the runtime's rk4_step (runtime/src/rk4.cpp)
// operation for operation, so both give the same numbers.
#include "codegen/printer.hpp"
#include "codegen/syntax.hpp"

#include <string>

namespace yamsc::codegen {

struct Rk4Names {
    std::string prefix;      // <prefix>_rhs is the right-hand side it calls
    std::string real;        // the API's floating-point type, <prefix>_real
    std::string params_type; // <prefix>_params
};

/// `void <prefix>_rk4_step(<real> t, <real> h, <real>* x, const <real>* u,
/// const <prefix>_params* p)`, without a semicolon.
std::string rk4_signature(const Rk4Names& names);

/// The definition, for a state of nx = 2 nq values (arrays of at least one:
/// C has no empty arrays); literals and locals in the syntax's floating-point type.
std::string rk4_definition(const Rk4Names& names, const Syntax& syntax, int nx);

/// The operations of one step: 4 calls of rhs, whose count is `rhs`, and the
/// stage and update arithmetic of the definition.
OperationCount rk4_count(int nx, const OperationCount& rhs);

} // namespace yamsc::codegen
