// dump(Module): the module as text, for `yamsc --dump=module` and for tests.
#include "codegen/ldlt_text.hpp"
#include "codegen/module.hpp"
#include "codegen/printer.hpp"
#include "codegen/syntax.hpp"
#include "codegen/text.hpp"

#include <fmt/format.h>

namespace yamsc::codegen {
namespace {

std::string names_of(const std::vector<NamedDoc>& items) {
    if (items.empty()) return "(none)";
    std::string out;
    for (const NamedDoc& d : items) out += (out.empty() ? "" : ", ") + d.name;
    return out;
}

void dump_routine(std::string& out, const Routine& r, const Module& module) {
    const ModelInfo& model = module.model;
    std::string args, unused;
    for (const Argument& a : r.arguments) {
        args += (args.empty() ? "" : ", ") + a.name;
        if (!a.used) unused += (unused.empty() ? "" : ", ") + a.name;
    }
    out += fmt::format("\nroutine {}{}({})  # {}\n", r.internal ? "(internal) " : "", r.name, args,
                       r.summary);
    if (!unused.empty()) out += fmt::format("  unused: {}\n", unused);
    for (const LocalArray& l : r.locals) out += fmt::format("  local {}[{}]\n", l.name, l.size);
    const Syntax syntax = neutral_syntax();
    ExprPrinter printer(r, model, syntax);
    OperationCount solver;
    for (const Step& s : r.steps) {
        switch (s.kind) {
        case StepKind::evaluate:
            out += "  evaluate\n";
            for (int t : s.temporaries)
                out +=
                    fmt::format("    {} = {}\n", ExprPrinter::temporary_name(r.exprs[t].temporary),
                                printer.definition(t));
            for (const Assignment& a : s.assignments)
                out +=
                    fmt::format("    {}[{}] = {}\n", a.array, a.index, printer.reference(a.expr));
            break;
        case StepKind::factor:
            out += fmt::format("  factor {} = L D L^T  (n = {})\n", s.matrix, s.n);
            solver += solver_step_count(module.mass_ldlt, s);
            break;
        case StepKind::solve:
            out += fmt::format("  solve {} X = {}[{}..]  (n = {}, {} columns)\n", s.matrix,
                               s.target, s.offset, s.n, s.columns);
            solver += solver_step_count(module.mass_ldlt, s);
            break;
        case StepKind::call: {
            std::string args;
            for (const std::string& a : s.call.arguments) args += (args.empty() ? "" : ", ") + a;
            out += fmt::format("  call {}({})\n", s.call.callee, args);
            break;
        }
        case StepKind::sweep: {
            const Sweep& w = s.sweep;
            out +=
                fmt::format("  sweep k < {}: {}[{} + i*{} + k] = {} * {}(.., e_({} + k), ..)[{} + "
                            "i], i < {}\n",
                            w.count, w.target, w.offset, w.stride, format_number(w.scale), w.callee,
                            w.first, w.result_first, w.rows);
            break;
        }
        }
    }
    OperationCount total = printer.count();
    total += solver;
    out += fmt::format("  operations: {} adds, {} muls, {} divs, {} calls; {} temporaries\n",
                       total.adds, total.muls, total.divs, total.calls, r.temporary_count);
}

} // namespace

std::string dump(const Module& module) {
    const ModelInfo& m = module.model;
    std::string out = fmt::format("module {} {}\n", m.name, comment_quote(m.title));
    out += fmt::format("  source {} digest {}\n", comment_quote(m.source_path),
                       comment_quote(m.source_digest));
    out += fmt::format("  options: max_multiplied_power {}, max_inline_depth {}\n",
                       module.options.max_multiplied_power, module.options.max_inline_depth);
    out += fmt::format("  dofs: {}\n  inputs: {}\n", names_of(m.dofs), names_of(m.inputs));
    std::string params;
    for (const ParamInfo& p : m.params)
        params += (params.empty() ? "" : ", ") + p.name + " = " +
                  (p.default_value ? format_number(*p.default_value) : std::string("(unset)"));
    out += fmt::format("  params: {}\n", params.empty() ? "(none)" : params);
    out += fmt::format("  outputs: {}\n", names_of(m.outputs));
    out += fmt::format("  mass_matrix short form: {}\n",
                       module.mass_matrix_short_form ? "yes (M depends on q and p only)" : "no");
    const LdltPlan& plan = module.mass_ldlt;
    if (plan.n > 0) {
        std::string order;
        for (int a : plan.order) order += (order.empty() ? "" : " ") + std::to_string(a);
        out += fmt::format("  mass LDL^T: {}, order {}; {} structural zeros, {} fill-in, {} "
                           "updates\n",
                           plan.straight_line ? "straight-line" : "loops", order,
                           plan.structural_zeros, plan.fill_in, plan.updates);
    }
    for (const Routine& r : module.routines) dump_routine(out, r, module);
    return out;
}

} // namespace yamsc::codegen
