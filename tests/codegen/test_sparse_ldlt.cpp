// The symbolic LDL^T of the mass matrix (codegen/sparse_ldlt.hpp): the
// pattern read from the IR, the minimum-degree order and its fill-in, the
// threshold of straight-line code, how its sums are grouped (ready_sum.hpp),
// and that the operation counts are those of the printed text. The numbers of
// the printed code are checked in tests/embedded/sparse_ldlt_test.cpp.
#include "codegen/emit.hpp"
#include "codegen/ldlt_text.hpp"
#include "codegen/ready_sum.hpp"
#include "codegen/sparse_ldlt.hpp"
#include "diag/diagnostics.hpp"
#include "fixtures.hpp"

#include <doctest/doctest.h>

using namespace yamsc::codegen;
using codegen_test::occurrences;

namespace {

LowerPattern pattern_of(int n, bool (*coupled)(int, int)) {
    LowerPattern p = dense_pattern(n);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < i; ++j) p[i][j] = coupled(i, j);
    return p;
}

/// The printed text without its comment lines.
std::string code_of(const std::string& text) {
    std::string out;
    std::size_t pos = 0;
    while (pos < text.size()) {
        const std::size_t end = std::min(text.find('\n', pos), text.size());
        const std::string line = text.substr(pos, end - pos);
        if (line.rfind("//", 0) != 0) out += line + "\n";
        pos = end + 1;
    }
    return out;
}

} // namespace

TEST_CASE("sparse LDL^T: a dense pattern keeps its order and has (n^3 - n)/6 updates") {
    const LdltPlan p = plan_ldlt(dense_pattern(6));
    CHECK(p.order == std::vector<int>{0, 1, 2, 3, 4, 5});
    CHECK(p.structural_zeros == 0);
    CHECK(p.fill_in == 0);
    CHECK(p.updates == (6 * 6 * 6 - 6) / 6);
    CHECK(p.below[0] == std::vector<int>{1, 2, 3, 4, 5});
    CHECK(p.below[5].empty());
    // Straight-line up to every dense M the unrolled form derives (24 DOFs).
    CHECK(plan_ldlt(dense_pattern(24)).straight_line);
    CHECK_FALSE(plan_ldlt(dense_pattern(25)).straight_line);
    CHECK_FALSE(plan_ldlt(dense_pattern(0)).straight_line);
}

TEST_CASE("sparse LDL^T: minimum degree eliminates the leaves first, without fill-in") {
    // An arrow: q0 coupled with all, q3 with q4.
    const LdltPlan arrow =
        plan_ldlt(pattern_of(7, [](int i, int j) { return j == 0 || (i == 4 && j == 3); }));
    CHECK(arrow.order == std::vector<int>{1, 2, 5, 6, 3, 4, 0});
    CHECK(arrow.fill_in == 0);
    CHECK(arrow.structural_zeros == 21 - 7);
    CHECK(arrow.updates == 8); // D(q0) from 6 columns; D(q4) and W(q0, q4) from q3's
    // The turbine: a hub of 7 (tower, yaw, azimuth, drivetrain) coupled with
    // three blades of 3 modes that do not couple with each other. Ties go to
    // the smaller original pattern, so all blades come before the hub.
    const LdltPlan turbine =
        plan_ldlt(pattern_of(16, [](int i, int j) { return j < 7 || (i - 7) / 3 == (j - 7) / 3; }));
    CHECK(turbine.order == std::vector<int>{7, 8, 9, 10, 11, 12, 13, 14, 15, 0, 1, 2, 3, 4, 5, 6});
    CHECK(turbine.structural_zeros == 27);
    CHECK(turbine.fill_in == 0);
    CHECK(turbine.updates == 383);
    CHECK(turbine.nonzero(1, 0));       // q8 with q7
    CHECK_FALSE(turbine.nonzero(3, 0)); // q10 with q7: blade 2 with blade 1
    CHECK(turbine.nonzero(15, 0));      // q6 with q7
}

TEST_CASE("sparse LDL^T: a cycle fills in, and the fill is in L's pattern") {
    const LdltPlan ring =
        plan_ldlt(pattern_of(6, [](int i, int j) { return i - j == 1 || (i == 5 && j == 0); }));
    CHECK(ring.structural_zeros == 9);
    CHECK(ring.fill_in == 3); // a cycle of n fills in n - 3 chords
    int entries = 0, fill = 0;
    for (int j = 0; j < 6; ++j)
        for (int i : ring.below[static_cast<std::size_t>(j)]) {
            ++entries;
            fill += ring.nonzero_in_m(i, j) ? 0 : 1;
        }
    CHECK(entries == 6 + 3);
    CHECK(fill == 3);
    CHECK_THROWS_AS(plan_ldlt({{true}, {true}}), yamsc::diag::InternalError);
}

TEST_CASE("sparse LDL^T: the pattern of M is that of its IR nodes") {
    yamsc::ir::Graph g;
    const yamsc::ir::NodeId zero = g.number(0.0), two = g.number(2.0);
    const LowerPattern p =
        mass_pattern(g, {{two, zero, zero}, {zero, two, zero}, {two, zero, two}});
    CHECK(p == LowerPattern{{true}, {false, true}, {true, false, true}});
}

TEST_CASE("sums are grouped by when their terms are ready") {
    // In order of readiness: the chain C writes left to right.
    CHECK(difference({"a", 0}, {{"t1", 4}, {"t2", 8}}).text == "a - t1 - t2");
    // Terms ready together, before the first term: summed first.
    const Timed late = difference({"a", 12}, {{"t1", 4}, {"t2", 4}, {"t3", 4}});
    CHECK(late.text == "a - (t1 + t2 + t3)");
    CHECK(late.ready == 16);
    // No first term (fill-in): the negated sum.
    CHECK(difference({""}, {{"t1", 4}, {"t2", 4}}).text == "-(t1 + t2)");
    CHECK(difference({""}, {{"t1 * t2", 4}}).text == "-t1 * t2");
    CHECK(difference({"a", 3}, {}).text == "a");
    const Timed p = product({"l", 2}, {"w", 9});
    CHECK(p.text == "l * w");
    CHECK(p.ready == 9 + mul_latency);
}

TEST_CASE("sparse LDL^T: the operation counts are those of the printed text") {
    for (const LowerPattern& pattern :
         {dense_pattern(5),
          pattern_of(6, [](int i, int j) { return i - j == 1 || (i == 5 && j == 0); }),
          pattern_of(10, [](int i, int j) { return j < 4 || (i - 4) / 3 == (j - 4) / 3; })}) {
        const LdltPlan plan = plan_ldlt(pattern);
        const std::string text = code_of(straight_ldlt_text(plan, cpp_syntax(), ""));
        const std::size_t solve_at = text.find("void mass_ldlt_solve");
        REQUIRE(solve_at != std::string::npos);
        const std::string factor = text.substr(0, solve_at), solve = text.substr(solve_at);
        const OperationCount f = straight_factor_count(plan);
        CHECK(occurrences(factor, " * ") == static_cast<std::size_t>(f.muls));
        CHECK(occurrences(factor, " - ") + occurrences(factor, " + ") ==
              static_cast<std::size_t>(f.adds));
        CHECK(occurrences(factor, " / ") == static_cast<std::size_t>(f.divs));
        const OperationCount s = straight_solve_count(plan, 1);
        // The solve's own `c + 1` loop and `B + c`, and `k * m` indices, are not arithmetic.
        CHECK(occurrences(solve, " * ") - occurrences(solve, " * m]") ==
              static_cast<std::size_t>(s.muls));
        CHECK(occurrences(solve, " - ") + occurrences(solve, " + ") - 1 ==
              static_cast<std::size_t>(s.adds));
        CHECK(s.divs == 0);
    }
}

TEST_CASE("sparse LDL^T: generated code calls the straight-line functions for M") {
    const Module m = codegen_test::build_module(codegen_test::double_pendulum());
    CHECK(m.mass_ldlt.n == 2);
    CHECK(m.mass_ldlt.straight_line);
    const EmittedFiles cpp = emit_cpp(m, {});
    CHECK(occurrences(cpp.source, "    mass_ldlt_factor(M);\n") >= 2); // rhs, rhs_jacobian, ...
    CHECK(cpp.source.find("    mass_ldlt_solve(M, xdot + 2, 1);\n") != std::string::npos);
    CHECK(cpp.source.find("void mass_ldlt_factor(double* A) {") != std::string::npos);
    CHECK(cpp.source.find("ldlt_factor(M, 2)") == std::string::npos);
    CHECK(cpp.source.find("void ldlt_factor(") == std::string::npos); // no generic loops left
    EmitOptions c_options;
    c_options.real = EmitOptions::Real::single_precision;
    const EmittedFiles c = emit_c(m, c_options);
    CHECK(c.source.find("static void double_pendulum_mass_ldlt_factor(float* A) {") !=
          std::string::npos);
    CHECK(c.source.find("1.0f / d0") != std::string::npos);
    // A module without a plan (or a matrix of another size) keeps the loops.
    Module loops = m;
    loops.mass_ldlt = LdltPlan{};
    const EmittedFiles generic = emit_cpp(loops, {});
    CHECK(generic.source.find("    ldlt_factor(M, 2);\n") != std::string::npos);
    CHECK(generic.source.find("mass_ldlt") == std::string::npos);
}
