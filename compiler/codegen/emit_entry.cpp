#include "codegen/emit_entry.hpp"

#include "codegen/header_comment.hpp"
#include "codegen/text.hpp"
#include "diag/diagnostics.hpp"

namespace yamsc::codegen {

std::string checked_scope(const Module& module, const EmitOptions& options, ScopeName rule) {
    const std::string scope =
        options.namespace_name.empty() ? module.model.name : options.namespace_name;
    if (rule == ScopeName::cpp_namespace && !is_cpp_namespace(scope))
        throw diag::InternalError("code generation: '" + scope + "' is not a C++ namespace name");
    if (rule == ScopeName::c_identifier && !is_c_identifier(scope))
        throw diag::InternalError("code generation: '" + scope + "' is not a C identifier");
    check_printed_names(module, options);
    return scope;
}

} // namespace yamsc::codegen
