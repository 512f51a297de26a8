#pragma once
// The output part of a linear model, y = y0 + C (x - x0) + D (u - u0): the
// generated code has no output Jacobians, so C and D are central differences
// of the outputs routine (`yamsc lin` prints no C and D).
#include <yamsc/model_view.hpp>

#include <vector>

namespace yamsc::python {

struct OutputMatrices {
    std::vector<double> C; ///< ny x 2nq, row-major
    std::vector<double> D; ///< ny x nu, row-major
};

/// At x0 = [q0, q0'], u0, t0. Throws std::invalid_argument without an outputs routine.
OutputMatrices output_matrices(const runtime::ModelView& view, const std::vector<double>& x0,
                               const std::vector<double>& u0, double t0);

} // namespace yamsc::python
