#pragma once
// The kinds of load block a model may declare (`load KIND NAME { role = ... }`,
// docs/language.md) and their roles: what each binds to in the model. The
// checker validates a declaration against this table; analysis/load_blocks.cpp
// builds the runtime's block of each kind from the bound names. A new kind is a
// row here, its role enum, and its builder in analysis/.
#include <string>
#include <vector>

namespace yamsc::model {

enum class LoadKind { rotor_table, blade_elements, mooring, hydrodyn };

/// What a role is bound to.
enum class RoleTarget {
    input_read,  // an input the block reads (wind, pitch)
    load_input,  // an input the block's load is added to
    output_read, // an output the block reads (the motion it responds to)
    parameter,   // a parameter, at its bound value
    body,        // a body the block moves with and loads: its mesh channels (mesh_channels.hpp)
};

struct LoadRole {
    std::string name;
    RoleTarget target;
    bool required;
    std::string what; // for messages and docs
};

struct LoadKindInfo {
    LoadKind kind;
    std::string name;
    std::vector<LoadRole> roles;      // in the order of the kind's role enum
    std::vector<std::string> outputs; // the block's outputs, after the model's
    int wind_role = -1;               // the role `--wind` drives, if any
    /// The outputs are NAME_<output>; or, for kinds that compute OpenFAST's
    /// channels, named as the channels (AeroDyn's RtFldCp, B1N1Alpha, ...).
    bool prefixed_outputs = true;

    /// The name block `block` gives its output `output`.
    std::string output_name(const std::string& block, const std::string& output) const {
        return prefixed_outputs ? block + "_" + output : output;
    }
};

/// The roles of `load rotor_table`, in the order of its LoadKindInfo::roles.
enum class RotorTableRole { wind, pitch, thrust, torque, speed, hub_velocity, radius, density };

/// The roles of `load blade_elements`: AeroDyn's blade elements on the blades' nodes.
enum class BladeElementsRole { wind, pitch, hub, blade1, blade2, blade3, tower };

/// The roles of the platform kinds, `load mooring` (MAP++'s lines) and `load
/// hydrodyn` (HydroDyn's members and potential flow): the body they load and
/// the water they are in. Both kinds share this order.
enum class PlatformRole { platform, depth, density, gravity };

const std::vector<LoadKindInfo>& load_kinds();
const LoadKindInfo& load_kind_info(LoadKind kind);

} // namespace yamsc::model
