#pragma once
// External functions in generated C++ (docs/generated-api.md): the user's C
// functions are called by wrappers around the module's routines. Each public
// routine that reads u (forcing, jacobians, outputs_from_qdd, outputs, rhs,
// rhs_jacobian and the linear model's) becomes the internal `inner_<name>`,
// which reads the declared inputs followed by the externals' results w (and
// calls inner routines: inner_outputs calls inner_rhs); its wrapper evaluates the
// arguments a, calls the functions for w (checking that every result is
// finite), calls the inner routine and adds the chain rule
// dF/dw * dw/da * da/d[x, u] to the derivatives. dw/da is the user's
// `<name>_jacobian` when it is linked (a weak symbol), else central differences.
#include "codegen/module.hpp"

#include <string>

namespace yamsc::codegen {

/// Whether the routine is wrapped when the module has externals.
bool wrapped_routine(const Routine& routine);

/// The module with every wrapped routine renamed `inner_<name>` and internal.
Module with_inner_routines(const Module& module);

/// The externals' C prototypes (valid C and C++), as the generated header and
/// the user's source (`--external file.c`) see them.
std::string external_prototypes(const Module& module);

/// The header comment's lines about the externals ("" without any).
std::string external_comment(const Module& module);

/// The weak declarations of the optional derivatives and the helper functions
/// the wrappers call; C++ for the anonymous namespace, after the internal routines.
std::string external_weak_declarations(const Module& module);
std::string external_support(const Module& module);

/// The body (statements, braces excluded) of the public routine `id`'s wrapper.
std::string external_wrapper_body(const Module& module, RoutineId id);

} // namespace yamsc::codegen
