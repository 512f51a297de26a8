// The C99 emitter: the same functions as in C++ with a `<prefix>_` on every
// name, a `<prefix>_params` struct and `<prefix>_default_params(void)`, plus
// `<prefix>_rk4_step`; clean under gcc -std=c99 -pedantic -Wall -Wextra -Werror.
// The API spells its floating-point type `<prefix>_real` (double, or float with
// --real float); inside the functions the type is written out.
#include "codegen/body.hpp"
#include "codegen/emit.hpp"
#include "codegen/emit_c_rk4.hpp"
#include "codegen/emit_entry.hpp"
#include "codegen/functions.hpp"
#include "codegen/header_comment.hpp"
#include "codegen/text.hpp"
#include "diag/diagnostics.hpp"
#include "diag/errors.hpp"

#include <fmt/format.h>
#include <optional>

namespace yamsc::codegen {
namespace {

struct CNames {
    std::string prefix;
    bool single_precision = false;
    std::string real() const { return prefix + "_real"; }
    std::string function(const FunctionPlan& plan) const {
        const bool full_mass_matrix =
            plan.routine->id == RoutineId::mass_matrix && !plan.short_form;
        return prefix + "_" + plan.routine->name + (full_mass_matrix ? "_tu" : "");
    }
    std::string params_type() const { return prefix + "_params"; }
    Rk4Names rk4() const { return {prefix, real(), params_type()}; }
};

Syntax syntax_of(const CNames& names) {
    return c_syntax(names.prefix, names.single_precision);
}

std::string parameter_text(const CNames& names, const Argument& a) {
    switch (a.kind) {
    case ArgumentKind::scalar:
        return names.real() + " " + a.name;
    case ArgumentKind::input_array:
        return "const " + names.real() + "* " + a.name;
    case ArgumentKind::params:
        return "const " + names.params_type() + "* " + a.name;
    case ArgumentKind::output_array:
        return names.real() + "* " + a.name;
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
    if (!m.constraints.empty()) {
        arrays.push_back({"constraint_names", {}});
        arrays.push_back({"constraint_sources", {}});
        for (const ConstraintInfo& c : m.constraints) {
            arrays[4].names.push_back(c.name);
            arrays[5].names.push_back(c.source);
        }
    }
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
    if (!m.constraints.empty())
        out +=
            fmt::format("// Constraints: nc rows r = B q' + c = 0, the first nh holonomic (phi = "
                        "0).\nenum {{ {0}_nh = {1}, {0}_nc = {2} }};\n\n",
                        x, m.nh(), m.nc());
    out += fmt::format("// The floating-point type of every argument and parameter (--real).\n"
                       "typedef {} {};\n\n",
                       names.single_precision ? "float" : "double", names.real());
    out += fmt::format("extern const char* const {}_model_name;\n", x);
    for (const NameArray& a : name_arrays(m))
        out += fmt::format("extern const char* const {}_{}[{}];\n", x, a.suffix, array_size(a));
    if (!m.constraints.empty())
        out +=
            fmt::format("// The DOF each constraint row's declaration names `dependent`, or -1.\n"
                        "extern const int {}_constraint_dependent[{}];\n",
                        x, m.nc());
    out += fmt::format("\n// The parameters; {}_default_params() gives their defaults (NaN: no\n"
                       "// default, set it before use).\n",
                       x);
    out += fmt::format("typedef struct {} {{\n", names.params_type());
    if (m.params.empty()) out += "    int no_parameters; /* C has no empty structs */\n";
    for (const ParamInfo& p : m.params) {
        out += fmt::format("    {} {};", names.real(), p.name);
        if (!p.doc.empty()) out += " // " + comment_quote(p.doc);
        out += "\n";
    }
    out += fmt::format("}} {};\n\n", names.params_type());
    out +=
        fmt::format("{0} {1}_default_params(void);\n"
                    "// The parameters as an array of np values, in declaration order, and back.\n"
                    "void {1}_params_to_array(const {0}* p, {2}* a);\n"
                    "{0} {1}_params_from_array(const {2}* a);\n\n",
                    names.params_type(), x, names.real());
    out += "// M(q) q'' = F(q, q', u, t); u may be NULL when nu == 0.\n";
    for (const FunctionPlan& plan : plans) {
        out += fmt::format("// {}\n", plan.short_form
                                          ? std::string("M(q) when it depends on q and p only")
                                          : plan.routine->summary);
        out += signature(names, plan) + ";\n";
    }
    out += "// x += one classical RK4 step of h from t (x = [q, q'], u held over the step)\n";
    out += rk4_signature(names.rk4()) + ";\n";
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
    if (!module.model.constraints.empty()) {
        std::string dependent;
        for (const ConstraintInfo& c : module.model.constraints)
            dependent += (dependent.empty() ? "" : ", ") + std::to_string(c.dependent);
        out += fmt::format("const int {}_constraint_dependent[{}] = {{{}}};\n", x,
                           module.model.nc(), dependent);
    }
    return out;
}

// A parameter's default as a literal of the code's type.
std::string default_literal(const ParamInfo& p, const Syntax& syntax) {
    if (!p.default_value) return "NAN";
    try {
        return format_literal(*p.default_value, syntax);
    } catch (const NumberOutOfRange& e) {
        throw NumberOutOfRange("the default of parameter '" + p.name + "': " + e.what());
    }
}

std::string params_functions(const ModelInfo& m, const CNames& names) {
    const std::string& type = names.params_type();
    const std::string& x = names.prefix;
    const Syntax syntax = syntax_of(names);
    std::string defaults = fmt::format("{0} {1}_default_params(void) {{\n    {0} p;\n", type, x);
    std::string to =
        fmt::format("void {}_params_to_array(const {}* p, {}* a) {{\n", x, type, names.real());
    std::string from =
        fmt::format("{0} {1}_params_from_array(const {2}* a) {{\n", type, x, names.real());
    if (m.params.empty()) {
        defaults += "    p.no_parameters = 0;\n";
        to += "    (void)p;\n    (void)a;\n";
        from += "    (void)a;\n";
    }
    from += fmt::format("    {} p = {}_default_params();\n", type, x);
    for (std::size_t i = 0; i < m.params.size(); ++i) {
        const ParamInfo& p = m.params[i];
        defaults += fmt::format("    p.{} = {};\n", p.name, default_literal(p, syntax));
        to += fmt::format("    a[{}] = p->{};\n", i, p.name);
        from += fmt::format("    p.{} = a[{}];\n", p.name, i);
    }
    return defaults + "    return p;\n}\n\n" + to + "}\n\n" + from + "    return p;\n}\n";
}

// The body of a plan's function; a constant out of the float range is
// reported with the function it is in.
BodyText printed_body(const FunctionPlan& plan, const Module& module, const Syntax& syntax,
                      int max_statements, const CalleeCosts& callee_costs) {
    try {
        return body_text(*plan.routine, module, syntax, parameter_names(plan), max_statements,
                         callee_costs);
    } catch (const NumberOutOfRange& e) {
        throw NumberOutOfRange("in " + plan.routine->name + ": " + e.what());
    }
}

struct Definitions {
    std::string text;
    std::string helpers; // part functions of the bodies cut in parts
    std::vector<FunctionCost> costs;
};

// The internal routines of the tangent form, static and defined before the
// functions whose sweeps call them; their costs price those sweeps.
Definitions internal_definitions(const Module& module, const CNames& names, int max_statements,
                                 CalleeCosts& callee_costs) {
    const Syntax syntax = syntax_of(names);
    Definitions d;
    for (const FunctionPlan& plan : internal_function_plans(module)) {
        const BodyText body = printed_body(plan, module, syntax, max_statements, callee_costs);
        d.helpers += body.helpers;
        d.helpers += "// " + plan.routine->summary + "\nstatic " + signature(names, plan) + " {\n" +
                     body.text + "}\n\n";
        d.costs.push_back({plan.routine->name, body.count});
        callee_costs[plan.routine->name] = body.count;
    }
    return d;
}

Definitions definitions(const Module& module, const CNames& names,
                        const std::vector<FunctionPlan>& plans, int max_statements,
                        CalleeCosts callee_costs) {
    const Syntax syntax = syntax_of(names);
    // Printed callees first, so that a call (outputs calls rhs) is priced;
    // written in the plans' order.
    std::vector<std::string> texts(plans.size()), helpers(plans.size());
    std::vector<std::optional<FunctionCost>> costs(plans.size());
    for (std::size_t i : callees_first(plans)) {
        const FunctionPlan& plan = plans[i];
        if (plan.forwards_to_short) {
            for (const Argument* a : plan.not_forwarded) texts[i] += "    (void)" + a->name + ";\n";
            texts[i] += fmt::format("    {}_mass_matrix(q, p, M);\n", names.prefix);
        } else {
            BodyText body = printed_body(plan, module, syntax, max_statements, callee_costs);
            texts[i] = std::move(body.text);
            helpers[i] = std::move(body.helpers);
            costs[i] = FunctionCost{plan.routine->name, body.count};
            callee_costs[plan.routine->name] = body.count;
        }
    }
    Definitions d;
    d.text = params_functions(module.model, names);
    for (std::size_t i = 0; i < plans.size(); ++i) {
        d.text += "\n// " + plans[i].routine->summary + "\n" + signature(names, plans[i]) + " {\n" +
                  texts[i] + "}\n";
        d.helpers += helpers[i];
        if (costs[i]) d.costs.push_back(*costs[i]);
    }
    // rk4_step last: it calls rhs, and its cost is four of rhs's.
    OperationCount rhs;
    for (const FunctionCost& c : d.costs)
        if (c.name == routine_name(RoutineId::rhs)) rhs = c.count;
    const int nx = 2 * module.model.nq();
    d.text += "\n// x += one classical RK4 step of h from t (x = [q, q'], u held over the step)\n" +
              rk4_definition(names.rk4(), syntax, nx);
    d.costs.push_back({"rk4_step", rk4_count(nx, rhs)});
    return d;
}

} // namespace

EmittedFiles emit_c(const Module& module, const EmitOptions& options) {
    if (!module.externals.empty())
        throw diag::UserError(module.externals.front().location + ": external function '" +
                              module.externals.front().name +
                              "': external functions are not supported in --lang c yet (use "
                              "--lang cpp)");
    CNames names;
    names.prefix = checked_scope(module, options, ScopeName::c_identifier);
    names.single_precision = options.real == EmitOptions::Real::single_precision;

    const std::vector<FunctionPlan> plans = function_plans(module);
    CalleeCosts callee_costs;
    const Definitions internal =
        internal_definitions(module, names, options.max_function_statements, callee_costs);
    Definitions defs =
        definitions(module, names, plans, options.max_function_statements, callee_costs);
    defs.helpers = internal.helpers + defs.helpers;
    defs.costs.insert(defs.costs.end(), internal.costs.begin(), internal.costs.end());
    const std::string comment = header_comment(module, options, "C", names.prefix, defs.costs);
    const std::string decls = declarations(module, names, plans);

    std::string body = data_definitions(module, names);
    if (const std::string solver = solver_helpers_text(module, syntax_of(names), "static ");
        !solver.empty())
        body += "\n" + solver;
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
