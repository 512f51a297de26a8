#include "analysis/dlc_files.hpp"

#include <yamsc/csv.hpp>

#include <cstdio>
#include <sstream>

namespace yamsc::analysis {

namespace {

/// A number as the CSV writer writes it (%.10g, whatever the C locale).
std::string num(double v) {
    return runtime::format_csv_value(v);
}

/// "value   Key  - comment" as TurbSim's files align them.
std::string entry(const std::string& value, const std::string& key, const std::string& comment) {
    char s[256];
    std::snprintf(s, sizeof s, "%14s   %-15s - ", value.c_str(), key.c_str());
    return s + comment + "\n";
}

std::string quoted(const std::string& s) {
    return "\"" + s + "\"";
}

std::string turbulence_characteristic(const DlcOptions& o, const DlcWind& w) {
    if (w.model == DlcWindModel::ewm50) return "11"; // sigma_1 = 0.11 V_hub, IEC (18)
    return o.turbulence == TurbulenceCategory::A   ? "A"
           : o.turbulence == TurbulenceCategory::B ? "B"
                                                   : "C";
}

std::string iec_wind_type(const DlcOptions& o, const DlcWind& w) {
    if (w.model != DlcWindModel::etm) return "NTM";
    return std::to_string(static_cast<int>(o.turbine_class) + 1) + "ETM";
}

} // namespace

std::string turbsim_input_text(const DlcOptions& o, const DlcWind& w) {
    const double size = grid_size(o);
    const double tmax = o.time + o.transient;
    const double shear = w.model == DlcWindModel::ewm50 ? 0.11 : o.shear;
    std::string s;
    s += "---------TurbSim v2 (OpenFAST) Input File------------------\n";
    s += "yamsc dlc: " + w.name + " (IEC 61400-1 Ed. 3 " + wind_model_name(w.model) + ", class " +
         class_name(o) + ", seed " + std::to_string(w.seed) + ")\n";
    s += "---------Runtime Options-----------------------------------\n";
    s += entry("False", "Echo", "Echo input data to <RootName>.ech (flag)");
    s += entry(std::to_string(w.rand_seed), "RandSeed1", "First random seed");
    s += entry("\"RanLux\"", "RandSeed2", "Second random seed, or an alternative pRNG");
    for (const char* key : {"WrBHHTP", "WrFHHTP", "WrADHH"})
        s += entry("False", key, "hub-height outputs (not written)");
    s += entry("True", "WrADFF",
               "Output full-field time-series data in TurbSim/AeroDyn form "
               "(RootName.bts)");
    for (const char* key : {"WrBLFF", "WrADTWR", "WrHAWCFF", "WrFMTFF", "WrACT"})
        s += entry("False", key, "other outputs (not written)");
    s += entry("0", "ScaleIEC", "Scale IEC turbulence models to exact target standard deviation?");
    s += "\n--------Turbine/Model Specifications-----------------------\n";
    s += entry(std::to_string(o.grid_points), "NumGrid_Z", "Vertical grid-point matrix dimension");
    s +=
        entry(std::to_string(o.grid_points), "NumGrid_Y", "Horizontal grid-point matrix dimension");
    s += entry(num(o.wind_dt), "TimeStep", "Time step [seconds]");
    s += entry(num(tmax), "AnalysisTime", "Length of analysis time series [seconds]");
    s += entry(num(tmax), "UsableTime", "Usable length of output time series [seconds]");
    s += entry(num(o.hub_height), "HubHt", "Hub height [m]");
    s += entry(num(size), "GridHeight", "Grid height [m]");
    s += entry(num(size), "GridWidth", "Grid width [m]");
    s += entry("0", "VFlowAng", "Vertical mean flow (uptilt) angle [degrees]");
    s += entry("0", "HFlowAng", "Horizontal mean flow (skew) angle [degrees]");
    s += "\n--------Meteorological Boundary Conditions-------------------\n";
    s += entry("\"IECKAI\"", "TurbModel", "Turbulence model");
    s += entry("\"unused.spectra\", \"unused.timeSeriesInput\"", "UserFile",
               "user-defined spectra or time series (unused)");
    s += entry("\"1-ED3\"", "IECstandard", "Number of IEC 61400-x standard");
    s += entry(quoted(turbulence_characteristic(o, w)), "IECturbc",
               w.model == DlcWindModel::ewm50
                   ? "turbulence intensity in percent: sigma_1 = 0.11 V_hub "
                     "(EWM, IEC (18))"
                   : "IEC turbulence characteristic");
    s += entry(quoted(iec_wind_type(o, w)), "IEC_WindType", "IEC turbulence type");
    s += entry("\"default\"", "ETMc", "IEC Extreme Turbulence Model \"c\" parameter [m/s]");
    s += entry("\"PL\"", "WindProfileType", "Velocity profile type");
    s += entry("\"unused\"", "ProfileFile", "user-defined profiles (unused)");
    s += entry(num(o.hub_height), "RefHt", "Height of the reference velocity (URef) [m]");
    s += entry(num(w.speed), "URef", "Mean (total) velocity at the reference height [m/s]");
    s += entry("350", "ZJetMax", "Jet height [m] (unused)");
    s += entry(num(shear), "PLExp", "Power law exponent [-]");
    s += entry("\"default\"", "Z0", "Surface roughness length [m]");
    s += "\n--------Non-IEC Meteorological Boundary Conditions------------\n";
    s += entry("\"default\"", "Latitude", "Site latitude [degrees]");
    s += entry("0.05", "RICH_NO", "Gradient Richardson number [-]");
    for (const char* key : {"UStar", "ZI", "PC_UW", "PC_UV", "PC_VW"})
        s += entry("\"default\"", key, "(not used by IECKAI)");
    s += "\n--------Spatial Coherence Parameters----------------------------\n";
    for (const char* key :
         {"SCMod1", "SCMod2", "SCMod3", "InCDec1", "InCDec2", "InCDec3", "CohExp"})
        s += entry("\"default\"", key, "the IEC model's defaults");
    s += "\n--------Coherent Turbulence Scaling Parameters-------------------\n";
    s += entry("\"unused\"", "CTEventPath", "(WrACT is False)");
    s += entry("\"les\"", "CTEventFile", "(WrACT is False)");
    s += entry("true", "Randomize", "(WrACT is False)");
    s += entry("1", "DistScl", "(WrACT is False)");
    s += entry("0.5", "CTLy", "(WrACT is False)");
    s += entry("0.5", "CTLz", "(WrACT is False)");
    s += entry("10", "CTStartTime", "(WrACT is False)");
    s += "\n====================================================\n";
    s += "! NOTE: Do not add or remove any lines in this file!\n";
    s += "====================================================\n";
    return s;
}

std::string inflowwind_text(const DlcWind& w, double yaw, double hub_height,
                            const std::string& bts) {
    std::string s;
    s += "------- InflowWind v3.01.* INPUT FILE "
         "-----------------------------------------------------------------------"
         "--\n";
    s += "yamsc dlc: " + w.name + " seen at a yaw misalignment of " + num(yaw) + " deg\n";
    s += "-----------------------------------------------------------------------"
         "---------------"
         "-------------------------\n";
    s += entry("False", "Echo", "Echo input data to <RootName>.ech (flag)");
    s += entry("3", "WindType", "switch for wind file type (3=binary TurbSim FF)");
    s += entry(num(yaw), "PropagationDir",
               "Direction of wind propagation (meteorological rotation from "
               "aligned with X "
               "(positive rotates towards -Y) -- degrees)");
    s += entry("0", "VFlowAng", "Upflow angle (degrees)");
    s += entry("False", "VelInterpCubic", "Use cubic interpolation for velocity in time");
    s += entry("1", "NWindVel", "Number of points to output the wind velocity (0 to 9)");
    s += entry("0", "WindVxiList", "List of coordinates in the inertial X direction (m)");
    s += entry("0", "WindVyiList", "List of coordinates in the inertial Y direction (m)");
    s += entry(num(hub_height), "WindVziList",
               "List of coordinates in the inertial Z direction (m): the hub");
    s += "================== Parameters for Steady Wind Conditions [used only "
         "for WindType = 1] "
         "=========================\n";
    s += entry("0", "HWindSpeed", "Horizontal windspeed (m/s)");
    s += entry("0", "RefHt", "Reference height for horizontal wind speed (m)");
    s += entry("0", "PLexp", "Power law exponent (-)");
    s += "================== Parameters for Uniform wind file   [used only for "
         "WindType = 2] "
         "============================\n";
    s += entry("\"unused\"", "Filename_Uni", "Filename of time series data for uniform wind field");
    s += entry("0", "RefHt_Uni", "Reference height for horizontal wind speed (m)");
    s += entry("0", "RefLength", "Reference length for linear horizontal and vertical sheer (-)");
    s += "================== Parameters for Binary TurbSim Full-Field files   "
         "[used only for "
         "WindType = 3] ==============\n";
    s += entry(quoted(bts), "FileName_BTS", "Name of the Full field wind file to use (.bts)");
    s += "================== Parameters for Binary Bladed-style Full-Field files "
         "  [used only "
         "for WindType = 4 or WindType = 7] =========\n";
    s += entry("\"unused\"", "FileNameRoot", "Rootname of the full-field wind file to use");
    s += entry("False", "TowerFile", "Have tower file (.twr) (flag)");
    s += "================== Parameters for HAWC-format binary files  [Only used "
         "with WindType "
         "= 5] =====================\n";
    for (const char* key : {"FileName_u", "FileName_v", "FileName_w"})
        s += entry("\"unused\"", key, "(WindType 5 only)");
    for (const char* key : {"nx", "ny", "nz"}) s += entry("2", key, "(WindType 5 only)");
    for (const char* key : {"dx", "dy", "dz", "RefHt_Hawc"})
        s += entry("1", key, "(WindType 5 only)");
    s += "  -------------   Scaling parameters for turbulence   "
         "---------------------------------------------------------\n";
    s += entry("0", "ScaleMethod", "Turbulence scaling method (WindType 5 only)");
    for (const char* key : {"SFx", "SFy", "SFz", "SigmaFx", "SigmaFy", "SigmaFz"})
        s += entry("1", key, "(WindType 5 only)");
    s += "  -------------   Mean wind profile parameters (added to HAWC-format "
         "files)   "
         "---------------------------------\n";
    s += entry("0", "URef", "(WindType 5 only)");
    s += entry("0", "WindProfile", "(WindType 5 only)");
    s += entry("0", "PLExp_Hawc", "(WindType 5 only)");
    s += entry("0.03", "Z0", "(WindType 5 only)");
    s += entry("0", "XOffset", "(WindType 5 only)");
    s += "================== LIDAR Parameters "
         "======================================================================="
         "====\n";
    s += entry("0", "SensorType", "Switch for lidar configuration (0 = None)");
    s += entry("0", "NumPulseGate", "(no lidar)");
    s += entry("30", "PulseSpacing", "(no lidar)");
    s += entry("0", "NumBeam", "(no lidar)");
    s += entry("-200", "FocalDistanceX", "(no lidar)");
    s += entry("0", "FocalDistanceY", "(no lidar)");
    s += entry("0", "FocalDistanceZ", "(no lidar)");
    s += entry("0.0 0.0 0.0", "RotorApexOffsetPos", "(no lidar)");
    s += entry("17", "URefLid", "(no lidar)");
    s += entry("0.25", "MeasurementInterval", "(no lidar)");
    s += entry("False", "LidRadialVel", "(no lidar)");
    s += entry("1", "ConsiderHubMotion", "(no lidar)");
    s += "====================== OUTPUT "
         "==================================================\n";
    s += entry("False", "SumPrint", "Print summary data to <RootName>.IfW.sum (flag)");
    s += "              OutList      - The next line(s) contains a list of "
         "output parameters.\n";
    s += "\"Wind1VelX\"               X-direction wind velocity at point "
         "WindList(1)\n";
    s += "END of input file (the word \"END\" must appear in the first 3 columns "
         "of this last "
         "OutList line)\n";
    s += "-----------------------------------------------------------------------"
         "---------------"
         "-------------------------\n";
    return s;
}

std::string manifest_text(const DlcOptions& o, const DlcTable& t, const DlcPaths& paths) {
    std::ostringstream s;
    s << "# yamsc dlc: IEC 61400-1 Ed. 3, class " << class_name(o) << ", hub height "
      << num(o.hub_height) << " m, rotor diameter " << num(o.rotor_diameter) << " m\n"
      << "# tmax = " << num(o.time) << " s + a transient of " << num(o.transient)
      << " s to drop: yamsc loads --batch cases.out --speeds table.csv --from " << num(o.transient)
      << "\n"
      << "id,model,tmax,dt,method,coupling,channels,dt_out,wind,aero,controller,"
         "controller_input,u\n";
    for (const DlcCase& c : t.cases) {
        s << c.id << "," << (c.parked ? paths.parked_model : paths.model) << ","
          << num(o.time + o.transient) << "," << num(o.dt) << ",abm4,loose,openfast,"
          << num(o.dt_out) << ",wind/" << c.inflow << ".dat," << paths.aero << ","
          << (c.parked ? "" : paths.controller) << "," << (c.parked ? "" : paths.controller_input)
          << "," << (c.parked && !o.parked_u.empty() ? "\"" + o.parked_u + "\"" : "") << "\n";
    }
    return s.str();
}

std::string table_text(const DlcOptions& o, const DlcTable& t) {
    std::ostringstream s;
    s << "id,dlc,speed,turbulence,seed,rand_seed,yaw,parked,transient\n";
    for (const DlcCase& c : t.cases) {
        const DlcWind& w = t.winds[c.wind];
        s << c.id << "," << dlc_name(c.dlc) << "," << num(w.speed) << ","
          << wind_model_name(w.model) << "," << w.seed << "," << w.rand_seed << "," << num(c.yaw)
          << "," << (c.parked ? "yes" : "no") << "," << num(o.transient) << "\n";
    }
    return s.str();
}

} // namespace yamsc::analysis
