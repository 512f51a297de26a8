#pragma once
// What every emitter of a Module checks on entry, in one place. The driver
// validates user input first, so a failure here is an internal error.
#include "codegen/emit.hpp"
#include "codegen/module.hpp"

#include <string>

namespace yamsc::codegen {

/// How a target names the model's scope.
enum class ScopeName {
    cpp_namespace, // identifiers joined by ::
    c_identifier,  // one identifier, the prefix of every name
};

/// The namespace or prefix of the generated code (the model's name when the
/// options give none), after checking it, the parameters' names (identifiers
/// in every target) and the header's name.
std::string checked_scope(const Module& module, const EmitOptions& options, ScopeName rule);

} // namespace yamsc::codegen
