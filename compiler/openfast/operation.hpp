#pragma once
// What a full OpenFAST deck's InflowWind, AeroDyn and ServoDyn become in a yamsc
// model (docs/openfast.md, "A full deck: wind, rotor block, controller"): the
// runtime's quasi-steady rotor block (`yamsc sim --aero TABLE`: rotor radius, air
// density, a Cp/Ct/Cq table), the hub-height wind (`--wind`), the generator
// (efficiency, ServoDyn's simple region-2 law) and the controller hookup
// (`--controller LIB --controller-input FILE`). Each value keeps where it came
// from, for the model's comments.
#include "diag/diagnostics.hpp"
#include "openfast/deck.hpp"

#include <optional>
#include <string>

namespace yamsc::openfast {

struct Operation {
    double rotor_radius = 0; ///< TipRad (ElastoDyn) [m]
    double air_density = 0;  ///< AirDens (.fst, else AeroDyn) [kg/m^3]
    std::string air_density_from;
    /// `--wind`'s argument: a hub-height speed, or a uniform wind file, or with the
    /// blade elements the InflowWind file itself (resolved paths); empty when
    /// InflowWind's wind type is not converted.
    std::string wind;
    std::optional<double> wind_speed; ///< when steady
    std::string wind_from;
    double gen_efficiency = 100; ///< GenEff [%]
    std::string gen_efficiency_from;
    /// ServoDyn's VS_Rgn2K (VSContrl = 1) converted to k w^2 in the generator's speed
    /// in rad/s [N m s^2]; 0 otherwise.
    double region2_k = 0;
    std::string region2_k_from;
    std::string controller, controller_input; ///< resolved paths; empty without a DLL
    /// AeroDyn as its blade elements (`load blade_elements`, --aero the AeroDyn
    /// file), or the table rotor (`load rotor_table`, --aero the table).
    bool blade_elements = false;
    std::string aerodyn; ///< AeroFile (resolved), the blade elements' --aero
    std::string table;   ///< the Cp/Ct/Cq table (resolved), or empty
    std::string table_from;
};

/// ServoDyn's nacelle-yaw spring and damper: ServoDyn's yaw moment on ElastoDyn's yaw
/// DOF, YawMom = -YawSpr (yaw - YawPosCom) - YawDamp (yaw rate - YawRateCom), with
/// YawPosCom = YawNeut and YawRateCom = 0 without active yaw control (YCMode 0, or
/// before TYCOn). Each value keeps its "file:line".
struct YawSpring {
    double stiffness = 0;   ///< YawSpr [N m/rad]
    double damping = 0;     ///< YawDamp [N m s/rad]
    double neutral_deg = 0; ///< YawNeut [deg]
    std::string stiffness_from, damping_from, neutral_from;
};

/// The yaw spring and damper of a deck whose `.fst` switches on ServoDyn (CompServo 1),
/// else nullopt. Active yaw control (YCMode 3, 4, 5) and the override yaw maneuver
/// (TYawManS within the run) are warnings at their line: the spring then holds YawNeut,
/// as ServoDyn's does before TYCOn and under a DLL that commands no yaw rate.
std::optional<YawSpring> read_yaw_spring(const openfast::OpenFastDeck& deck,
                                         diag::Diagnostics& diags);

/// The operation of a deck whose `.fst` switches on AeroDyn (CompAero != 0), else
/// nullopt. `cp_table` is `from-openfast --cp-table` (empty: the controller input's
/// PerfFileName, as ROSCO reads it). What cannot be converted (BEM, dynamic inflow,
/// unsteady aerodynamics, other wind types) is a warning at its line.
std::optional<Operation> read_operation(const openfast::OpenFastDeck& deck,
                                        const std::string& cp_table, bool blade_elements,
                                        diag::Diagnostics& diags);

} // namespace yamsc::openfast
