#pragma once
// Compiles generated models with the system compilers at strict warning levels,
// links them with a small driver that evaluates every function at a point (and
// central finite differences of rhs), runs it and parses what it prints.
#include "codegen/emit.hpp"
#include "codegen/module.hpp"
#include "fixtures.hpp"
#include "test_files.hpp"

#include <map>
#include <string>
#include <vector>

namespace codegen_test {

enum class Language { cpp, c };

struct ModelUnderTest {
    const Equations* eq = nullptr;
    yamsc::codegen::Module module;
    Point point;
    bool with_header = true; // false: one self-contained file, included by the driver
    int max_function_statements = yamsc::codegen::EmitOptions{}.max_function_statements;
};

/// "<model> <what>" -> the printed values (what: defaults, M, M_short, F, dF_dq,
/// dF_dqd, dF_du, y, xdot, J, J_fd, and in C++ xdot_model).
using Results = std::map<std::string, std::vector<double>>;

struct RunResult {
    bool ok = false;
    std::string log; // commands and compiler/driver output when !ok
    Results values;
    std::vector<std::string> files; // the generated files written
};

RunResult compile_and_run(Language lang, const std::vector<ModelUnderTest>& models,
                          const std::string& dir_name);

/// A fresh directory under YAMSC_TEST_BINARY_DIR.
inline std::string scratch_dir(const std::string& name) {
    return test_support::scratch_dir("codegen_scratch", name);
}
using test_support::read_file;
using test_support::write_file;

} // namespace codegen_test
