#include "model/load_kinds.hpp"

namespace yamsc::model {

namespace {

/// The roles of PlatformRole: the body, then the water (the mooring's seabed
/// needs the depth; HydroDyn may take it from the SeaState file).
std::vector<LoadRole> platform_roles(const std::string& platform, bool depth_required) {
    using T = RoleTarget;
    return {
        {"platform", T::body, true, platform},
        {"depth", T::parameter, depth_required, "the water depth below the still-water level [m]"},
        {"density", T::parameter, false, "the water density [kg/m^3] (1025 unbound)"},
        {"gravity", T::parameter, false,
         "the acceleration of gravity the water weighs with [m/s^2] (9.80665 unbound)"},
    };
}

} // namespace

const std::vector<LoadKindInfo>& load_kinds() {
    using T = RoleTarget;
    static const std::vector<LoadKindInfo> kinds{
        {LoadKind::rotor_table,
         "rotor_table",
         {
             {"wind", T::input_read, true, "the hub-height wind speed [m/s]"},
             {"pitch", T::input_read, false, "the collective blade pitch [rad]"},
             {"thrust", T::load_input, true,
              "the input the thrust along the shaft is added to [N]"},
             {"rotor_torque", T::load_input, true,
              "the input the aerodynamic torque about the shaft is added to [N m]"},
             {"speed", T::output_read, true, "the rotor speed [rad/s]"},
             {"hub_velocity", T::output_read, true,
              "the hub's velocity along the shaft, downwind [m/s]"},
             {"radius", T::parameter, true, "the rotor radius of the table [m]"},
             {"density", T::parameter, true, "the air density [kg/m^3]"},
         },
         {"thrust", "torque_out", "power", "tsr", "v_rel", "cp", "ct"},
         static_cast<int>(RotorTableRole::wind)},
        {LoadKind::blade_elements,
         "blade_elements",
         {
             {"wind", T::input_read, true, "the hub-height wind speed [m/s]"},
             {"pitch", T::input_read, false,
              "the blades' collective pitch, replacing their frames' [rad]"},
             {"hub", T::body, true, "the hub: its x axis is the rotor's axis"},
             {"blade1", T::body, true,
              "blade 1: its AeroDyn nodes move with it (and its deflection)"},
             {"blade2", T::body, false, "blade 2"},
             {"blade3", T::body, false, "blade 3"},
             {"tower", T::body, false,
              "the tower: AeroDyn's tower nodes move with it, its drag acts on it"},
         },
         {"RtSpeed", "RtTSR", "RtVAvgxh", "RtSkew", "RtFldFxh", "RtFldMxh", "RtFldPwr", "RtFldCp",
          "RtFldCt", "RtFldCq"},
         static_cast<int>(BladeElementsRole::wind),
         false},
        {LoadKind::mooring,
         "mooring",
         platform_roles("the body the lines' fairleads are on (MAP++'s vessel)", true),
         {}, // <NAME>_T_fair<n>, <NAME>_T_anch<n>: one per line of the file
         -1},
        {LoadKind::hydrodyn,
         "hydrodyn",
         platform_roles("the body HydroDyn's members and potential flow move with", false),
         {}, // the parts' own (analysis/hydrodyn_parts.hpp)
         -1},
    };
    return kinds;
}

const LoadKindInfo& load_kind_info(LoadKind kind) {
    for (const LoadKindInfo& k : load_kinds())
        if (k.kind == kind) return k;
    return load_kinds().front(); // every kind has a row
}

} // namespace yamsc::model
