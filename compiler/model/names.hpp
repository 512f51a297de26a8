#pragma once
// Names: what the language, C and C++ reserve, and the symbol table of a model.
#include "model/model.hpp"

#include <map>
#include <string>
#include <string_view>

namespace yamsc::model {

/// Why `name` cannot be used for a declaration, or "" if it can.
std::string reserved_reason(std::string_view name);

/// Scalar functions of the expression language and their number of arguments.
int function_arity(std::string_view name); // -1 if not a function

/// Kinematic vector functions, allowed in outputs only: position, velocity, angular_velocity.
bool is_kinematic_function(std::string_view name);
/// The loads a body's joint transmits, allowed in outputs only: reaction_force,
/// reaction_moment (also kinematic functions: vectors of one body).
bool is_reaction_function(std::string_view name);

struct NameInfo {
    NameKind kind;
    int index; // into the model's list of that kind
    Loc loc;
};

using SymbolTable = std::map<std::string, NameInfo>;

} // namespace yamsc::model
