#pragma once
// AeroDyn's input files (the primary file, its blade files and airfoil files) as
// the blade-element code's aero::RotorInput: angles in radians, every switch as its
// enum, file names relative to the primary file's folder (as AeroDyn resolves them),
// the blade files' BlCrvAng computed where AeroDyn computes it, and the unsteady
// constants the airfoil files leave to AeroDyn computed as AirfoilInfo computes them
// (aerodyn_input/airfoil.hpp).
#include "aerodyn/primary_file.hpp"
#include "diag/diagnostics.hpp"
#include "yamsc/aero/rotor_input.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace yamsc::aerodyn_input {

/// What AeroDyn takes from the glue code when the primary file says "default"
/// (OpenFAST's AirDens, KinVisc, SpdSound of the .fst).
struct AeroDynDefaults {
    double air_density = 1.225;            // [kg/m^3]
    double kinematic_viscosity = 1.464e-5; // [m^2/s]
    double speed_of_sound = 335;           // [m/s]
};

/// The rotor of an AeroDyn primary file for `num_blades` blades (1 .. 3, or more
/// with as many ADBlFile lines): errors (located in the file that has them; a file
/// that cannot be read at the line that names it) and warnings go to `diags`;
/// nullopt after an error.
std::optional<aero::RotorInput> read_aerodyn_rotor(const std::filesystem::path& primary,
                                                   int num_blades, diag::Diagnostics& diags,
                                                   const AeroDynDefaults& defaults = {});

/// Every file the rotor of `primary` is read from, as AeroDyn resolves their
/// names: the primary file first, then its '@' includes, the blade files, the
/// airfoil files and theirs, each once (what a unit carries under resources/).
/// Empty after an error (in `diags`).
std::vector<std::string> aerodyn_files(const std::filesystem::path& primary, int num_blades,
                                       diag::Diagnostics& diags);

/// The conversion alone, from a primary file already read.
std::optional<aero::RotorInput> to_rotor_input(const aerodyn::PrimaryFile& primary, int num_blades,
                                               diag::Diagnostics& diags,
                                               const AeroDynDefaults& defaults = {});

} // namespace yamsc::aerodyn_input
