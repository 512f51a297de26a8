#pragma once
// IEC 61400-1 Ed. 3 design load cases (table 2) as the cases of a batch
// (docs/dlc.md): which winds (turbulence model x hub speed x seed) and which
// simulations (wind x yaw misalignment, operating or parked) a DLC table asks
// for.
#include <cstdint>
#include <string>
#include <vector>

namespace yamsc::analysis {

enum class DesignLoadCase { dlc1_1, dlc1_2, dlc1_3, dlc6_1, dlc6_2 };
enum class TurbineClass { I, II, III };      // V_ref 50, 42.5, 37.5 m/s
enum class TurbulenceCategory { A, B, C };   // I_ref 0.16, 0.14, 0.12
enum class DlcWindModel { ntm, etm, ewm50 }; // normal, extreme turbulence, 50-year extreme wind

/// `yamsc dlc MODEL -o FOLDER ...` (compiler/cli/commands/dlc.cpp).
struct DlcOptions {
    std::string model;        // the operating turbine (with its controller's inputs)
    std::string parked_model; // --parked-model; empty: `model`
    std::string output_dir;   // -o
    std::vector<DesignLoadCase> cases{DesignLoadCase::dlc1_2};
    TurbineClass turbine_class = TurbineClass::I;
    TurbulenceCategory turbulence = TurbulenceCategory::B;
    double hub_height = 0, rotor_diameter = 0; // [m], required
    double cut_in = 3, cut_out = 25,
           bin = 2;             // the operating speeds: bin centres [m/s]
    std::vector<double> speeds; // --speeds: instead of the bins
    int seeds = 6;
    std::int64_t seed_base = 1; // RandSeed1 of the first wind (docs/dlc.md)
    std::vector<double> yaw{0}; // DLC 1.x yaw misalignments [deg]
    double parked_yaw = 8;      // DLC 6.1: +- this [deg]
    double yaw_step = 30;       // DLC 6.2: -180 .. 180 - step [deg]
    std::string controller, controller_input,
        aero;                                          // the operating cases' (aero: all cases')
    std::string parked_u = "pitch=90deg,gen_torque=0"; // the parked cases' inputs
    double dt = 0.01, dt_out = 0.05;
    double time = 600, transient = 60; // tmax = time + transient [s]
    int grid_points = 15;              // the wind grid: N x N points
    double grid_size = 0;              // its width and height [m]; 0: 1.15 rotor diameters
    double wind_dt = 0.05;             // the wind field's time step [s]
    double shear = 0.2;                // the NTM and ETM power law (EWM: 0.11, IEC (16))
    bool write_bts = true;             // --no-bts: the TurbSim inputs only
    int threads = 0;                   // --threads: fields made at a time; 0: one per core
};

/// One distinct turbulent wind field.
struct DlcWind {
    std::string name; // the file stem: NTM_U11.0_s1
    DlcWindModel model = DlcWindModel::ntm;
    double speed = 0; // the hub's 10-minute mean [m/s]
    int seed = 1;     // 1 .. seeds
    std::int64_t rand_seed = 0;
};

/// One simulation: a wind seen at a yaw misalignment.
struct DlcCase {
    std::string id;     // dlc1.2_U11.0_s1_y-8
    std::string inflow; // the InflowWind file's stem: NTM_U11.0_s1_y-8
    DesignLoadCase dlc = DesignLoadCase::dlc1_2;
    std::size_t wind = 0; // into DlcTable::winds
    double yaw = 0;       // [deg]
    bool parked = false;
};

struct DlcTable {
    std::vector<DlcWind> winds; // each once, in order of first use
    std::vector<DlcCase> cases;
};

/// Throws diag::UsageError for a table that cannot be made.
DlcTable dlc_table(const DlcOptions& o);

std::string dlc_name(DesignLoadCase c);      // "1.2"
std::string wind_model_name(DlcWindModel m); // "NTM", "ETM", "EWM50"
double reference_speed(TurbineClass c);      // V_ref [m/s]
std::string class_name(const DlcOptions& o); // "IB"
/// The grid's width and height [m].
double grid_size(const DlcOptions& o);

} // namespace yamsc::analysis
