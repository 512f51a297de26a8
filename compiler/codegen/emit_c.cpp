// The C99 emitter: the same functions as in C++ with a `<prefix>_` on every
// name, a `<prefix>_params` struct and `<prefix>_default_params(void)`;
// clean under gcc -std=c99 -pedantic -Wall -Wextra -Werror.
#include "codegen/body.hpp"
#include "codegen/emit.hpp"
#include "codegen/functions.hpp"
#include "codegen/header_comment.hpp"
#include "codegen/text.hpp"
#include "diag/diagnostics.hpp"

#include <fmt/format.h>

namespace yamsc::codegen {
namespace {

struct CNames {
    std::string prefix;
    std::string function(const FunctionPlan& plan) const {
        const bool full_mass_matrix = plan.routine->name == "mass_matrix" && !plan.short_form;
        return prefix + "_" + plan.routine->name + (full_mass_matrix ? "_tu" : "");
    }
    std::string params_type() const { return prefix + "_params"; }
};

std::string parameter_text(const CNames& names, const Argument& a) {
    switch (a.kind) {
    case ArgumentKind::scalar:
        return "double " + a.name;
    case ArgumentKind::input_array:
        return "const double* " + a.name;
    case ArgumentKind::params:
        return "const " + names.params_type() + "* " + a.name;
    case ArgumentKind::output_array:
        return "double* " + a.name;
    }
    return a.name;
}

std::string signature(const CNames& names, const FunctionPlan& plan) {
    std::string params;
    for (const Argument* a : plan.parameters) {
        if (!params.empty()) params += ", ";
        params += parameter_text(names, *a);
    }
    return fmt::format("void {}({})", names.function(plan), params);
}

struct NameArray {
    const char* suffix;
    std::vector<std::string> names;
};

std::vector<NameArray> name_arrays(const ModelInfo& m) {
    std::vector<NameArray> arrays{
        {"dof_names", {}}, {"input_names", {}}, {"param_names", {}}, {"output_names", {}}};
    for (const NamedDoc& d : m.dofs) arrays[0].names.push_back(d.name);
    for (const NamedDoc& u : m.inputs) arrays[1].names.push_back(u.name);
    for (const ParamInfo& p : m.params) arrays[2].names.push_back(p.name);
    for (const NamedDoc& y : m.outputs) arrays[3].names.push_back(y.name);
    return arrays;
}

std::string array_size(const NameArray& a) {
    return std::to_string(std::max<std::size_t>(a.names.size(), 1));
}

std::string declarations(const Module& module, const CNames& names,
                         const std::vector<FunctionPlan>& plans) {
    const ModelInfo& m = module.model;
    const std::string& x = names.prefix;
    std::string out =
        fmt::format("enum {{ {0}_nq = {1}, {0}_nu = {2}, {0}_np = {3}, {0}_ny = {4} }};\n\n", x,
                    m.nq(), m.nu(), m.np(), m.ny());
    out += fmt::format("extern const char* const {}_model_name;\n", x);
    for (const NameArray& a : name_arrays(m))
        out += fmt::format("extern const char* const {}_{}[{}];\n", x, a.suffix, array_size(a));
    out += fmt::format("\n// The parameters; {}_default_params() gives their defaults (NaN: no\n"
                       "// default, set it before use).\n",
                       x);
    out += fmt::format("typedef struct {} {{\n", names.params_type());
    if (m.params.empty()) out += "    int no_parameters; /* C has no empty structs */\n";
    for (const ParamInfo& p : m.params) {
        out += fmt::format("    double {};", p.name);
        if (!p.doc.empty()) out += " // " + comment_quote(p.doc);
        out += "\n";
    }
    out += fmt::format("}} {};\n\n", names.params_type());
    out +=
        fmt::format("{0} {1}_default_params(void);\n"
                    "// The parameters as an array of np values, in declaration order, and back.\n"
                    "void {1}_params_to_array(const {0}* p, double* a);\n"
                    "{0} {1}_params_from_array(const double* a);\n\n",
                    names.params_type(), x);
    out += "// M(q) q'' = F(q, q', u, t); u may be NULL when nu == 0.\n";
    for (const FunctionPlan& plan : plans) {
        out += fmt::format("// {}\n", plan.short_form
                                          ? std::string("M(q) when it depends on q and p only")
                                          : plan.routine->summary);
        out += signature(names, plan) + ";\n";
    }
    return out;
}

std::string data_definitions(const Module& module, const CNames& names) {
    const std::string& x = names.prefix;
    std::string out = fmt::format("const char* const {}_model_name = {};\n", x,
                                  c_string_literal(module.model.name));
    for (const NameArray& a : name_arrays(module.model)) {
        std::string items;
        for (const std::string& n : a.names)
            items += (items.empty() ? "" : ", ") + c_string_literal(n);
        if (a.names.empty()) items = "\"\"";
        out += fmt::format("const char* const {}_{}[{}] = {{{}}};\n", x, a.suffix, array_size(a),
                           items);
    }
    return out;
}

std::string params_functions(const ModelInfo& m, const CNames& names) {
    const std::string& type = names.params_type();
    const std::string& x = names.prefix;
    std::string defaults = fmt::format("{0} {1}_default_params(void) {{\n    {0} p;\n", type, x);
    std::string to = fmt::format("void {}_params_to_array(const {}* p, double* a) {{\n", x, type);
    std::string from = fmt::format("{0} {1}_params_from_array(const double* a) {{\n", type, x);
    if (m.params.empty()) {
        defaults += "    p.no_parameters = 0;\n";
        to += "    (void)p;\n    (void)a;\n";
        from += "    (void)a;\n";
    }
    from += fmt::format("    {} p = {}_default_params();\n", type, x);
    for (std::size_t i = 0; i < m.params.size(); ++i) {
        const ParamInfo& p = m.params[i];
        defaults += fmt::format("    p.{} = {};\n", p.name,
                                p.default_value ? format_number(*p.default_value) : "NAN");
        to += fmt::format("    a[{}] = p->{};\n", i, p.name);
        from += fmt::format("    p.{} = a[{}];\n", p.name, i);
    }
    return defaults + "    return p;\n}\n\n" + to + "}\n\n" + from + "    return p;\n}\n";
}

struct Definitions {
    std::string text;
    std::string helpers; // part functions of the bodies cut in parts
    std::vector<FunctionCost> costs;
};

Definitions definitions(const Module& module, const CNames& names,
                        const std::vector<FunctionPlan>& plans, int max_statements) {
    const Syntax syntax = c_syntax(names.prefix);
    Definitions d;
    d.text = params_functions(module.model, names);
    for (const FunctionPlan& plan : plans) {
        d.text += "\n// " + plan.routine->summary + "\n" + signature(names, plan) + " {\n";
        if (plan.forwards_to_short) {
            for (const Argument* a : plan.parameters)
                if (a->name == "t" || a->name == "u") d.text += "    (void)" + a->name + ";\n";
            d.text += fmt::format("    {}_mass_matrix(q, p, M);\n", names.prefix);
        } else {
            BodyText body = body_text(*plan.routine, module.model, syntax, parameter_names(plan),
                                      max_statements);
            d.text += body.text;
            d.helpers += body.helpers;
            d.costs.push_back({plan.routine->name, body.count});
        }
        d.text += "}\n";
    }
    return d;
}

} // namespace

EmittedFiles emit_c(const Module& module, const EmitOptions& options) {
    CNames names;
    names.prefix = options.namespace_name.empty() ? module.model.name : options.namespace_name;
    if (!is_c_identifier(names.prefix))
        throw diag::InternalError("code generation: '" + names.prefix + "' is not a C identifier");
    for (const ParamInfo& p : module.model.params)
        if (!is_c_identifier(p.name))
            throw diag::InternalError("code generation: parameter name '" + p.name +
                                      "' is not an identifier");
    check_header_name(options.header_name);

    const std::vector<FunctionPlan> plans = function_plans(module);
    const Definitions defs = definitions(module, names, plans, options.max_function_statements);
    const std::string comment = header_comment(module, options, "C", names.prefix, defs.costs);
    const std::string decls = declarations(module, names, plans);

    std::string body = data_definitions(module, names);
    if (uses_solver(module)) body += "\n" + solver_helpers_text(c_syntax(names.prefix), "static ");
    if (!defs.helpers.empty()) body += "\n" + defs.helpers;
    body += "\n" + defs.text;

    EmittedFiles files;
    if (options.header_name.empty()) {
        files.source = comment + "\n#include <math.h>\n\n" + decls + "\n" + body;
    } else {
        const std::string guard = names.prefix + "_YAMSC_GENERATED_H";
        files.header = comment + "\n#ifndef " + guard + "\n#define " + guard +
                       "\n\n#ifdef __cplusplus\nextern \"C\" {\n#endif\n\n" + decls +
                       "\n#ifdef __cplusplus\n}\n#endif\n\n#endif\n";
        files.source =
            comment + "\n#include \"" + options.header_name + "\"\n\n#include <math.h>\n\n" + body;
    }
    return files;
}

} // namespace yamsc::codegen
