#pragma once
// The one place where a command's load blocks are chosen: the blocks the model
// declares (`load KIND NAME { role = name ... }`, model/load_kinds.hpp) whose
// data the command line supplies (--aero TABLE: the rotor_table blocks), each
// built by its kind's builder (one file per kind, registered in
// load_blocks.cpp) and closed around the model's view (yamsc/load_block.hpp).
// sim, batch, trim, lin, the sweeps and the Python module all come here.
#include "analysis/loaded_model.hpp"
#include "codegen/routines.hpp"
#include "driver/commands.hpp"
#include "driver/outputs.hpp"

#include <yamsc/hydro/waves.hpp>
#include <yamsc/load_block.hpp>
#include <yamsc/model_view.hpp>
#include <yamsc/trim.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace yamsc::analysis {

/// What the command line gives the load blocks.
struct BlockOptions {
    std::string aero;        // --aero TABLE: the Cp/Ct/Cq table of the rotor_table blocks
    std::string mooring{};   // --mooring MAP.dat: MAP++'s lines of the `mooring` blocks
    std::string hydro{};     // --hydro HydroDyn.dat: the `hydrodyn` blocks' members and matrices
    std::string sea_state{}; // --sea-state SeaState.dat: their waves (still water without)
    /// When set, the `hydrodyn` blocks' waves instead of --sea-state's, made in the
    /// declaration's water (null: still water): the frequency response's unit waves.
    std::function<std::shared_ptr<const runtime::hydro::WaveField>(const runtime::hydro::Water&)>
        waves{};
    /// --wind SPEC: an InflowWind file gives the blade elements its field
    /// (yamsc/wind.hpp); any other spec, or none, V_wind along ground x.
    std::string wind{};
    /// Blade elements differentiated with a frozen wake, as OpenFAST linearizes
    /// AeroDyn (`lin`'s default, --wake frozen); else the derivatives of the
    /// quasi-steady loads, the BEM solved at every perturbed point (trim's
    /// Newton, CVODE, `lin --wake quasi-steady`).
    bool frozen_wake = false;
    /// The blocks' central differences: each value v stepped by this times (1 + |v|).
    double difference_step = 1e-6;
    /// Blade elements: the BEM's inflow angle solved to this [rad] (0: AeroDyn's
    /// 1e-6, as sim runs it); trim and lin solve it to round-off, so that their
    /// Newton steps and difference quotients see smooth loads.
    double inflow_angle_tolerance = 0;
    /// How the blocks meet the structure within a step (sim's --coupling).
    runtime::BlockCoupling coupling{};
};

/// The block options of a command's options (sim, lin, trim: each has --aero).
template <class Options> BlockOptions block_options(const Options& o) {
    BlockOptions b;
    b.aero = o.aero;
    b.wind = o.wind;
    b.mooring = o.mooring;
    b.hydro = o.hydro;
    b.sea_state = o.sea_state;
    return b;
}

/// The block options of `sim`: its --coupling too.
BlockOptions sim_block_options(const driver::SimOptions& o);

/// The block options of `lin`: its --wake too.
BlockOptions linear_block_options(const driver::LinOptions& o);

/// The block options of a trim (`trim`, `lin --trim`, the sweeps' trims).
template <class Options> BlockOptions trim_block_options(const Options& o) {
    BlockOptions b = block_options(o);
    b.inflow_angle_tolerance = 1e-13;
    return b;
}

/// Whether the options ask for any load block.
bool any_blocks(const BlockOptions& b);

/// The routines closed blocks call besides the command's (jit.hpp): the outputs
/// they read; with `exact_jacobian` (CVODE's rhs_jacobian), M and F's Jacobians.
void add_block_routines(const BlockOptions& b, bool exact_jacobian, codegen::RoutineSet& routines);

/// The files the options name: inputs no output of the command may replace.
std::vector<driver::NamedFile> block_files(const BlockOptions& b);

/// The model's blocks the options supply, built at `params` for the view `v`
/// (UserError naming what to declare when the model has no block of a kind
/// the options supply, or what a block's data lacks).
runtime::LoadBlocks load_blocks(const Loaded& l, const runtime::ModelView& v,
                                const std::vector<double>& params, const BlockOptions& b);

/// `l`'s view with those blocks closed around it (the view itself without any).
runtime::ModelView with_load_blocks(const Loaded& l, const BlockOptions& b);
/// The same for a view of `l`'s library at other parameters.
runtime::ModelView with_load_blocks(const Loaded& l, const runtime::ModelView& v,
                                    const std::vector<double>& params, const BlockOptions& b);

/// The trim's settings with the blocks the options supply closed around `l`:
/// the default, or with blade elements a relative tolerance of 1e-6: their loads
/// are smooth only piecewise (the airfoil tables' linear interpolation, the
/// unsteady airfoils' settled states), and Newton on the 16-DOF NREL 5-MW stops
/// at 1e-7 to 1e-6 of the starting residual even with the inflow angle solved
/// to round-off (trim_block_options).
runtime::TrimSettings trim_settings(const Loaded& l, const BlockOptions& b);

/// The input `--wind` drives: the wind role of the model's first load block
/// that has one (UserError naming the declaration to add without one).
int wind_input(const Loaded& l, const runtime::ModelView& v);

} // namespace yamsc::analysis
