#pragma once
// The pieces `yamsc lin` prints, shared by the model in all its coordinates
// (run_model.cpp) and the constrained one in its independent coordinates
// (constrained_model.cpp).
#include <yamsc/modal.hpp>

#include <string>
#include <vector>

namespace yamsc::analysis {

/// The rows of a row-major nrow x ncol matrix (for driver::json::matrix).
std::vector<std::vector<double>> matrix_rows(const std::vector<double>& m, int nrow, int ncol);

/// "mode  frequency [Hz]  damping ratio  shape (largest DOF)" and a line per mode;
/// the shapes' entries are those of `dofs`.
std::string format_mode_table(const std::vector<std::string>& dofs,
                              const std::vector<runtime::Mode>& modes);

/// The modes as a JSON array of {freq_hz, damping_ratio, rigid_body}.
std::string modes_json(const std::vector<runtime::Mode>& modes);

} // namespace yamsc::analysis
