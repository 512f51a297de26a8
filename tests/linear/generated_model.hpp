#pragma once
// A model's generated C++ as the user gets it (`yamsc MODEL -o model.cpp`),
// compiled with strict warnings into a small program that evaluates the linear
// functions (operating_point, linear, state_space, output_matrices) and, for
// comparison, central finite differences of rhs and outputs, at points given
// on its standard input.
#include "test_files.hpp"

#include <map>
#include <string>
#include <vector>

namespace linear_test {

/// One evaluation point: parameters (np, declaration order), q0, qd0, u0.
struct Point {
    std::vector<double> p, q, qd, u;
};

/// What the program printed for one point: "A", "B", "A_fd", "B_fd", "M0", "C0",
/// "K0", "Q0", "C", "D", "C_fd", "D_fd" (row-major arrays).
using Values = std::map<std::string, std::vector<double>>;

class GeneratedModel {
public:
    /// Compiles `model` (a path relative to the source tree). REQUIREs success.
    GeneratedModel(const std::string& model, const std::string& ns);

    int nq = 0, nu = 0, np = 0, ny = 0;
    std::vector<double> defaults;          // the parameters' defaults
    std::vector<double> op_q, op_qd, op_u; // operating_point(defaults)
    std::string source;                    // the generated C++ text

    /// The functions at each point (run in one process).
    std::vector<Values> evaluate(const std::vector<Point>& points) const;
    /// operating_point(p) for the given parameters: q0, qd0, u0 concatenated.
    std::vector<double> operating_point(const std::vector<double>& p) const;

private:
    std::string dir_, exe_;
};

/// A fresh directory under the test build folder.
inline std::string scratch_dir(const std::string& name) {
    return test_support::scratch_dir("linear_scratch", name);
}
/// Runs a shell command; true on exit status 0.
inline bool run(const std::string& command) {
    return test_support::exit_status(command) == 0;
}
using test_support::read_file;
/// "<k> <name> <values...>" lines, as the evaluation programs print them, by
/// point k (-1 for the header line) and name.
std::map<int, Values> parse_printed(const std::string& text);
using test_support::write_file;

} // namespace linear_test
