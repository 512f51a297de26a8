#pragma once
// WAMIT's numeric output files as HydroDyn reads them (PotMod 1, PotFile):
//   .1    radiation:    PER I J A [B]        (added mass and damping by period)
//   .3    excitation:   PER BETA I |X| PHASE Re(X) Im(X)   (per unit wave amplitude)
//   .hst  hydrostatics: I J C                (linear restoring)
// One row per line, values separated by blanks, tabs or commas (Fortran's list
// input; 'D' exponents accepted), blank lines skipped. PER < 0 is the
// zero-frequency limit and PER = 0 the infinite-frequency limit: WAMIT writes
// only A on those rows. Values are kept nondimensional, as written (WAMIT's
// ULEN, rho and g redimensionalize them: the analysis stage does, as HydroDyn).
// Bad input: located errors (file:line:col) and nullopt.
#include "diag/diagnostics.hpp"

#include <memory>
#include <optional>
#include <vector>

namespace yamsc::wamit {

/// The most rows a file may hold (the OC3 spar's .1 has about 2,300).
inline constexpr int max_rows = 4'000'000;
/// The largest mode index I, J: 6 per body and generalized modes.
inline constexpr int max_mode = 600;

struct RadiationRow {
    double period = 0; // PER [s]: < 0 zero frequency, 0 infinite frequency
    int i = 0, j = 0;  // modes, 1-based
    double added_mass = 0;
    std::optional<double> damping; // absent on the limits' rows
    int line = 0;
};

struct ExcitationRow {
    double period = 0;             // PER [s]
    double heading = 0;            // BETA [deg], the direction the waves travel toward
    int i = 0;                     // mode, 1-based
    double modulus = 0, phase = 0; // |X|, phase [deg]
    double re = 0, im = 0;         // Re(X), Im(X)
    int line = 0;
};

struct HydrostaticRow {
    int i = 0, j = 0;
    double restoring = 0;
    int line = 0;
};

template <class Row> struct Table {
    std::shared_ptr<const diag::SourceFile> file;
    std::vector<Row> rows; // in the file's order
};
using RadiationFile = Table<RadiationRow>;
using ExcitationFile = Table<ExcitationRow>;
using HydrostaticFile = Table<HydrostaticRow>;

/// Errors: a row with too few or too many values, a value that is not a
/// number, a mode index that is not a whole number from 1 to max_mode, a
/// positive period without damping, more than max_rows rows, no row at all.
std::optional<RadiationFile> read_radiation(const std::shared_ptr<const diag::SourceFile>& file,
                                            diag::Diagnostics& diags);
std::optional<ExcitationFile> read_excitation(const std::shared_ptr<const diag::SourceFile>& file,
                                              diag::Diagnostics& diags);
std::optional<HydrostaticFile>
read_hydrostatics(const std::shared_ptr<const diag::SourceFile>& file, diag::Diagnostics& diags);

} // namespace yamsc::wamit
