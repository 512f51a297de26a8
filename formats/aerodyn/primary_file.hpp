#pragma once
// The AeroDyn v15 primary input file as OpenFAST v4/v5 write it, read in order as
// AeroDyn's ParsePrimaryFileInfo does, with the entries older files (OpenFAST v3)
// have instead: WakeMod {0, 1, 2 = DBEMT, 3}, AFAeroMod {1 steady, 2 unsteady},
// UAMod, SkewMod, SkewModFactor, FrozenWake, and lines newer versions added left
// out (BEM_Mod, Skew_Mod, SkewMomCorr, SkewRedistr_Mod, SectAvg, AoA34,
// IntegrationMethod, UAStartRad, UAEndRad, NacelleDrag, the hub, nacelle and tail
// fin sections) take AeroDyn's defaults. The older entries are mapped to the newer
// ones as AeroDyn maps them. File names are resolved against the file's folder.
// Options yamsc does not convert are warnings at their line; bad input gives
// located errors and nullopt.
#include "aerodyn/lines.hpp"

#include <optional>
#include <string>
#include <vector>

namespace yamsc::aerodyn {

/// A file the primary file names, resolved, and where it names it.
struct FileName {
    std::string path;
    diag::Location at;
};

/// A row of the tower table (TwrTI, TwrCb, TwrCp, TwrCa are 0 when the column is absent).
struct TowerRow {
    double elevation = 0, diameter = 0, cd = 0, ti = 0, cb = 0, cp = 0, ca = 0;
    diag::Location at;
};

struct PrimaryFile {
    std::shared_ptr<const diag::SourceFile> file;
    // General options
    std::optional<double> dt_aero; // DTAero; nullopt: "default" (the glue code's step)
    int wake_mod = 1;              // Wake_Mod (WakeMod 2 reads as 1 with DBEMT)
    int twr_potent = 0, twr_shadow = 0;
    bool twr_aero = false, cavit_check = false, nacelle_drag = false, comp_aa = false;
    // Environmental conditions; nullopt: "default" (the glue code's values)
    std::optional<double> air_density, kinematic_viscosity, speed_of_sound, patm, pvap;
    // Blade-element/momentum theory
    int bem_mod = 1, skew_mod = 1;
    bool skew_mom_corr = false;
    int skew_redistr_mod = 1;
    double skew_redistr_factor = 15.0 * 3.14159265358979323846 / 32.0;
    bool tip_loss = true, hub_loss = true, tan_ind = true, ai_drag = false, ti_drag = false;
    std::optional<double> ind_toler; // IndToler; nullopt: "default"
    int max_iter = 100;
    bool sect_avg = false;
    int dbemt_mod = 0;     // -1 frozen wake (FrozenWake = True in older files)
    double tau1_const = 4; // [s]
    // Unsteady airfoil aerodynamics
    bool aoa34 = true;
    int ua_mod = 0; // UA_Mod; 0 when the older AFAeroMod is 1
    bool flookup = true;
    int integration_method = 3;
    double ua_start_rad = 0, ua_end_rad = 1;
    // Airfoil information
    int af_tab_mod = 1;
    int in_col_alfa = 1, in_col_cl = 2, in_col_cd = 3, in_col_cm = 4, in_col_cpmin = 0;
    std::vector<FileName> airfoils; // AFNames (NumAFfiles)
    // Rotor and blades
    bool use_bl_cm = true;
    std::vector<FileName> blade_files; // ADBlFile(1..): max(3, number of blades) lines
    // Hub, nacelle, tail fin
    double vol_hub = 0, vol_nac = 0;
    bool tfin_aero = false;
    // Tower
    std::vector<TowerRow> tower; // NumTwrNds
    // Outputs (the node numbers AeroDyn writes BkNj... and TwNj... channels for)
    std::vector<int> blade_out_nodes, tower_out_nodes; // BlOutNd, TwOutNd (NBlOuts, NTwOuts)
    std::vector<std::string> out_list;                 // OutList, as written

    /// Where each entry read is, by its key as written ("Wake_Mod" -> file:line:col);
    /// location() looks a key up ignoring case (the file without a line if absent).
    std::vector<std::pair<std::string, diag::Location>> where;
    diag::Location location(const std::string& key) const;
};

/// Reads the primary file `file`; `blades` is the number of blades (the file gives
/// max(3, blades) ADBlFile lines). '@' lines include files through `includes`.
std::optional<PrimaryFile> read_primary_file(const std::shared_ptr<const diag::SourceFile>& file,
                                             int blades, diag::Diagnostics& diags,
                                             const IncludeReader& includes = includes_from_disk());

} // namespace yamsc::aerodyn
