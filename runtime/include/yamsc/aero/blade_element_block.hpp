#pragma once
// `load blade_elements`: AeroDyn's blade elements on a model's blades, as a load
// block (yamsc/load_block.hpp). The model's mesh channels give the hub's and
// each blade's frame and modes; each AeroDyn node moves with its blade
// (yamsc/body_mesh.hpp: between the blade's nodes, following its deflection),
// the rotor's BEM (bem_rotor.hpp) gives the loads per length at the AeroDyn
// nodes, and those are carried to the blade's structural nodes as ElastoDyn
// takes them (the load per length at each node times its element's length)
// and set on the blade exactly through the node's partial velocities.
#include "yamsc/aero/rotor_input.hpp"
#include "yamsc/body_mesh.hpp"
#include "yamsc/load_block.hpp"
#include "yamsc/wind/wind_field.hpp"

#include <memory>
#include <string>
#include <vector>

namespace yamsc::aero {

/// The optional tower role: its mesh outputs (18 + 2 modes; empty: no tower
/// role), its mesh inputs (6 + modes) and its SID nodes along its z axis (none:
/// a rigid tower). AeroDyn's tower nodes (TwrElev, above the ground) move with
/// it, between its nodes; the tower's influence and drag follow them.
struct TowerChannels {
    std::vector<int> outputs, loads;
    std::vector<runtime::BodyPoint> points;
};

/// Where the block meets the model: indices into the view's channels.
struct BladeElementChannels {
    int wind = -1;  // input: V_wind, the hub-height wind speed [m/s] (the field's reference speed)
    int pitch = -1; // input (or -1): the blades' collective pitch [rad], about their z axes
                    // from the pitch their frames have relative to the hub (else as they are)
    std::vector<int> hub_outputs; // the hub's mesh outputs (18)
    struct Blade {
        std::vector<int> outputs; // its mesh outputs (18 + 2 modes)
        std::vector<int> loads;   // its mesh inputs (6 + modes)
        std::vector<runtime::BodyPoint>
            points; // its structural nodes (body axes, z along the span)
    };
    std::vector<Blade> blades;
    TowerChannels tower;
};

struct BladeElementSetup {
    std::string output_prefix; // before each output's name (AeroDyn's: RtFldCp, B1N1Alpha, ...)
    RotorInput rotor;
    BladeElementChannels channels;
    /// How derivatives() takes the loads' derivatives: central differences of
    /// relative step `difference_step`, with the BEM solved at every perturbed
    /// point (quasi-steady: trim's Newton, CVODE) or, with `frozen_wake`, the
    /// wake frozen at the point (the linear model, as OpenFAST linearizes
    /// AeroDyn: BemRotor::freeze_wake).
    bool frozen_wake = false;
    double difference_step = 1e-6;
    /// The wind at every node (blades and tower) at the block's time, its
    /// reference speed replaced by the V_wind read (wind_field.hpp); null: V_wind
    /// along ground x everywhere.
    std::shared_ptr<const runtime::WindField> wind_field;
};

std::shared_ptr<const runtime::LoadBlock> blade_element_block(BladeElementSetup setup);

} // namespace yamsc::aero
