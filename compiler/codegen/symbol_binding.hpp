#pragma once
// How a routine reads the symbols of the equations: the arrays its arguments
// or locals hold them in. Every routine builder binds symbols through one
// SymbolSource, so the rules (t = 0 in the linear model, q' after q in x, ...)
// are written once.
#include "codegen/module.hpp"
#include "codegen/routine_builder.hpp"
#include "codegen/routines.hpp"

#include <string>
#include <vector>

namespace yamsc::codegen {

/// array[index] as an expression.
Expr load(const std::string& array, int index);
/// An argument of a routine, not yet marked used.
Argument argument(const char* name, ArgumentKind kind);

/// Where each kind of symbol is read: array names (and offsets into them); an
/// empty name leaves the kind unbound (a routine that meets it is malformed).
/// An empty `time` reads t as 0: the linear model has no time argument.
struct SymbolSource {
    std::string time = "t";
    std::string q = "q";
    int q_offset = 0;
    std::string qd = "qd";
    int qd_offset = 0;
    std::string u = "u";
    std::string a;      // the vector `a` of M a
    std::string qdd;    // q''
    std::string seed;   // the tangent form's direction
    std::string lambda; // the constraint reactions λ

    /// q, q' from the state vector x = [q, q'].
    static SymbolSource state_vector(int nq);
    /// The operating point (q0, qd0, u0) of the linear routines, t = 0, `a` from
    /// the solved accelerations qdd0.
    static SymbolSource operating_point();
};

RoutineBuilder::Binding bind(SymbolSource source);

/// (q0, qd0, u0, p, outputs...): the arguments of the linear model's routines.
std::vector<Argument> point_arguments(std::vector<Argument> outputs);

/// The name, summary and arguments of a function of the generated API, from
/// its row of the routine table (codegen/routines.hpp), for both forms
/// (unrolled and tangent) so that they cannot drift apart.
RoutineBuilder::Signature api_signature(RoutineId id);

} // namespace yamsc::codegen
