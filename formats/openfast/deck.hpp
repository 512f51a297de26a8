#pragma once
// An OpenFAST deck as `yamsc from-openfast` sees it: the ElastoDyn main file (found
// through the `.fst` when one is given), every entry of it classified as used, ignored
// (outputs, simulation control, two-bladed rotors) or unknown, and the values the model
// needs. Entries that change the dynamics but cannot be converted are reported as
// warnings at their line; unknown entries likewise. Nothing is dropped silently.
#include "diag/diagnostics.hpp"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace yamsc::openfast {

/// One `value  key  - comment` line of an OpenFAST input file.
struct DeckEntry {
    std::string key;   ///< as written
    std::string value; ///< the first token, quotes removed
    int line = 0, col = 0;
};

/// The ElastoDyn DOF switches, in ElastoDyn's order of DOFs.
const std::vector<std::string>& elastodyn_dof_flags();

/// Whether the switches `dofs` (flag -> on) make the tower flexible (a tower mode
/// DOF on: TwFADOF1, TwSSDOF1, TwFADOF2, TwSSDOF2), or the blades (FlapDOF1,
/// FlapDOF2, EdgeDOF). A flag not in `dofs` is off.
bool flexible_tower(const std::map<std::string, bool>& dofs);
bool flexible_blades(const std::map<std::string, bool>& dofs);

struct OpenFastDeck {
    std::shared_ptr<const diag::SourceFile> fst; ///< null when the ElastoDyn file was given
    std::shared_ptr<const diag::SourceFile> ed;
    std::string title;                       ///< line 2 of the ElastoDyn file
    std::map<std::string, bool> dofs;        ///< ElastoDyn flag name -> enabled
    std::map<std::string, double> num;       ///< numeric entries by canonical name (BlPitch1, ...)
    std::map<std::string, std::string> text; ///< numeric entries as written, for comments
    int blades = 3;
    int tower_nodes = 50, blade_nodes = 50;
    std::string tower_file;                ///< paths as resolved from the ElastoDyn file
    std::vector<std::string> blade_files;  ///< one per blade
    std::optional<double> tmax, dt;        ///< the `.fst` run, for the model's comment
    std::optional<int> method;             ///< ElastoDyn's integrator (1 RK4, 2 AB4, 3 ABM4)
    std::optional<int> mod_coupling;       ///< the glue's coupling (1 loose, 2 and 3 tight)
    std::optional<int> interp_order;       ///< its extrapolation of inputs (1 linear, 2 quadratic)
    std::optional<double> fst_gravity;     ///< newer decks give gravity in the `.fst`
    std::optional<double> fst_air_density; ///< likewise the air density (AirDens)
    std::string fst_air_density_at;        ///< "file:line" of it
    /// The `.fst`'s module switches (CompInflow, CompAero, CompServo, ...) as written,
    /// with where they are, and the module files it names (InflowFile, AeroFile,
    /// ServoFile), resolved: what `from-openfast` turns into the rotor block
    /// (compiler/openfast/operation.hpp).
    std::map<std::string, DeckEntry> modules;
    std::map<std::string, std::string> module_files;
    /// A floating deck's loads the model declares as blocks (`load hydrodyn` with
    /// CompHydro 1, `load mooring` with CompMooring 1, MAP++, or 3, MoorDyn): their files,
    /// resolved (empty when the module is off), and the `.fst`'s water (OpenFAST
    /// v4: WtrDens, WtrDpth, MSL2SWL; nullopt in older decks).
    struct Offshore {
        std::string hydro_file, sea_state_file, mooring_file;
        std::optional<double> water_density, water_depth, msl2swl;
    } offshore;
    /// Entries read but without effect on the structural model (outputs, simulation
    /// control, glue-code settings, two-bladed rotors): (file name, "Key:line").
    std::vector<std::pair<std::string, std::string>> ignored;
    /// Where an entry is, for messages: "file:line".
    std::map<std::string, std::string> where;

    double operator[](const std::string& name) const { return num.at(name); }
};

/// Reads a `.fst` (and the ElastoDyn file it names) or an ElastoDyn main file.
/// Errors (missing or bad entries, unreadable files) and warnings (unknown or
/// unsupported entries) go to `diags`; nullopt after an error.
std::optional<OpenFastDeck> read_openfast_deck(const std::string& path, diag::Diagnostics& diags);

/// The entries of an OpenFAST input file (not its tables, not its OutList block).
std::vector<DeckEntry> scan_deck_entries(const diag::SourceFile& file);

} // namespace yamsc::openfast
