#include "codegen/ldlt_text.hpp"

#include "codegen/ready_sum.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>

namespace yamsc::codegen {
namespace {

std::string array_at(const std::string& array, int offset) {
    return offset == 0 ? array : fmt::format("{} + {}", array, offset);
}

/// The straight-line code's names and indices, by permuted row and column.
/// Locals are named by the original rows: l<a>_<b> is L's entry in the row of
/// q<a> and the column of q<b>, w<a>_<b> the same entry before its scaling by
/// r<b> = 1/D(b): with W(i, j) = L(i, j) D(j) the update of L(i, j) by
/// column k is the single product L(i, k) W(j, k).
class Names {
public:
    explicit Names(const LdltPlan& plan) : plan_(plan) {}

    int original(int k) const { return plan_.order[static_cast<std::size_t>(k)]; }
    /// Where the permuted entry (i, j) lives in the row-major n x n array: in
    /// M's lower triangle.
    int index(int i, int j) const {
        const int a = std::max(original(i), original(j)), b = std::min(original(i), original(j));
        return a * plan_.n + b;
    }
    std::string entry(const char* kind, int i, int j) const {
        return fmt::format("{}{}_{}", kind, original(i), original(j));
    }
    std::string l(int i, int j) const { return entry("l", i, j); }
    std::string w(int i, int j) const { return entry("w", i, j); }
    std::string d(int j) const { return fmt::format("d{}", original(j)); }
    std::string r(int j) const { return fmt::format("r{}", original(j)); }
    /// b[row * m]: the row of the column being solved.
    std::string b(int i) const {
        const int a = original(i);
        return a == 0 ? "b[0]" : a == 1 ? "b[m]" : fmt::format("b[{} * m]", a);
    }

private:
    const LdltPlan& plan_;
};

/// The nonzero columns k < j of row i of L, and of rows i and j both.
struct Rows {
    std::vector<std::vector<int>> of; // by permuted row, ascending

    explicit Rows(const LdltPlan& plan) : of(static_cast<std::size_t>(plan.n)) {
        for (int k = 0; k < plan.n; ++k)
            for (int i : plan.below[static_cast<std::size_t>(k)])
                of[static_cast<std::size_t>(i)].push_back(k);
    }
    std::vector<int> common(int i, int j) const {
        std::vector<int> out;
        const std::vector<int>&a = of[static_cast<std::size_t>(i)],
              &b = of[static_cast<std::size_t>(j)];
        std::size_t x = 0, y = 0;
        while (x < a.size() && y < b.size()) {
            if (a[x] == b[y]) {
                out.push_back(a[x]);
                ++x;
                ++y;
            } else if (a[x] < b[y]) {
                ++x;
            } else {
                ++y;
            }
        }
        return out;
    }
};

/// `text` as comment lines of at most 80 columns.
std::string comment(const std::string& text) {
    std::string out, line = "//";
    std::size_t at = 0;
    while (at < text.size()) {
        const std::size_t end = std::min(text.find(' ', at), text.size());
        const std::string word = text.substr(at, end - at);
        if (line.size() + 1 + word.size() > 80) {
            out += line + "\n";
            line = "//";
        }
        line += " " + word;
        at = end + 1;
    }
    return out + line + "\n";
}

std::string factor_comment(const LdltPlan& plan) {
    std::string order;
    for (int a : plan.order) order += fmt::format(" q{}", a);
    std::string zeros =
        plan.structural_zeros == 0 ? std::string("M has no structural zeros below the diagonal.")
        : plan.fill_in == 0
            ? fmt::format("The {} entries below the diagonal that are zero in every state are "
                          "skipped (no fill-in).",
                          plan.structural_zeros)
            : fmt::format("The {} entries below the diagonal that are zero in every state are "
                          "not read; {} of them fill in, the others are skipped.",
                          plan.structural_zeros, plan.fill_in);
    return comment(fmt::format(
        "A = L D L^T in place for this model's {0} x {0} mass matrix (row-major, lower "
        "triangle read), rows and columns eliminated in the order{1} (minimum degree). {2} On "
        "return L (unit diagonal) of the permuted matrix is where M's lower triangle was and the "
        "diagonal holds 1/D.",
        plan.n, order, zeros));
}

// Column by column (left-looking): D(j) and 1/D(j), then the column's
// entries of L, each with the ready time of its value (ready_sum.hpp).
std::string factor_text(const LdltPlan& plan, const Syntax& syntax, const std::string& linkage) {
    const Names name(plan);
    const Rows rows(plan);
    const std::string& real = syntax.real_type;
    std::string out = factor_comment(plan);
    out +=
        fmt::format("{}void {}mass_ldlt_factor({}* A) {{\n", linkage, syntax.helper_prefix, real);
    const std::string one = format_literal(1.0, syntax);
    std::map<std::string, int> ready; // of the locals, by name
    auto timed = [&](const std::string& local) { return Timed{local, ready.at(local), false}; };
    auto define = [&](const std::string& local, const Timed& value) {
        out += fmt::format("    const {} {} = {};\n", real, local, value.text);
        ready[local] = value.ready;
    };
    for (int j = 0; j < plan.n; ++j) {
        std::vector<Timed> terms;
        for (int k : rows.of[static_cast<std::size_t>(j)])
            terms.push_back(product(timed(name.l(j, k)), timed(name.w(j, k))));
        define(name.d(j), difference({fmt::format("A[{}]", name.index(j, j))}, terms));
        define(name.r(j), {one + " / " + name.d(j), ready.at(name.d(j)) + div_latency});
        out += fmt::format("    A[{}] = {};\n", name.index(j, j), name.r(j));
        for (int i : plan.below[static_cast<std::size_t>(j)]) {
            terms.clear();
            for (int k : rows.common(i, j))
                terms.push_back(product(timed(name.l(i, k)), timed(name.w(j, k))));
            const bool in_m = plan.nonzero_in_m(i, j);
            define(name.w(i, j),
                   difference({in_m ? fmt::format("A[{}]", name.index(i, j)) : ""}, terms));
            define(name.l(i, j), product(timed(name.w(i, j)), timed(name.r(j))));
            out += fmt::format("    A[{}] = {};\n", name.index(i, j), name.l(i, j));
        }
    }
    return out + "}\n";
}

// Per column of B: forward substitution with L, scaling by 1/D, backward
// substitution with L^T, the column's values loaded first and stored last.
std::string solve_text(const LdltPlan& plan, const Syntax& syntax, const std::string& linkage) {
    const Names name(plan);
    const Rows rows(plan);
    const std::string& real = syntax.real_type;
    std::string out =
        fmt::format("// Solves (L D L^T) X = B in place for the {} x m row-major block B, with LD\n"
                    "// from {}mass_ldlt_factor.\n",
                    plan.n, syntax.helper_prefix);
    out += fmt::format("{}void {}mass_ldlt_solve(const {}* LD, {}* B, int m) {{\n", linkage,
                       syntax.helper_prefix, real, real);
    out += "    for (int c = 0; c < m; ++c) {\n";
    out += fmt::format("        {}* b = B + c;\n", real);
    std::map<std::string, int> ready;
    auto timed = [&](const std::string& local) { return Timed{local, ready.at(local), false}; };
    auto define = [&](const std::string& local, const Timed& value) {
        out += fmt::format("        const {} {} = {};\n", real, local, value.text);
        ready[local] = value.ready;
    };
    auto ld = [&](int i, int j) { return Timed{fmt::format("LD[{}]", name.index(i, j))}; };
    auto y = [&](int i) { return fmt::format("y{}", name.original(i)); };
    auto x = [&](int i) { return fmt::format("x{}", name.original(i)); };
    for (int i = 0; i < plan.n; ++i) {
        std::vector<Timed> terms;
        for (int k : rows.of[static_cast<std::size_t>(i)])
            terms.push_back(product(ld(i, k), timed(y(k))));
        define(y(i), difference({name.b(i)}, terms));
    }
    for (int i = plan.n - 1; i >= 0; --i) {
        std::vector<Timed> terms;
        for (int k : plan.below[static_cast<std::size_t>(i)])
            terms.push_back(product(ld(k, i), timed(x(k))));
        define(x(i), difference(product(timed(y(i)), ld(i, i)), terms));
    }
    for (int i = 0; i < plan.n; ++i) out += fmt::format("        {} = {};\n", name.b(i), x(i));
    return out + "    }\n}\n";
}

} // namespace

bool straight_line_step(const LdltPlan& plan, const Step& step) {
    // Only M has the model's pattern (the constrained rhs factors another matrix).
    return plan.straight_line && step.n == plan.n && step.matrix == "M";
}

std::string solver_statement(const LdltPlan& plan, const Step& step, const Syntax& syntax) {
    const std::string& prefix = syntax.helper_prefix;
    const bool straight = straight_line_step(plan, step);
    if (step.kind == StepKind::factor)
        return straight ? fmt::format("    {}mass_ldlt_factor({});\n", prefix, step.matrix)
                        : fmt::format("    {}ldlt_factor({}, {});\n", prefix, step.matrix, step.n);
    const std::string target = array_at(step.target, step.offset);
    return straight ? fmt::format("    {}mass_ldlt_solve({}, {}, {});\n", prefix, step.matrix,
                                  target, step.columns)
                    : fmt::format("    {}ldlt_solve({}, {}, {}, {});\n", prefix, step.matrix,
                                  step.n, target, step.columns);
}

OperationCount solver_step_count(const LdltPlan& plan, const Step& step) {
    const bool straight = straight_line_step(plan, step);
    if (step.kind == StepKind::factor)
        return straight ? straight_factor_count(plan) : ldlt_factor_count(step.n);
    return straight ? straight_solve_count(plan, step.columns)
                    : ldlt_solve_count(step.n, step.columns);
}

std::string straight_ldlt_text(const LdltPlan& plan, const Syntax& syntax,
                               const std::string& linkage) {
    return factor_text(plan, syntax, linkage) + "\n" + solve_text(plan, syntax, linkage);
}

OperationCount straight_factor_count(const LdltPlan& plan) {
    const Rows rows(plan);
    OperationCount c;
    for (int j = 0; j < plan.n; ++j) {
        const long terms = static_cast<long>(rows.of[static_cast<std::size_t>(j)].size());
        c.muls += terms;
        c.adds += terms;
        c.divs += 1; // 1/D(j)
        for (int i : plan.below[static_cast<std::size_t>(j)]) {
            const long common = static_cast<long>(rows.common(i, j).size());
            c.muls += common + 1; // the updates, then the scaling by 1/D(j)
            c.adds += plan.nonzero_in_m(i, j) ? common : common - 1;
        }
    }
    return c;
}

OperationCount straight_solve_count(const LdltPlan& plan, int columns) {
    long entries = 0;
    for (const std::vector<int>& column : plan.below) entries += static_cast<long>(column.size());
    OperationCount c;
    c.adds = static_cast<long>(columns) * 2 * entries;            // forward, then backward
    c.muls = static_cast<long>(columns) * (2 * entries + plan.n); // and the scaling by 1/D
    return c;
}

} // namespace yamsc::codegen
