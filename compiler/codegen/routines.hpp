#pragma once
// The routines of the generated API as values, one row each: the name the
// generated code gives it, its summary and arguments, whether the C ABI of
// compiled models (runtime/include/yamsc/abi_export.hpp) exports it, and the
// passes its rows come from. Code generation, the JIT's list of what a command
// compiles (analysis/jit.hpp) and the ABI shim all read this one table.
#include "ir/enum_set.hpp"
#include "ir/system.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace yamsc::codegen {

/// In this order the JIT exports them: the ABI routines first, rhs leading.
enum class RoutineId : std::uint8_t {
    rhs,
    rhs_jacobian,
    mass_matrix,
    forcing,
    jacobians,
    outputs,
    outputs_from_qdd,
    linear,
    state_space,
    output_matrices,
    linear_sensitivities,
    operating_point,
    // Only in models with constraints (constraint_routines()).
    constraints,
    constraint_matrix,
    constraint_bias,
    constraint_jacobians,
};
inline constexpr std::size_t routine_count = 16;
using RoutineSet = ir::EnumSet<RoutineId, routine_count>;

/// The arguments before a routine's outputs.
enum class ArgumentForm {
    t_q_u_p,             // (t, q, u, p): M reads no rates
    t_q_qd_u_p,          // (t, q, qd, u, p)
    t_q_qd_qdd_u_p,      // (t, q, qd, qdd, u, p)
    t_x_u_p,             // (t, x, u, p), x = [q, q']
    point,               // (q0, qd0, u0, p): the linear model, at t = 0
    p,                   // (p)
    t_q_qd_u_lambda_a_p, // (t, q, qd, u, lambda, a, p): the constraint Jacobians
};

struct RoutineRow {
    RoutineId id;
    const char* name;    // in the generated API
    const char* summary; // its comment (linear_sensitivities adds the parameters' names)
    ArgumentForm form;
    std::array<const char*, 5> outputs; // the output arrays, unused ones null
    const char* abi_symbol;             // the C ABI's symbol; null: not exported
    const char* abi_macro;              // abi_export.hpp's YAMSC_EXPORT_<ROUTINE>
    /// Computes derivatives: with externals it needs their arguments' Jacobian.
    bool derivative;
    /// With externals, the public function wraps inner_<name>, which reads u
    /// followed by the externals' results (external_wrappers.hpp).
    bool wraps_externals;
    /// The passes its rows come from (the unrolled form; the tangent form needs
    /// derive_tangent for every routine).
    ir::PassSet needs;
};

/// Every row, in the order of RoutineId.
const std::array<RoutineRow, routine_count>& routine_table();
const RoutineRow& routine_row(RoutineId id);
inline const char* routine_name(RoutineId id) {
    return routine_row(id).name;
}
/// The routine of that API name (user input: the Python module's `routines=`).
std::optional<RoutineId> routine_named(std::string_view name);
/// The routines the C ABI exports.
RoutineSet abi_routines();
/// The routines of the constraint rows: a module has them exactly when its model
/// has constraints (and the JIT then compiles them for every command).
RoutineSet constraint_routines();
/// "rhs, outputs": the names, in the table's order.
std::string routine_names(RoutineSet set);

} // namespace yamsc::codegen
