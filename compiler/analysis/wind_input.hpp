#pragma once
// `--wind SPEC` (steady, step or file; yamsc/wind.hpp) on the wind input the
// model's load block declares (load_blocks.hpp, wind_input).
#include "analysis/loaded_model.hpp"

#include <yamsc/integration.hpp>
#include <yamsc/model_view.hpp>

#include <yamsc/wind.hpp>

#include <string>
#include <vector>

namespace yamsc::analysis {

/// What --wind names (yamsc/wind.hpp), its warnings printed to stderr; a
/// malformed spec is a UsageError, a bad file a UserError.
runtime::WindInput open_wind_input(const std::string& spec);

/// Inputs `u` with the wind input following --wind.
runtime::InputFunction wind_inputs(const Loaded& l, const runtime::ModelView& v,
                                   std::vector<double> u, const std::string& spec);

/// The wind at t = 0 of --wind, written into u's wind input (for lin and trim).
void set_wind_at_start(const Loaded& l, const runtime::ModelView& v, std::vector<double>& u,
                       const std::string& spec);

} // namespace yamsc::analysis
