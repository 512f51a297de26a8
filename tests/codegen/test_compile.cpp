// The emitted C++ and C compile at strict warning levels and compute what the
// equations say: every function against the independent evaluator, rhs against
// M^-1 F, rhs_jacobian against central finite differences of the generated rhs.
#include "compile_support.hpp"

#include <cmath>
#include <doctest/doctest.h>

using namespace codegen_test;

namespace {

Vector flat(const Dense& m) {
    Vector out;
    for (const Vector& row : m) out.insert(out.end(), row.begin(), row.end());
    return out;
}

void check_close(const Results& r, const std::string& key, const Vector& expected, double rel) {
    INFO(key);
    const auto it = r.find(key);
    REQUIRE(it != r.end());
    const Vector& got = it->second;
    REQUIRE(got.size() == expected.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
        INFO("entry " << i << ": got " << got[i] << ", expected " << expected[i]);
        CHECK(std::fabs(got[i] - expected[i]) <= rel * std::max(1.0, std::fabs(expected[i])));
    }
}

ModelUnderTest under_test(const Equations& eq, bool with_header, int max_statements = 200) {
    ModelUnderTest m;
    m.eq = &eq;
    m.module = build_module(eq);
    m.point = sample_point(eq);
    m.with_header = with_header;
    m.max_function_statements = max_statements;
    return m;
}

void check_model(const Results& r, const ModelUnderTest& m, bool cpp) {
    const std::string name = m.eq->model_name + " ";
    const Reference ref = reference(*m.eq, m.point);
    check_close(r, name + "M", flat(ref.M), 1e-12);
    if (m.module.mass_matrix_short_form) check_close(r, name + "M_short", flat(ref.M), 1e-12);
    check_close(r, name + "F", ref.F, 1e-12);
    check_close(r, name + "dF_dq", flat(ref.dF_dq), 1e-12);
    check_close(r, name + "dF_dqd", flat(ref.dF_dqd), 1e-12);
    check_close(r, name + "dF_du", flat(ref.dF_du), 1e-12);
    check_close(r, name + "y", ref.y, 1e-12);
    check_close(r, name + "xdot", ref.xdot, 1e-11);
    check_close(r, name + "J", flat(ref.J), 1e-10);
    // The generated rhs_jacobian against finite differences of the generated rhs.
    check_close(r, name + "J_fd", r.at(name + "J"), 1e-6);
    if (cpp) check_close(r, name + "xdot_model", ref.xdot, 1e-11);
}

void check_defaults(const Results& r) {
    // pendulum: m has no default (NaN), l = 0.75, g = 9.807, c = 0.1.
    const Vector& d = r.at("pendulum defaults");
    REQUIRE(d.size() == 4);
    CHECK(std::isnan(d[0]));
    CHECK(d[1] == 0.75);
    CHECK(d[2] == 9.807);
    CHECK(d[3] == 0.1);
}

} // namespace

TEST_CASE("generated C++ compiles with -Wall -Wextra -Werror and computes the equations") {
    const Equations pend = pendulum(), dp = double_pendulum(), pres = prescribed(),
                    deep = deep_chain(30), empty = bare();
    const std::vector<ModelUnderTest> models{under_test(pend, true), under_test(dp, true),
                                             under_test(pres, false), under_test(deep, false),
                                             under_test(empty, true)};
    const RunResult run = compile_and_run(Language::cpp, models, "cpp");
    INFO(run.log);
    REQUIRE(run.ok);
    for (const ModelUnderTest& m : models) check_model(run.values, m, true);
    check_defaults(run.values);
}

TEST_CASE("generated C compiles with -std=c99 -pedantic -Wall -Wextra -Werror and computes the "
          "equations") {
    const Equations pend = pendulum(), dp = double_pendulum(), pres = prescribed(),
                    deep = deep_chain(30), empty = bare();
    const std::vector<ModelUnderTest> models{under_test(pend, true), under_test(dp, false),
                                             under_test(pres, true), under_test(deep, true),
                                             under_test(empty, false)};
    const RunResult run = compile_and_run(Language::c, models, "c");
    INFO(run.log);
    REQUIRE(run.ok);
    for (const ModelUnderTest& m : models) check_model(run.values, m, false);
    check_defaults(run.values);
}

// Functions cut into parts of at most 3 statements: the work array's slots,
// their reuse and the parts' unused parameters all compile and compute alike.
TEST_CASE("functions cut into parts compile cleanly and compute the same numbers") {
    const Equations dp = double_pendulum(), pres = prescribed(), deep = deep_chain(30);
    for (const Language lang : {Language::cpp, Language::c}) {
        const std::vector<ModelUnderTest> models{
            under_test(dp, true, 3), under_test(pres, false, 3), under_test(deep, true, 5)};
        const RunResult run =
            compile_and_run(lang, models, lang == Language::cpp ? "cpp_parts" : "c_parts");
        INFO(run.log);
        REQUIRE(run.ok);
        const std::string source = read_file(run.files.front());
        CHECK(source.find("rhs_jacobian_part0(") != std::string::npos);
        CHECK(source.find(" w[") != std::string::npos);
        for (const ModelUnderTest& m : models) check_model(run.values, m, lang == Language::cpp);
    }
}
