#pragma once
// TurbSim's input file (OpenFAST v5's TurbSim, "TurbSim v2" format), the entries
// an IEC 61400-1 Ed. 3 Kaimal field needs (TurbModel IECKAI). TurbSim reads its
// lines in order, "value  Key  - comment"; here each line's key is found among
// TurbSim's entry names, so an entry is read wherever it stands. Entries that
// would change TurbSim's field but are not supported warn at their line
// (RandSeed2, output kinds other than the .bts, flow angles, coherence models
// other than the default, unknown keys); entries TurbSim ignores for IECKAI are
// read silently; anything unusable for the generator is a located error
// "source:line:col: what".
#include <cstdint>
#include <istream>
#include <string>
#include <vector>

namespace yamsc::wind {

/// IECturbc: a class's reference intensity (Ed. 3: A 0.16, B 0.14, C 0.12) or a
/// turbulence intensity in percent.
enum class TurbulenceCharacteristic { A, B, C, percent };
/// IEC_WindType: the normal or the extreme turbulence model.
enum class IecTurbulenceModel { normal, extreme };
/// WindProfileType.
enum class WindProfile { power_law, logarithmic };

struct TurbSimInput {
    std::string source;
    std::int64_t seed = 0; // RandSeed1
    int scale_iec = 0;     // ScaleIEC: 0 none, 1 the hub's factor everywhere, 2 each point's
    int nz = 0, ny = 0;    // NumGrid_Z, NumGrid_Y
    double time_step = 0, analysis_time = 0;
    double usable_time = 0; // UsableTime; "ALL": periodic (the FFT's length)
    bool periodic = false;
    double hub_height = 0, grid_height = 0, grid_width = 0;
    TurbulenceCharacteristic characteristic = TurbulenceCharacteristic::B;
    double intensity_percent = 0; // IECturbc as a number
    IecTurbulenceModel model = IecTurbulenceModel::normal;
    int turbine_class = 0; // xETM: the wind turbine class 1, 2 or 3 (its V_ref)
    double etm_c = 2;      // ETMc [m/s]
    WindProfile profile = WindProfile::power_law;
    double ref_height = 0, ref_speed = 0; // RefHt [m], URef [m/s]
    double power_law = 0.2;               // PLExp ("default": 0.2, TurbSim's for IEC models)
    double roughness = 0.03;              // Z0 [m] ("default": 0.03, TurbSim's for IECKAI)
    /// "source:line:col: warning: ..." for entries read but not supported.
    std::vector<std::string> warnings;
};

/// Throws std::runtime_error "source:line:col: what".
TurbSimInput read_turbsim_input(std::istream& in, const std::string& source);

} // namespace yamsc::wind
