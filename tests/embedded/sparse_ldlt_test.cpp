// The straight-line LDL^T that generated code calls for a model's mass matrix
// (codegen/ldlt_text.hpp), printed for a few patterns and compiled as strict
// C99 (double and float) and C++17 into one program, whose numbers are checked
// against Eigen: the factor is an LDL^T of the permuted matrix (L where M's
// lower triangle was, 1/D on the diagonal), the solve of three columns matches
// Eigen's, and the entries that are zero in every state are neither read nor
// written (they hold a sentinel) unless they fill in.
#include "codegen/ldlt_text.hpp"
#include "codegen/sparse_ldlt.hpp"
#include "embedded/support.hpp"

#include <Eigen/Dense>
#include <doctest/doctest.h>

#include <cmath>
#include <fmt/format.h>
#include <sstream>

using namespace embedded_test;
using namespace yamsc::codegen;

namespace {

constexpr int columns = 3;
constexpr double sentinel = 12345.0; // in the structural zeros and the upper triangle

struct Case {
    std::string name;
    LowerPattern pattern;
};

LowerPattern pattern_of(int n, bool (*coupled)(int, int)) {
    LowerPattern p = dense_pattern(n);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < i; ++j) p[i][j] = coupled(i, j);
    return p;
}

// dense: every entry; arrow: q0 coupled with all, q3 with q4; blocks: a hub
// of four coupled with two blades of three that do not couple with each other
// (the turbine's structure); ring: q_i with q_(i-1) and q5 with q0, which
// fills in whatever the order.
std::vector<Case> cases() {
    return {{"dense", dense_pattern(5)},
            {"arrow", pattern_of(7, [](int i, int j) { return j == 0 || (i == 4 && j == 3); })},
            {"blocks",
             pattern_of(10, [](int i, int j) { return j < 4 || (i - 4) / 3 == (j - 4) / 3; })},
            {"ring", pattern_of(6, [](int i, int j) { return i - j == 1 || (i == 5 && j == 0); })}};
}

/// A symmetric positive definite matrix with `pattern`, its rows scaled by
/// 10^-1, 1, 10 in turn (as a model's masses and inertias differ).
Eigen::MatrixXd matrix_of(const LowerPattern& pattern) {
    const int n = static_cast<int>(pattern.size());
    Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n, n);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < i; ++j)
            if (pattern[i][j]) M(i, j) = M(j, i) = std::sin(1.0 + 7 * i + 3 * j);
    for (int i = 0; i < n; ++i) M(i, i) = 1.0 + M.row(i).cwiseAbs().sum();
    Eigen::VectorXd scale(n);
    for (int i = 0; i < n; ++i) scale(i) = std::pow(10.0, i % 3 - 1);
    return scale.asDiagonal() * M * scale.asDiagonal();
}

Eigen::MatrixXd rhs_of(int n) {
    Eigen::MatrixXd B(n, columns);
    for (int i = 0; i < n; ++i)
        for (int c = 0; c < columns; ++c) B(i, c) = std::cos(2.0 + i - 5.0 * c);
    return B;
}

std::string literals(const std::vector<double>& values, const Syntax& syntax) {
    std::string out;
    for (double v : values) out += (out.empty() ? "" : ", ") + format_literal(v, syntax);
    return out;
}

/// The program: each case's functions, its matrix as the generated routines
/// leave it (lower triangle; sentinels elsewhere) and B; main factors, solves
/// and prints A, then B.
std::string program(bool cxx, bool single) {
    std::string out = "#include <stdio.h>\n\n";
    std::string calls;
    for (const Case& c : cases()) {
        const int n = static_cast<int>(c.pattern.size());
        const LdltPlan plan = plan_ldlt(c.pattern);
        REQUIRE(plan.straight_line);
        Syntax syntax = c_syntax(c.name, single);
        if (cxx) syntax = cpp_syntax(), syntax.helper_prefix = c.name + "_";
        out += straight_ldlt_text(plan, syntax, "static ") + "\n";
        const Eigen::MatrixXd M = matrix_of(c.pattern);
        const Eigen::MatrixXd B = rhs_of(n);
        std::vector<double> a, b;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) a.push_back(j <= i && c.pattern[i][j] ? M(i, j) : sentinel);
        for (int i = 0; i < n; ++i)
            for (int k = 0; k < columns; ++k) b.push_back(B(i, k));
        const std::string real = single ? "float" : "double";
        out +=
            fmt::format("static {0} A_{1}[{2}] = {{{3}}};\nstatic {0} B_{1}[{4}] = {{{5}}};\n\n",
                        real, c.name, n * n, literals(a, syntax), n * columns, literals(b, syntax));
        calls +=
            fmt::format("    {0}_mass_ldlt_factor(A_{0});\n"
                        "    {0}_mass_ldlt_solve(A_{0}, B_{0}, {3});\n"
                        "    for (i = 0; i < {1}; ++i) printf(\"%.17g\\n\", (double)A_{0}[i]);\n"
                        "    for (i = 0; i < {2}; ++i) printf(\"%.17g\\n\", (double)B_{0}[i]);\n",
                        c.name, n * n, n * columns, columns);
    }
    return out + "int main(void) {\n    int i;\n" + calls + "    return 0;\n}\n";
}

std::vector<double> run_program(const std::string& compiler, const std::string& flags,
                                const std::string& name, const std::string& text) {
    const std::string dir = scratch_dir("sparse_ldlt_" + name);
    write_file(dir + "/ldlt.c", text);
    const std::string exe = dir + "/ldlt";
    const std::string command = compiler + " " + flags + " -Wall -Wextra -Werror -Wshadow " + dir +
                                "/ldlt.c -o " + exe + " > " + dir + "/cc.log 2>&1";
    REQUIRE_MESSAGE(run(command) == 0, command, "\n", read_file(dir + "/cc.log"));
    REQUIRE(run(exe + " > " + dir + "/out.txt") == 0);
    std::istringstream in(read_file(dir + "/out.txt"));
    std::vector<double> out;
    for (double v; in >> v;) out.push_back(v);
    return out;
}

void check(const std::vector<double>& printed, double tolerance) {
    std::size_t at = 0;
    for (const Case& c : cases()) {
        CAPTURE(c.name);
        const int n = static_cast<int>(c.pattern.size());
        const LdltPlan plan = plan_ldlt(c.pattern);
        const Eigen::MatrixXd M = matrix_of(c.pattern);
        REQUIRE(printed.size() >= at + static_cast<std::size_t>(n * n + n * columns));
        auto A = [&](int i, int j) { return printed[at + static_cast<std::size_t>(i * n + j)]; };
        // L and D of the permuted matrix, from where M's entries were.
        Eigen::MatrixXd L = Eigen::MatrixXd::Identity(n, n);
        Eigen::VectorXd D(n);
        Eigen::MatrixXd PMPt(n, n);
        for (int i = 0; i < n; ++i) {
            const int a = plan.order[static_cast<std::size_t>(i)];
            D(i) = 1.0 / A(a, a);
            for (int j = 0; j < n; ++j) {
                const int b = plan.order[static_cast<std::size_t>(j)];
                PMPt(i, j) = M(a, b);
                if (j < i && plan.nonzero(i, j)) L(i, j) = A(std::max(a, b), std::min(a, b));
            }
        }
        const Eigen::MatrixXd LDLt = L * D.asDiagonal() * L.transpose();
        CHECK((LDLt - PMPt).cwiseAbs().maxCoeff() <= tolerance * PMPt.cwiseAbs().maxCoeff());
        int untouched = 0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                if (j > i) CHECK(A(i, j) == sentinel);
                untouched += A(i, j) == sentinel;
            }
        // Sentinels stay in the upper triangle and in the zeros that do not fill in.
        CHECK(untouched == n * (n - 1) / 2 + plan.structural_zeros - plan.fill_in);
        at += static_cast<std::size_t>(n * n);
        const Eigen::MatrixXd X = M.ldlt().solve(rhs_of(n));
        for (int i = 0; i < n; ++i)
            for (int k = 0; k < columns; ++k)
                CHECK(printed[at + static_cast<std::size_t>(i * columns + k)] ==
                      doctest::Approx(X(i, k)).epsilon(tolerance).scale(X.cwiseAbs().maxCoeff()));
        at += static_cast<std::size_t>(n * columns);
    }
    CHECK(at == printed.size());
}

} // namespace

TEST_CASE("sparse LDL^T: the straight-line code as strict C99 factors and solves like Eigen") {
    check(run_program(YAMSC_C_COMPILER, "-std=c99 -pedantic -x c", "c99", program(false, false)),
          1e-13);
}

TEST_CASE("sparse LDL^T: the straight-line code in single precision (C99)") {
    check(run_program(YAMSC_C_COMPILER,
                      "-std=c99 -pedantic -Wdouble-promotion -Wfloat-conversion -x c", "c99_float",
                      program(false, true)),
          1e-5);
}

TEST_CASE("sparse LDL^T: the straight-line code as C++17 factors and solves like Eigen") {
    check(run_program(YAMSC_CXX_COMPILER, "-std=c++17 -pedantic -x c++", "cxx17",
                      program(true, false)),
          1e-13);
}
