#include "codegen/body.hpp"

#include "codegen/body_plan.hpp"
#include "codegen/helper_sources.hpp"
#include "codegen/ldlt_text.hpp"

#include "diag/diagnostics.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace yamsc::codegen {
namespace {

std::string join(const std::vector<std::string>& items, const char* separator) {
    std::string out;
    for (const std::string& item : items) out += (out.empty() ? "" : separator) + item;
    return out;
}

std::string parameter_declaration(const Argument& a, const Syntax& syntax) {
    switch (a.kind) {
    case ArgumentKind::scalar:
        return syntax.real_type + " " + a.name;
    case ArgumentKind::input_array:
        return "const " + syntax.real_type + "* " + a.name;
    case ArgumentKind::params:
        return syntax.params_type + " " + a.name;
    case ArgumentKind::output_array:
        return syntax.real_type + "* " + a.name;
    }
    return a.name;
}

} // namespace

namespace {

void check_signature(const Routine& routine, const std::vector<std::string>& signature) {
    for (const Argument& a : routine.arguments)
        if (a.used && std::find(signature.begin(), signature.end(), a.name) == signature.end())
            throw diag::InternalError("code generation: " + routine.name + " needs '" + a.name +
                                      "', which its short form does not take");
}

// The parameters of a routine's part functions: the function's own, its local
// arrays and, when some temporaries travel between parts, the work array w.
struct PartParameters {
    std::vector<std::string> names;
    std::vector<std::string> declarations;
};

PartParameters part_parameters(const Routine& routine, const Syntax& syntax,
                               const std::vector<std::string>& signature, bool with_work_array) {
    PartParameters p;
    p.names = signature;
    for (const std::string& name : signature)
        p.declarations.push_back(parameter_declaration(*routine.argument(name), syntax));
    for (const LocalArray& l : routine.locals) {
        p.names.push_back(l.name);
        p.declarations.push_back(syntax.real_type + "* " + l.name);
    }
    if (with_work_array) {
        p.names.push_back("w");
        p.declarations.push_back(syntax.real_type + "* w");
    }
    return p;
}

// The loop of a sweep (module.hpp): one call of the internal routine per unit
// direction, its result copied into a column of the target.
std::string sweep_text(const Sweep& w, const Syntax& syntax, const CalleeCosts& callee_costs,
                       OperationCount& count) {
    std::vector<std::string> arguments = w.arguments;
    arguments.at(static_cast<std::size_t>(w.seed_argument)) = "seed";
    arguments.push_back("column");
    const std::string row = w.stride == 1 ? "i" : fmt::format("i * {}", w.stride);
    const std::string target =
        w.offset == 0 ? row + " + k" : fmt::format("{} + {} + k", w.offset, row);
    const std::string source = w.result_first == 0 ? "i" : fmt::format("{} + i", w.result_first);
    const std::string value = w.scale == 1.0 ? "column[" + source + "]"
                              : w.scale == -1.0
                                  ? "-column[" + source + "]"
                                  : format_literal(w.scale, syntax) + " * column[" + source + "]";
    OperationCount per_column;
    if (auto it = callee_costs.find(w.callee); it != callee_costs.end()) per_column = it->second;
    if (w.scale != 1.0 && w.scale != -1.0) per_column.muls += w.rows;
    for (int k = 0; k < w.count; ++k) count += per_column;
    return fmt::format("    for (int k = 0; k < {0}; ++k) {{\n"
                       "        {9} seed[{1}] = {{{10}}};\n"
                       "        {9} column[{2}];\n"
                       "        seed[{3}] = {11};\n"
                       "        {4}{5}({6});\n"
                       "        for (int i = 0; i < {7}; ++i) {8};\n"
                       "    }}\n",
                       w.count, std::max(w.seed_size, 1), std::max(w.result_size, 1),
                       w.first == 0 ? "k" : fmt::format("{} + k", w.first), syntax.helper_prefix,
                       w.callee, join(arguments, ", "), w.rows,
                       fmt::format("{}[{}] = {}", w.target, target, value), syntax.real_type,
                       format_literal(0.0, syntax), format_literal(1.0, syntax));
}

// One statement, appended to `main` (factorisations, solves, sweeps) or `part`.
void print_statement(const Statement& s, const Routine& routine, const LdltPlan& solver,
                     const BodyPlan& plan, const Syntax& syntax, const CalleeCosts& callee_costs,
                     ExprPrinter& printer, std::string& main, std::string& part,
                     OperationCount& count) {
    switch (s.kind) {
    case Statement::Kind::define: {
        const int number = routine.exprs[static_cast<std::size_t>(s.expr)].temporary;
        const bool in_work_array = s.part >= 0 && plan.slot[static_cast<std::size_t>(number)] >= 0;
        part +=
            fmt::format("    {}{} = {};\n", in_work_array ? "" : "const " + syntax.real_type + " ",
                        printer.temporary(number), printer.definition(s.expr));
        break;
    }
    case Statement::Kind::assign:
        part += fmt::format("    {}[{}] = {};\n", s.assignment->array, s.assignment->index,
                            printer.reference(s.expr));
        break;
    case Statement::Kind::factor:
    case Statement::Kind::solve:
        main += solver_statement(solver, *s.step, syntax);
        count += solver_step_count(solver, *s.step);
        break;
    case Statement::Kind::sweep:
        main += sweep_text(s.step->sweep, syntax, callee_costs, count);
        break;
    case Statement::Kind::call:
        main += fmt::format("    {}{}({});\n", syntax.helper_prefix, s.step->call.callee,
                            join(s.step->call.arguments, ", "));
        if (auto it = callee_costs.find(s.step->call.callee); it != callee_costs.end())
            count += it->second;
        break;
    }
}

} // namespace

BodyText body_text(const Routine& routine, const Module& module, const Syntax& syntax,
                   const std::vector<std::string>& signature, int max_statements,
                   const CalleeCosts& callee_costs) {
    check_signature(routine, signature);
    const bool hot = routine.id == RoutineId::rhs || routine.id == RoutineId::outputs_from_qdd;
    const BodyPlan plan =
        plan_body(routine, hot ? hot_part_factor * max_statements : max_statements);
    const bool cut = plan.part_count > 0;
    ExprPrinter printer(routine, module.model, syntax);
    if (cut) {
        std::vector<std::string> names;
        for (int k = 0; k < routine.temporary_count; ++k)
            names.push_back(plan.slot[static_cast<std::size_t>(k)] >= 0
                                ? fmt::format("w[{}]", plan.slot[static_cast<std::size_t>(k)])
                                : ExprPrinter::temporary_name(k));
        printer.set_temporary_names(std::move(names));
    }

    BodyText body;
    std::string& main = body.text;
    if (!cut) // a cut body passes every parameter on, so all are used
        for (const Argument& a : routine.arguments)
            if (!a.used && std::find(signature.begin(), signature.end(), a.name) != signature.end())
                main += fmt::format("    (void){};\n", a.name);
    for (const LocalArray& l : routine.locals)
        main += fmt::format("    {} {}[{}];\n", syntax.real_type, l.name, std::max(l.size, 1));
    if (plan.slot_count > 0)
        main += fmt::format("    {} w[{}];\n", syntax.real_type, plan.slot_count);

    const PartParameters parameters =
        part_parameters(routine, syntax, signature, plan.slot_count > 0);
    int open_part = -1;
    for (const Statement& s : plan.statements) {
        if (s.part >= 0 && s.part != open_part) {
            if (open_part >= 0) body.helpers += "}\n\n";
            open_part = s.part;
            const std::string name =
                fmt::format("{}{}_part{}", syntax.helper_prefix, routine.name, s.part);
            main += fmt::format("    {}({});\n", name, join(parameters.names, ", "));
            body.helpers += fmt::format("{}void {}({}) {{\n", syntax.helper_linkage, name,
                                        join(parameters.declarations, ", "));
            const std::vector<std::string>& used =
                plan.names_used[static_cast<std::size_t>(s.part)];
            for (const std::string& p : parameters.names)
                if (!std::binary_search(used.begin(), used.end(), p))
                    body.helpers += fmt::format("    (void){};\n", p);
        }
        print_statement(s, routine, module.mass_ldlt, plan, syntax, callee_costs, printer, main,
                        s.part >= 0 ? body.helpers : main, body.count);
    }
    if (open_part >= 0) body.helpers += "}\n\n";
    body.count += printer.count();
    return body;
}

namespace {

/// Whether some factor or solve step calls the straight-line functions
/// (`straight`) or the generic loops (`!straight`).
bool uses_solver(const Module& module, bool straight) {
    for (const Routine& r : module.routines)
        for (const Step& s : r.steps)
            if ((s.kind == StepKind::factor || s.kind == StepKind::solve) &&
                straight_line_step(module.mass_ldlt, s) == straight)
                return true;
    return false;
}

} // namespace

std::string solver_helpers_text(const Module& module, const Syntax& syntax,
                                const std::string& linkage) {
    std::string out;
    // Counted by ldlt_factor_count and ldlt_solve_count (printer.cpp) and by
    // straight_factor_count and straight_solve_count (ldlt_text.cpp).
    if (uses_solver(module, false)) out += ldlt_source(syntax, linkage);
    if (uses_solver(module, true))
        out += (out.empty() ? "" : "\n") + straight_ldlt_text(module.mass_ldlt, syntax, linkage);
    return out;
}

} // namespace yamsc::codegen
