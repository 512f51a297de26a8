#include "codegen/body_plan.hpp"

#include <algorithm>

namespace yamsc::codegen {
namespace {

std::vector<Statement> statements_of(const Routine& r) {
    std::vector<Statement> out;
    for (const Step& step : r.steps) {
        switch (step.kind) {
        case StepKind::evaluate:
            for (int t : step.temporaries)
                out.push_back({Statement::Kind::define, t, nullptr, nullptr});
            for (const Assignment& a : step.assignments)
                out.push_back({Statement::Kind::assign, a.expr, &a, nullptr});
            break;
        case StepKind::factor:
            out.push_back({Statement::Kind::factor, 0, nullptr, &step});
            break;
        case StepKind::solve:
            out.push_back({Statement::Kind::solve, 0, nullptr, &step});
            break;
        case StepKind::sweep:
            out.push_back({Statement::Kind::sweep, 0, nullptr, &step});
            break;
        case StepKind::call:
            out.push_back({Statement::Kind::call, 0, nullptr, &step});
            break;
        }
    }
    return out;
}

// What the printed text of `root` reads: leaves and the temporaries it names.
// Walks the single-use (inline) part of the DAG only, so each node is visited
// by exactly one statement.
void reads(const Routine& r, int root, bool root_is_definition, std::vector<int>& temporaries,
           std::vector<std::string>& names) {
    std::vector<int> stack{root};
    bool first = true;
    while (!stack.empty()) {
        const Expr& e = r.exprs[static_cast<std::size_t>(stack.back())];
        stack.pop_back();
        if (e.temporary >= 0 && !(first && root_is_definition)) {
            temporaries.push_back(e.temporary);
        } else if (e.kind == ExprKind::load) {
            names.push_back(e.array);
        } else if (e.kind == ExprKind::param) {
            names.push_back("p");
        } else if (e.kind == ExprKind::time) {
            names.push_back("t");
        } else {
            for (const ExprOperand& op : e.operands) stack.push_back(op.expr);
        }
        first = false;
    }
}

bool is_evaluation(const Statement& s) {
    return s.kind == Statement::Kind::define || s.kind == Statement::Kind::assign;
}

} // namespace

BodyPlan plan_body(const Routine& routine, int max_statements) {
    BodyPlan plan;
    plan.statements = statements_of(routine);
    plan.slot.assign(static_cast<std::size_t>(routine.temporary_count), -1);
    const auto evaluations =
        std::count_if(plan.statements.begin(), plan.statements.end(), is_evaluation);
    if (max_statements <= 0 || evaluations <= max_statements) return plan;

    // Parts: runs of evaluations, cut at the limit and at every factor or solve.
    int size = 0;
    bool open = false;
    for (Statement& s : plan.statements) {
        if (!is_evaluation(s) || (open && size == max_statements)) {
            open = false;
            if (!is_evaluation(s)) continue;
        }
        if (!open) {
            ++plan.part_count;
            open = true;
            size = 0;
        }
        s.part = plan.part_count - 1;
        ++size;
    }

    // Where each temporary is defined and last read; what each part names.
    const std::size_t temps = plan.slot.size();
    std::vector<int> defined_in(temps, -1), last_read_in(temps, -1);
    plan.names_used.assign(static_cast<std::size_t>(plan.part_count), {});
    for (const Statement& s : plan.statements) {
        if (s.part < 0) continue;
        std::vector<int> read;
        std::vector<std::string>& names = plan.names_used[static_cast<std::size_t>(s.part)];
        const bool definition = s.kind == Statement::Kind::define;
        reads(routine, s.expr, definition, read, names);
        if (definition)
            defined_in[static_cast<std::size_t>(routine.exprs[s.expr].temporary)] = s.part;
        else
            names.push_back(s.assignment->array);
        for (int t : read) last_read_in[static_cast<std::size_t>(t)] = s.part;
    }
    // Slots for the temporaries read outside their part, reused once dead.
    std::vector<int> free_slots;
    std::vector<std::vector<int>> dying(static_cast<std::size_t>(plan.part_count));
    for (int part = 0; part < plan.part_count; ++part) {
        for (int t : dying[static_cast<std::size_t>(part)]) free_slots.push_back(plan.slot[t]);
        std::sort(free_slots.begin(), free_slots.end(), std::greater<int>());
        for (std::size_t t = 0; t < temps; ++t) {
            if (defined_in[t] != part || last_read_in[t] <= part) continue;
            int slot = plan.slot_count;
            if (!free_slots.empty()) {
                slot = free_slots.back();
                free_slots.pop_back();
            } else {
                ++plan.slot_count;
            }
            plan.slot[t] = slot;
            // Free after its last reader: from the part that follows it.
            if (last_read_in[t] + 1 < plan.part_count)
                dying[static_cast<std::size_t>(last_read_in[t] + 1)].push_back(static_cast<int>(t));
        }
    }
    // A part that defines or reads a slot names w.
    for (const Statement& s : plan.statements) {
        if (s.part < 0) continue;
        std::vector<int> read;
        std::vector<std::string> ignored;
        const bool definition = s.kind == Statement::Kind::define;
        reads(routine, s.expr, definition, read, ignored);
        if (definition) read.push_back(routine.exprs[s.expr].temporary);
        for (int t : read)
            if (plan.slot[static_cast<std::size_t>(t)] >= 0)
                plan.names_used[static_cast<std::size_t>(s.part)].push_back("w");
    }
    for (std::vector<std::string>& names : plan.names_used) {
        std::sort(names.begin(), names.end());
        names.erase(std::unique(names.begin(), names.end()), names.end());
    }
    return plan;
}

} // namespace yamsc::codegen
