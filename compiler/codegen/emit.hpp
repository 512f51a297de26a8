#pragma once
// Emitters: print a Module as C++ or C99 source (and header), following
// docs/generated-api.md. The output depends only on the Module and the
// options, byte for byte.
#include "codegen/module.hpp"

#include <string>

namespace yamsc::codegen {

struct EmitOptions {
    /// C++ namespace (identifiers joined by ::) or C prefix (an identifier);
    /// empty: the model name.
    std::string namespace_name;
    /// Non-empty: emit a header too, which the source includes as "header_name".
    std::string header_name;
    /// Written in the header comment.
    std::string compiler_version;
    /// The options as given on the command line, for the header comment.
    std::string command_line;
    /// A function with more statements is cut into part functions of at most
    /// this many (compilers are superlinear in function size); 0: never cut.
    int max_function_statements = 200;
    /// The floating-point type of the generated C (`double` or `float`): every
    /// argument, temporary, literal and math function follows it.
    enum class Real { double_precision, single_precision } real = Real::double_precision;
};

struct EmittedFiles {
    std::string source;
    std::string header; // empty unless EmitOptions::header_name is set
};

/// Throws diag::InternalError for an invalid namespace or header name (the
/// driver validates user input first) or a malformed module.
EmittedFiles emit_cpp(const Module& module, const EmitOptions& options);
EmittedFiles emit_c(const Module& module, const EmitOptions& options);

} // namespace yamsc::codegen
