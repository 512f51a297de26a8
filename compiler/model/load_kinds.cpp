#include "model/load_kinds.hpp"

namespace yamsc::model {

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
    };
    return kinds;
}

const LoadKindInfo& load_kind_info(LoadKind kind) {
    for (const LoadKindInfo& k : load_kinds())
        if (k.kind == kind) return k;
    return load_kinds().front(); // every kind has a row
}

} // namespace yamsc::model
