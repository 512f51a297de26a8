// What the checker and the approximation report for bad `linearize` blocks and
// `approx` statements: the error, its kind and its place, and no output file.
#include "generated_model.hpp"

#include <doctest/doctest.h>

#include <sys/wait.h>

using namespace linear_test;

namespace {

struct Outcome {
    int status = -1;
    std::string err;
    bool wrote_output = false;
};

const char* base_model = R"(model m
param k = 2, w = 0.5
input u order 1
dof q, r
rigid a { mass = 1; com = (0, 0, -1) }
rigid b { mass = 1; com = (0, 0, -1) }
gravity (0, 0, -9.81)
joint ground -> a { rotate y q }
joint a -> b { translate x r }
spring r stiffness k
genforce q = u
)";

/// Compiles the base model followed by `extra`; the status and stderr.
Outcome compile_with(const std::string& extra) {
    const std::string dir = scratch_dir("diagnostics");
    write_file(dir + "/m.mbd", std::string(base_model) + extra + "\n");
    const std::string cmd = "cd " + dir + " && " + YAMSC_EXE + " m.mbd -o m.cpp 2> err.txt";
    Outcome o;
    const int raw = std::system(cmd.c_str());
    o.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    o.err = read_file(dir + "/err.txt");
    o.wrote_output = run("test -e " + dir + "/m.cpp");
    return o;
}

void expect_error(const std::string& extra, const std::string& message) {
    CAPTURE(extra);
    Outcome o = compile_with(extra);
    CHECK(o.status == 1);
    CHECK_FALSE(o.wrote_output);
    CHECK_MESSAGE(o.err.find(message) != std::string::npos, o.err);
}

} // namespace

TEST_CASE("linearize: the block is checked") {
    expect_error("linearize { s = 1 }",
                 "m.mbd:12:13: error: unknown DOF or input 's' in the linearize block "
                 "[unknown-name]");
    expect_error("linearize { q'' = 1 }",
                 "error: the operating point sets DOFs and rates, not 'q'''");
    expect_error("linearize { u'' = 1 }",
                 "error: input 'u' is declared with order 1: 'u''' is not one of its channels");
    expect_error("linearize { k = 1 }", "is not one of them [wrong-kind]");
    expect_error("linearize { q = 1; q = 2 }",
                 "error: 'q' is given twice in the linearize block [duplicate-name]");
    // Values are functions of the parameters only.
    expect_error("linearize { q = r }", "[wrong-kind]");
    expect_error("linearize { q = t }",
                 "m.mbd:12:17: error: time 't' cannot appear in the operating point value of 'q'");
    // Valid: parameters, derivatives of inputs, rates.
    Outcome ok = compile_with("linearize { q = w; r' = k * w; u = sin(w); u' = 1 }");
    CHECK(ok.status == 0);
    CHECK(ok.wrote_output);
}

TEST_CASE("approx: the statement is checked and what cannot be expanded is reported") {
    expect_error("approx zz order 1", "error: unknown name 'zz' in approx [unknown-name]");
    expect_error("approx a order 1", "approx expands in parameters, DOFs or inputs; 'a' is none");
    expect_error("approx q order 9", "error: approx order must be between 1 and 8, not 9");
    expect_error("approx q, w order 1\napprox q order 2", "error: 'q' is already approximated");
    // A pole at the expansion point: 1/w at w = 0.
    expect_error("genforce r = k / w\napprox w order 1",
                 "m.mbd:13:1: error: approx: cannot expand the equations in w to order 1: they "
                 "contain a division by (or a root of) an expression that is zero when the "
                 "approximated symbols are [invalid-value]");
    CHECK(compile_with("approx q, u order 2\napprox w order 1").status == 0);
}
