#pragma once
// One simulation as `yamsc sim` runs it, on a model already loaded and bound:
// `sim` and `batch` both run this, so a batch case gives bit for bit the
// numbers of `yamsc sim` with the same options.
#include "analysis/channels.hpp"
#include "analysis/loaded_model.hpp"
#include "codegen/routines.hpp"
#include "driver/commands.hpp"

#include <yamsc/model_view.hpp>
#include <yamsc/simulation.hpp>

#include <iosfwd>
#include <string>
#include <vector>

namespace yamsc::analysis {

/// The routines a simulation with these options calls (jit.hpp).
codegen::RoutineSet sim_routines(const driver::SimOptions& o);

struct SimRun {
    runtime::ModelView view; // what was integrated (linear, with the load blocks)
    runtime::SimulationResult result;
};

/// Integrates `l` (its parameters bound) from its initial state with --ic, the
/// inputs, --wind, --aero, --linear and --controller of `o`. The model, --set,
/// --sid and the output options of `o` are not looked at. --verbose details go
/// to `out` and `err`, as sim prints them.
SimRun simulate_case(const Loaded& l, const driver::SimOptions& o, std::ostream& out,
                     std::ostream& err);

/// The table sim writes with -o: every column, or OpenFAST's channels.
Table sim_table(const SimRun& run, driver::Channels channels);

/// Writes sim's -o file atomically.
void write_sim_csv(const SimRun& run, driver::Channels channels, const std::string& path);

} // namespace yamsc::analysis
