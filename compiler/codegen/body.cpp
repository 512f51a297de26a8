#include "codegen/body.hpp"

#include "codegen/body_plan.hpp"

#include "diag/diagnostics.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace yamsc::codegen {
namespace {

std::string array_at(const std::string& array, int offset) {
    return offset == 0 ? array : fmt::format("{} + {}", array, offset);
}

std::string join(const std::vector<std::string>& items, const char* separator) {
    std::string out;
    for (const std::string& item : items) out += (out.empty() ? "" : separator) + item;
    return out;
}

std::string parameter_declaration(const Argument& a, const Syntax& syntax) {
    switch (a.kind) {
    case ArgumentKind::scalar:
        return "double " + a.name;
    case ArgumentKind::input_array:
        return "const double* " + a.name;
    case ArgumentKind::params:
        return syntax.params_type + " " + a.name;
    case ArgumentKind::output_array:
        return "double* " + a.name;
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
        p.declarations.push_back("double* " + l.name);
    }
    if (with_work_array) {
        p.names.push_back("w");
        p.declarations.push_back("double* w");
    }
    return p;
}

// One statement, appended to `main` (factorisations, solves) or `part`.
void print_statement(const Statement& s, const Routine& routine, const BodyPlan& plan,
                     const Syntax& syntax, ExprPrinter& printer, std::string& main,
                     std::string& part, OperationCount& count) {
    switch (s.kind) {
    case Statement::Kind::define: {
        const int number = routine.exprs[static_cast<std::size_t>(s.expr)].temporary;
        const bool in_work_array = s.part >= 0 && plan.slot[static_cast<std::size_t>(number)] >= 0;
        part += fmt::format("    {}{} = {};\n", in_work_array ? "" : "const double ",
                            printer.temporary(number), printer.definition(s.expr));
        break;
    }
    case Statement::Kind::assign:
        part += fmt::format("    {}[{}] = {};\n", s.assignment->array, s.assignment->index,
                            printer.reference(s.expr));
        break;
    case Statement::Kind::factor:
        main += fmt::format("    {}ldlt_factor({}, {});\n", syntax.helper_prefix, s.step->matrix,
                            s.step->n);
        count += ldlt_factor_count(s.step->n);
        break;
    case Statement::Kind::solve:
        main +=
            fmt::format("    {}ldlt_solve({}, {}, {}, {});\n", syntax.helper_prefix, s.step->matrix,
                        s.step->n, array_at(s.step->target, s.step->offset), s.step->columns);
        count += ldlt_solve_count(s.step->n, s.step->columns);
        break;
    }
}

} // namespace

BodyText body_text(const Routine& routine, const ModelInfo& model, const Syntax& syntax,
                   const std::vector<std::string>& signature, int max_statements) {
    check_signature(routine, signature);
    const BodyPlan plan = plan_body(routine, max_statements);
    const bool cut = plan.part_count > 0;
    ExprPrinter printer(routine, model, syntax);
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
        main += fmt::format("    double {}[{}];\n", l.name, std::max(l.size, 1));
    if (plan.slot_count > 0) main += fmt::format("    double w[{}];\n", plan.slot_count);

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
        print_statement(s, routine, plan, syntax, printer, main, s.part >= 0 ? body.helpers : main,
                        body.count);
    }
    if (open_part >= 0) body.helpers += "}\n\n";
    body.count += printer.count();
    return body;
}

bool uses_solver(const Module& module) {
    for (const Routine& r : module.routines)
        for (const Step& s : r.steps)
            if (s.kind != StepKind::evaluate) return true;
    return false;
}

std::string solver_helpers_text(const Syntax& syntax, const std::string& linkage) {
    // Mirrors ldlt_factor_count and ldlt_solve_count in printer.cpp.
    return fmt::format(
        R"(// In-place LDL^T factorisation of the symmetric positive definite n x n matrix A
// (row-major; only the lower triangle is read): on return the strict lower
// triangle holds L (unit diagonal) and the diagonal holds D. No pivoting and no
// square roots: a mass matrix is positive definite.
{0}void {1}ldlt_factor(double* A, int n) {{
    for (int j = 0; j < n; ++j) {{
        double d = A[j * n + j];
        for (int k = 0; k < j; ++k) d -= A[j * n + k] * A[j * n + k] * A[k * n + k];
        A[j * n + j] = d;
        for (int i = j + 1; i < n; ++i) {{
            double s = A[i * n + j];
            for (int k = 0; k < j; ++k) s -= A[i * n + k] * A[j * n + k] * A[k * n + k];
            A[i * n + j] = s / d;
        }}
    }}
}}

// Solves (L D L^T) X = B in place for the n x m row-major block B.
{0}void {1}ldlt_solve(const double* LD, int n, double* B, int m) {{
    for (int c = 0; c < m; ++c) {{
        for (int i = 0; i < n; ++i) {{
            double s = B[i * m + c];
            for (int k = 0; k < i; ++k) s -= LD[i * n + k] * B[k * m + c];
            B[i * m + c] = s;
        }}
        for (int i = 0; i < n; ++i) B[i * m + c] /= LD[i * n + i];
        for (int i = n - 1; i >= 0; --i) {{
            double s = B[i * m + c];
            for (int k = i + 1; k < n; ++k) s -= LD[k * n + i] * B[k * m + c];
            B[i * m + c] = s;
        }}
    }}
}}
)",
        linkage, syntax.helper_prefix);
}

} // namespace yamsc::codegen
