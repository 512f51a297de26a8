#pragma once
// HydroDyn's potential flow (PotMod 1) as the runtime's block: the WAMIT files
// PotFile names (.1, .3, .hst, relative to the HydroDyn file) read and
// redimensionalized as HydroDyn's WAMIT module does (rho, g, WAMITULEN), the
// radiation kernel (RdtnMod 1), the excitation table (ExctnMod 1) and the
// additional matrices. docs/hydrodynamics.md, "Potential flow".
#include "diag/diagnostics.hpp"
#include "hydrodyn/hydrodyn_input.hpp"
#include "wamit/wamit.hpp"
#include "yamsc/hydro/potential_flow.hpp"

#include <optional>

namespace yamsc::analysis {

/// The setup of one body (NBody 1, NBodyMod 1); its ports, origin and waves are the
/// caller's. `time_step` is the simulation's, for RdtnDT DEFAULT (0: none given).
/// Errors located in the HydroDyn file or the WAMIT file at fault; nullopt after one.
std::optional<runtime::hydro::PotentialFlowSetup>
potential_setup(const hydrodyn::Input& input, const runtime::hydro::Water& water,
                diag::Diagnostics& diags, double time_step = 0);

/// The WAMIT coefficients redimensionalized (HydroDyn's WAMIT_Init): what
/// potential_setup builds on, for tests.
struct WamitCoefficients {
    runtime::hydro::Mat6 added_mass_infinite{}, hydrostatic{};
    std::vector<double> omega;                    // ascending, with zero and "infinity"
    std::vector<runtime::hydro::Mat6> added_mass; // A(omega)
    std::vector<runtime::hydro::Mat6> damping;    // B(omega)
    runtime::hydro::ExcitationTable excitation;   // empty without a .3
};
std::optional<WamitCoefficients> wamit_coefficients(const wamit::RadiationFile& radiation,
                                                    const wamit::ExcitationFile* excitation,
                                                    const wamit::HydrostaticFile& hydrostatics,
                                                    double density, double gravity, double ulen,
                                                    diag::Diagnostics& diags);

} // namespace yamsc::analysis
