#pragma once
// SeaState's primary input file (OpenFAST v4/v5), read in the order SeaState's
// SeaSt_ParseInput reads it: environmental conditions ("default": the .fst's
// WtrDens, WtrDpth, MSL2SWL), the spatial grid, waves, second-order waves,
// constrained waves, current, MacCamy-Fuchs, output, then the OUTPUT CHANNELS up to
// the END line. Values as written (SI units, angles in degrees). Bad input: located
// errors and nullopt; options read but not modelled: warnings at their line.
#include "aerodyn/lines.hpp"
#include "diag/diagnostics.hpp"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace yamsc::seastate {

/// The most points NWaveElev and NWaveKin may give (SeaState allows 9).
inline constexpr int max_points = 9;
/// The largest grid count NX, NY, NZ may give.
inline constexpr int max_grid_nodes = 10000;

enum class WaveKind {
    still = 0,
    regular = 1,
    irregular = 2, // JONSWAP or Pierson-Moskowitz
    white_noise = 3,
    user_spectrum = 4,
    elevation_file = 5,
    kinematics_file = 6,
    components = 7
};
enum class Stretching { none = 0, vertical = 1, extrapolation = 2, wheeler = 3 };
enum class RandomGenerator { intrinsic, ranlux };

struct Input {
    std::string path;
    std::shared_ptr<const diag::SourceFile> file;

    // ENVIRONMENTAL CONDITIONS (nullopt: "default", the .fst's)
    std::optional<double> water_density, water_depth, msl2swl;
    // SPATIAL DISCRETIZATION
    double x_half_width = 0, y_half_width = 0;
    std::optional<double> z_depth; // nullopt: "default" (WtrDpth + MSL2SWL)
    int nx = 0, ny = 0, nz = 0;
    // WAVES
    WaveKind wave_mod = WaveKind::still;
    bool regular_user_phase = false;          // WaveMod "1P#"
    double wave_phase_deg = 0;                // the # of "1P#" [deg]
    Stretching stretching = Stretching::none; // WaveStMod
    int wave_current_mod = 0;                 // WvCrntMod (OpenFAST v5; 0 before)
    double wave_tmax = 0, wave_dt = 0, wave_hs = 0, wave_tp = 0;
    std::optional<double> peak_shape;       // WavePkShp; nullopt: DEFAULT
    double low_cutoff = 0, high_cutoff = 0; // WvLowCOff, WvHiCOff [rad/s]
    double wave_dir_deg = 0;
    int wave_dir_mod = 0;
    double wave_dir_spread = 0;
    int wave_n_dir = 1;
    double wave_dir_range = 0;
    int seed1 = 0;
    std::optional<int> seed2; // nullopt with RANLUX
    RandomGenerator generator = RandomGenerator::intrinsic;
    bool normal_amplitudes = false; // WaveNDAmp
    std::string wave_kin_file;      // WvKinFile, as written
    // 2ND-ORDER WAVES
    bool diff_qtf = false, sum_qtf = false; // WvDiffQTF, WvSumQTF
    double low_cutoff_diff = 0, high_cutoff_diff = 0, low_cutoff_sum = 0, high_cutoff_sum = 0;
    // CONSTRAINED WAVES
    int const_wave_mod = 0;
    double crest_hmax = 0, crest_time = 0, crest_xi = 0, crest_yi = 0;
    // CURRENT
    int curr_mod = 0;
    double curr_ssv0 = 0;
    std::optional<double> curr_ss_dir_deg; // nullopt: DEFAULT (the wave direction)
    double curr_ns_ref = 0, curr_nsv0 = 0, curr_ns_dir_deg = 0, curr_div = 0, curr_di_dir_deg = 0;
    // MacCamy-Fuchs
    double mcfd = 0;
    // OUTPUT
    bool sum_file = false; // SeaStSum
    int out_switch = 0;
    std::string out_fmt, out_sfmt;
    std::vector<double> wave_elev_x, wave_elev_y;           // NWaveElev points
    std::vector<double> wave_kin_x, wave_kin_y, wave_kin_z; // NWaveKin points
    std::vector<std::string> out_channels;                  // as written
    std::vector<int> out_channel_lines;

    /// Where an entry's value is (its key as in the file, any case), or no position.
    diag::Location location(const std::string& key) const;
    std::vector<std::pair<std::string, diag::Location>> entries; // every key read, in order
};

/// Reads a SeaState input file (file:line:col errors; warnings for WaveMod 3..7,
/// WaveDirMod 1, second-order waves, constrained waves, current, MacCamy-Fuchs).
/// Files an '@' line includes are read by `includes` (from the disk by default).
std::optional<Input>
read_seastate_input(const std::shared_ptr<const diag::SourceFile>& file, diag::Diagnostics& diags,
                    const aerodyn::IncludeReader& includes = aerodyn::includes_from_disk());
/// The same, from a path (an unreadable file is an `io` error).
std::optional<Input> read_seastate_input(const std::filesystem::path& path,
                                         diag::Diagnostics& diags);

} // namespace yamsc::seastate
