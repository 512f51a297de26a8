// The C++17 emitter: one namespace per model with constexpr sizes and names, a
// Params struct with defaults, the model functions and the Model bundle the
// runtime's from_generated<NS::Model> takes (docs/generated-api.md).
#include "codegen/body.hpp"
#include "codegen/emit.hpp"
#include "codegen/emit_entry.hpp"
#include "codegen/external_wrappers.hpp"
#include "codegen/functions.hpp"
#include "codegen/header_comment.hpp"
#include "codegen/text.hpp"
#include "diag/diagnostics.hpp"

#include <fmt/format.h>
#include <optional>

namespace yamsc::codegen {
namespace {

std::string parameter_text(const Argument& a) {
    switch (a.kind) {
    case ArgumentKind::scalar:
        return "double " + a.name;
    case ArgumentKind::input_array:
        return "const double* " + a.name;
    case ArgumentKind::params:
        return "const Params& " + a.name;
    case ArgumentKind::output_array:
        return "double* " + a.name;
    }
    return a.name;
}

std::string signature(const FunctionPlan& plan) {
    std::string params;
    for (const Argument* a : plan.parameters) {
        if (!params.empty()) params += ", ";
        params += parameter_text(*a);
    }
    return fmt::format("void {}({})", plan.routine->name, params);
}

std::string call_arguments(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
    return out;
}

std::string name_array(const char* name, const char* size_name, int size,
                       const std::vector<std::string>& names) {
    std::string items;
    for (const std::string& n : names) items += (items.empty() ? "" : ", ") + c_string_literal(n);
    if (names.empty()) items = "\"\"";
    return fmt::format("inline constexpr const char* {}[{}] = {{{}}};\n", name,
                       size > 0 ? size_name : "1", items);
}

bool any_param_without_default(const ModelInfo& m) {
    for (const ParamInfo& p : m.params)
        if (!p.default_value) return true;
    return false;
}

std::string params_struct(const ModelInfo& m) {
    std::string out = "// The parameters with their defaults; NaN: no default, set it before use.\n"
                      "struct Params {\n";
    for (const ParamInfo& p : m.params) {
        out += fmt::format("    double {} = {};", p.name,
                           p.default_value ? format_number(*p.default_value)
                                           : "std::numeric_limits<double>::quiet_NaN()");
        if (!p.doc.empty()) out += " // " + comment_quote(p.doc);
        out += "\n";
    }
    return out + "};\n";
}

/// The constraints' sizes and rows (only in models with constraints: the others
/// print as before).
std::string constraint_declarations(const ModelInfo& m) {
    if (m.constraints.empty()) return "";
    std::vector<std::string> names, sources;
    std::string dependent;
    for (const ConstraintInfo& c : m.constraints) {
        names.push_back(c.name);
        sources.push_back(c.source);
        dependent += (dependent.empty() ? "" : ", ") + std::to_string(c.dependent);
    }
    return fmt::format(
               "// Constraints: nc rows r = B q' + c = 0, the first nh holonomic (phi = 0).\n"
               "inline constexpr int nh = {}, nc = {};\n",
               m.nh(), m.nc()) +
           name_array("constraint_names", "nc", m.nc(), names) +
           fmt::format("// The DOF each row's declaration names `dependent`, or -1.\n"
                       "inline constexpr int constraint_dependent[nc] = {{{}}};\n",
                       dependent) +
           name_array("constraint_sources", "nc", m.nc(), sources);
}

std::string constraint_members(const ModelInfo& m, const std::string& q) {
    if (m.constraints.empty()) return "";
    return fmt::format("    static constexpr int nh = {0}nh, nc = {0}nc;\n"
                       "    static constexpr const char* const* constraint_names = "
                       "{0}constraint_names;\n"
                       "    static constexpr const int* constraint_dependent = "
                       "{0}constraint_dependent;\n"
                       "    static constexpr const char* const* constraint_sources = "
                       "{0}constraint_sources;\n",
                       q);
}

std::string model_struct(const std::string& ns, const ModelInfo& m,
                         const std::vector<FunctionPlan>& plans) {
    const std::string q = "::" + ns + "::";
    std::string out = fmt::format(
        "// Everything above in one type, for templates (the runtime's from_generated<Model>).\n"
        "struct Model {{\n"
        "    using Params = {0}Params;\n"
        "    static constexpr int nq = {0}nq, nu = {0}nu, np = {0}np, ny = {0}ny;\n"
        "    static constexpr const char* model_name = {0}model_name;\n"
        "    static constexpr const char* const* dof_names = {0}dof_names;\n"
        "    static constexpr const char* const* input_names = {0}input_names;\n"
        "    static constexpr const char* const* param_names = {0}param_names;\n"
        "    static constexpr const char* const* output_names = {0}output_names;\n",
        q);
    out += constraint_members(m, q);
    for (const FunctionPlan& plan : plans) {
        if (plan.short_form) continue;
        out += fmt::format("    static {} {{\n        {}{}({});\n    }}\n", signature(plan), q,
                           plan.routine->name, call_arguments(parameter_names(plan)));
    }
    out += fmt::format("    static void params_to_array(const Params& p, double* a) {{\n"
                       "        {0}params_to_array(p, a);\n    }}\n"
                       "    static Params params_from_array(const double* a) {{\n"
                       "        return {0}params_from_array(a);\n    }}\n",
                       q);
    return out + "};\n";
}

std::string declarations(const Module& module, const std::string& ns,
                         const std::vector<FunctionPlan>& plans) {
    const ModelInfo& m = module.model;
    std::vector<std::string> dofs, inputs, params, outputs;
    for (const NamedDoc& d : m.dofs) dofs.push_back(d.name);
    for (const NamedDoc& u : m.inputs) inputs.push_back(u.name);
    for (const ParamInfo& p : m.params) params.push_back(p.name);
    for (const NamedDoc& y : m.outputs) outputs.push_back(y.name);

    std::string out;
    if (!module.externals.empty())
        out += "// The model's external functions: the user provides them.\n" +
               external_prototypes(module) + "\n";
    out += fmt::format("namespace {} {{\n\n", ns);
    out += fmt::format("inline constexpr int nq = {}, nu = {}, np = {}, ny = {};\n", m.nq(), m.nu(),
                       m.np(), m.ny());
    out += fmt::format("inline constexpr const char* model_name = {};\n", c_string_literal(m.name));
    out += name_array("dof_names", "nq", m.nq(), dofs);
    out += name_array("input_names", "nu", m.nu(), inputs);
    out += name_array("param_names", "np", m.np(), params);
    out += name_array("output_names", "ny", m.ny(), outputs);
    out += constraint_declarations(m);
    out += "\n" + params_struct(m) + "\n";
    out += "// The parameters as an array of np values, in declaration order, and back.\n"
           "void params_to_array(const Params& p, double* a);\n"
           "Params params_from_array(const double* a);\n\n";
    out += "// M(q) q'' = F(q, q', u, t); u may be null when nu == 0.\n";
    for (const FunctionPlan& plan : plans) {
        out += fmt::format("// {}\n", plan.short_form
                                          ? std::string("M(q) when it depends on q and p only")
                                          : plan.routine->summary);
        out += signature(plan) + ";\n";
    }
    out += "\n" + model_struct(ns, m, plans) + "\n";
    return out + fmt::format("}} // namespace {}\n", ns);
}

std::string params_functions(const ModelInfo& m) {
    std::string to = "void params_to_array(const Params& p, double* a) {\n";
    std::string from = "Params params_from_array(const double* a) {\n";
    if (m.params.empty()) {
        to += "    (void)p;\n    (void)a;\n";
        from += "    (void)a;\n";
    }
    from += "    Params p;\n";
    for (std::size_t i = 0; i < m.params.size(); ++i) {
        to += fmt::format("    a[{}] = p.{};\n", i, m.params[i].name);
        from += fmt::format("    p.{} = a[{}];\n", m.params[i].name, i);
    }
    return to + "}\n\n" + from + "    return p;\n}\n";
}

struct Definitions {
    std::string text;
    std::string helpers; // part functions of the bodies cut in parts
    std::vector<FunctionCost> costs;
};

// The internal routines of the tangent form, defined in the anonymous
// namespace before the functions whose sweeps call them.
Definitions internal_definitions(const Module& module, int max_statements, CalleeCosts& costs) {
    const Syntax syntax = cpp_syntax();
    Definitions d;
    for (const FunctionPlan& plan : internal_function_plans(module)) {
        BodyText body =
            body_text(*plan.routine, module, syntax, parameter_names(plan), max_statements, costs);
        d.helpers += body.helpers;
        d.helpers +=
            "// " + plan.routine->summary + "\n" + signature(plan) + " {\n" + body.text + "}\n\n";
        d.costs.push_back({plan.routine->name, body.count});
        costs[plan.routine->name] = body.count;
    }
    return d;
}

Definitions definitions(const Module& module, const std::vector<FunctionPlan>& plans,
                        int max_statements, CalleeCosts callee_costs) {
    const Syntax syntax = cpp_syntax();
    // Printed callees first, so that a call (outputs calls rhs) is priced;
    // written in the plans' order.
    std::vector<std::string> texts(plans.size()), helpers(plans.size());
    std::vector<std::optional<FunctionCost>> costs(plans.size());
    for (std::size_t i : callees_first(plans)) {
        const FunctionPlan& plan = plans[i];
        std::string& text = texts[i];
        if (!module.externals.empty() && wrapped_routine(*plan.routine)) {
            text = external_wrapper_body(module, *plan.routine->id);
        } else if (plan.forwards_to_short) {
            for (const Argument* a : plan.not_forwarded) text += "    (void)" + a->name + ";\n";
            text += "    mass_matrix(q, p, M);\n";
        } else {
            BodyText body = body_text(*plan.routine, module, syntax, parameter_names(plan),
                                      max_statements, callee_costs);
            text = std::move(body.text);
            helpers[i] = std::move(body.helpers);
            costs[i] = FunctionCost{plan.routine->name, body.count};
            callee_costs[plan.routine->name] = body.count;
        }
    }
    Definitions d;
    d.text = params_functions(module.model);
    for (std::size_t i = 0; i < plans.size(); ++i) {
        d.text += "\n// " + plans[i].routine->summary + "\n" + signature(plans[i]) + " {\n" +
                  texts[i] + "}\n";
        d.helpers += helpers[i];
        if (costs[i]) d.costs.push_back(*costs[i]);
    }
    return d;
}

} // namespace

EmittedFiles emit_cpp(const Module& module, const EmitOptions& options) {
    const std::string ns = checked_scope(module, options, ScopeName::cpp_namespace);

    const std::vector<FunctionPlan> plans = function_plans(module);
    CalleeCosts callee_costs;
    const bool externals = !module.externals.empty();
    const Module inner = externals ? with_inner_routines(module) : Module{};
    Definitions internal = internal_definitions(externals ? inner : module,
                                                options.max_function_statements, callee_costs);
    if (externals) internal.helpers += external_support(module) + "\n";
    Definitions defs = definitions(module, plans, options.max_function_statements, callee_costs);
    defs.helpers = internal.helpers + defs.helpers;
    defs.costs.insert(defs.costs.end(), internal.costs.begin(), internal.costs.end());
    const std::string comment =
        header_comment(module, options, "C++17", ns, defs.costs) + external_comment(module);
    const std::string limits = any_param_without_default(module.model) ? "#include <limits>\n" : "";
    const std::string decls = declarations(module, ns, plans);

    std::string body = externals ? external_weak_declarations(module) + "\n" : "";
    body += fmt::format("namespace {} {{\n", ns);
    std::string helpers = solver_helpers_text(module, cpp_syntax(), "");
    if (!defs.helpers.empty()) helpers += (helpers.empty() ? "" : "\n") + defs.helpers;
    if (!helpers.empty()) body += "namespace {\n\n" + helpers + "\n} // namespace\n";
    body += "\n" + defs.text + "\n" + fmt::format("}} // namespace {}\n", ns);

    const std::string includes =
        externals ? "#include <cmath>\n#include <cstdio>\n#include <stdexcept>\n#include <string>\n"
                  : "#include <cmath>\n";
    EmittedFiles files;
    if (options.header_name.empty()) {
        files.source = comment + "\n" + includes + limits + "\n" + decls + "\n" + body;
    } else {
        files.header =
            comment + "\n#pragma once\n\n" + limits + (limits.empty() ? "" : "\n") + decls;
        files.source =
            comment + "\n#include \"" + options.header_name + "\"\n\n" + includes + "\n" + body;
    }
    return files;
}

} // namespace yamsc::codegen
