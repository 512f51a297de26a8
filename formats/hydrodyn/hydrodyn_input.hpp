#pragma once
// HydroDyn's primary input file (OpenFAST v4/v5), read in the order HydroDyn's
// HydroDyn_ParseInput reads it: key/value entries ("1   PotMod  - ..."), vectors and
// 6x6 matrices of one row per line (AddF0, AddCLin, AddBLin, AddBQuad), tables under a
// row of column names and a row of units (axial coefficients, joints, cross sections,
// coefficient tables, members, fill groups, marine growth, member and joint outputs),
// then the OUTPUT CHANNELS up to the END line. Values as written (SI units); the file's
// relative paths stay relative to the file. Bad input: located errors and nullopt;
// options read but not modelled: warnings at their line.
// Rows keep `line`: their line in the file that holds them (for rows an '@' line
// brings in, the included file's numbering).
#include "aerodyn/lines.hpp"
#include "diag/diagnostics.hpp"

#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace yamsc::hydrodyn {

/// The largest count a table or list may announce (NJoints, NMembers, NBody, ...).
inline constexpr int max_rows = 100000;
/// The most bodies NBody may give (each adds 6 rows to the additional matrices).
inline constexpr int max_bodies = 100;
/// The most generalized DOFs NAddDOF may add to a body.
inline constexpr int max_added_dofs = 100;

enum class PotentialFlow { none = 0, wamit = 1, fit = 2 }; // PotMod

struct Joint {
    int id = 0;                       // JointID
    std::array<double, 3> position{}; // Jointxi, Jointyi, Jointzi [m]
    int axial_coefficient_id = 0;     // JointAxID
    int overlap = 0;                  // JointOvrlp
    int line = 0;
};

struct CrossSection {
    int id = 0;           // PropSetID
    double diameter = 0;  // PropD [m]
    double thickness = 0; // PropThck [m]
    int line = 0;
};

/// One row of the simple, depth-based or member-based tables (one member end for
/// the member-based table). MG: with marine growth.
struct Coefficients {
    double cd = 0, cd_mg = 0, ca = 0, ca_mg = 0, cp = 0, cp_mg = 0;
    double ax_cd = 0, ax_cd_mg = 0, ax_ca = 0, ax_ca_mg = 0, ax_cp = 0, ax_cp_mg = 0;
    double cb = 1, cb_mg = 1; // buoyancy factors (OpenFAST v4; 1 when the row has none)
    bool mcf = false;         // "MCF" in place of Cp, CpMG: MacCamy-Fuchs (Cp = CpMG = 1)
};

struct DepthCoefficients {
    double depth = 0; // Dpth [m], as written
    Coefficients c;
    int line = 0;
};

struct MemberCoefficients {
    int member_id = 0;
    Coefficients end1, end2;
    int line = 0;
};

struct AxialCoefficient {
    int id = 0;                           // AxCoefID
    double cd = 0, ca = 0, cp = 0;        // AxCd, AxCa, AxCp
    int fd_mod = 0;                       // AxFDMod
    double vn_cutoff = -1, fd_lo_fsc = 1; // AxVnCOff, AxFDLoFSc (-1, 1: not given)
    int line = 0;
};

enum class CoefficientModel { simple = 1, depth = 2, member = 3 }; // MCoefMod

struct Member {
    int id = 0, joint1 = 0, joint2 = 0, section1 = 0, section2 = 0;
    double division_size = 0;       // MDivSize [m]
    int coefficient_model = 1;      // MCoefMod (1, 2 or 3: CoefficientModel)
    bool potential_flow = false;    // PropPot
    int section_kind = 1;           // MSecGeom: 1 circular, 2 rectangular (OpenFAST v4.1)
    double spin_orientation = 0;    // MSpinOrient [deg] (rectangular members)
    int hydrostatic_load_model = 0; // MHstLMod (OpenFAST v4)
    int line = 0;
};

struct FillGroup {
    std::vector<int> members;     // FillMList (FillNumM of them)
    double free_surface = 0;      // FillFSLoc [m]
    double density = 0;           // FillDens [kg/m^3] (0 when DEFAULT)
    bool density_default = false; // DEFAULT: the water's density
    int line = 0;
};

struct MarineGrowth {
    double depth = 0, thickness = 0, density = 0; // MGDpth, MGThck, MGDens
    int line = 0;
};

struct MemberOutput {
    int member_id = 0;
    std::vector<double> locations; // NodeLocs, normalized 0..1
    int line = 0;
};

struct Input {
    std::string path;
    std::shared_ptr<const diag::SourceFile> file;

    // FLOATING PLATFORM
    PotentialFlow pot_mod = PotentialFlow::none;
    int exctn_mod = 0, exctn_disp = 0;
    double exctn_cutoff = 0;                      // ExctnCutOff [Hz]
    int ptfm_y_mod = 0;                           // PtfmYMod (OpenFAST v4)
    double ptfm_ref_y_deg = 0, ptfm_y_cutoff = 0; // PtfmRefY [deg], PtfmYCutOff [Hz]
    int n_exctn_hdg = 0;                          // NExctnHdg
    int rdtn_mod = 0;
    double rdtn_tmax = 0, rdtn_dt = 0;
    bool rdtn_dt_default = false; // RdtnDT "default": the glue code's time step
    int n_body = 1, n_body_mod = 1;
    std::vector<std::string> pot_file; // as written, relative to the file
    std::vector<double> wamit_ulen, ptfm_ref_xt, ptfm_ref_yt, ptfm_ref_zt, ptfm_ref_zt_rot,
        ptfm_vol0, ptfm_cob_xt, ptfm_cob_yt; // NBody each (PtfmRefztRot in degrees)
    std::vector<int> n_add_dof;              // NAddDOF (OpenFAST v5; empty before)
    // 2ND-ORDER FLOATING PLATFORM FORCES
    int mn_drift = 0, newman_app = 0, diff_qtf = 0, sum_qtf = 0;
    // PLATFORM ADDITIONAL STIFFNESS AND DAMPING: NBodyMod 1: one (6 NBody) vector and
    // matrices; NBodyMod > 1: NBody 6-vectors and 6x6 matrices one after the other.
    int matrix_size = 6;                                  // rows (and columns) of one matrix
    int matrix_count = 1;                                 // how many matrices
    std::vector<double> add_f0;                           // matrix_count * matrix_size
    std::vector<double> add_c_lin, add_b_lin, add_b_quad; // matrix_count * size^2, row-major
    // STRIP THEORY OPTIONS
    int wave_disp = 0, am_mod = 0, hst_mod = 0; // HstMod: OpenFAST v5

    std::vector<AxialCoefficient> axial;
    std::vector<Joint> joints;
    std::vector<CrossSection> sections; // NPropSets, NPropSetsCyl (v4.1)
    int rectangular_sections = 0;       // NPropSetsRec rows (read, not kept)
    Coefficients simple;
    std::vector<DepthCoefficients> depth;
    std::vector<MemberCoefficients> member_coefficients;
    std::vector<Member> members;
    std::vector<FillGroup> fill_groups;
    std::vector<MarineGrowth> marine_growth;
    std::vector<MemberOutput> member_outputs;
    std::vector<int> joint_outputs; // JOutLst (NJOutputs of them)
    // OUTPUT
    bool hd_sum = false, out_all = false;
    int out_switch = 0;
    std::string out_fmt, out_sfmt;
    std::vector<std::string> out_channels; // OUTPUT CHANNELS, as written
    std::vector<int> out_channel_lines;

    /// Where an entry's value is (its key as in the file, any case), or no position.
    diag::Location location(const std::string& key) const;
    std::vector<std::pair<std::string, diag::Location>> entries; // every key read, in order
};

/// Reads a HydroDyn input file (file:line:col errors, warnings for the options that
/// are read but not modelled: PotMod 2, second-order forces, filled members, marine
/// growth, NBody > 1, NAddDOF, PtfmYMod 1, AMMod and HstMod other than 0, MacCamy-Fuchs
/// coefficients, rectangular members). Versions: the entries OpenFAST v4.0, v4.1 and v5
/// added are optional (a file of the version before them reads too).
/// Files an '@' line includes are read by `includes` (from the disk by default).
std::optional<Input>
read_hydrodyn_input(const std::shared_ptr<const diag::SourceFile>& file, diag::Diagnostics& diags,
                    const aerodyn::IncludeReader& includes = aerodyn::includes_from_disk());
/// The same, from a path (an unreadable file is an `io` error).
std::optional<Input> read_hydrodyn_input(const std::filesystem::path& path,
                                         diag::Diagnostics& diags);

} // namespace yamsc::hydrodyn
