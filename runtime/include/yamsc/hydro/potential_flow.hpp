#pragma once
// HydroDyn's potential-flow model (PotMod 1) for one rigid body, from WAMIT's
// coefficients: buoyancy and linear hydrostatic restoring (.hst), the
// infinite-frequency added mass (LoadBlock::added_mass), radiation memory by
// convolution of the impulse response K(t) (RdtnMod 1; its velocity history is
// the block's discrete state, as Conv_Radiation's) and first-order wave
// excitation from the .3 (ExctnMod 1, ExctnDisp 0), plus the additional matrices
// (additional_loads.hpp). Conventions: docs/hydrodynamics.md, "Potential flow".
#include <yamsc/hydro/additional_loads.hpp>
#include <yamsc/hydro/waves.hpp>

#include <complex>

namespace yamsc::runtime::hydro {

/// The excitation per unit wave amplitude, dimensional [N/m, N m/m], at the
/// WAMIT reference point in ground axes, tabulated as HydroDyn does: frequencies
/// ascending (a zero frequency holds the lowest positive one's values, the
/// infinite one zero), headings ascending.
struct ExcitationTable {
    std::vector<double> omega;               // [rad/s]
    std::vector<double> heading;             // [rad]
    std::vector<std::complex<double>> force; // [(f * heading.size() + h) * 6 + i]
    /// X at (omega, heading): linear in both, held at the ends of each range
    /// (throws std::invalid_argument outside the headings by more than 1e-6 rad).
    std::array<std::complex<double>, 6> at(double omega, double heading) const;
};

struct PotentialFlowSetup {
    Mat6 added_mass_infinite{};         // dimensional, about the WAMIT reference point, ground axes
    Mat6 hydrostatic{};                 // dimensional .hst restoring
    double displaced_volume = 0;        // PtfmVol0
    double cob_x = 0, cob_y = 0;        // PtfmCOBxt, PtfmCOByt (global)
    Vec3 reference{};                   // PtfmRefxt, yt, zt (global)
    double kernel_dt = 0;               // RdtnDT; 0: no radiation memory (RdtnMod 0)
    std::vector<Mat6> radiation_kernel; // K(k kernel_dt), k = 0 ...
    ExcitationTable excitation;         // empty: no excitation (ExctnMod 0)
    /// The waves (null: still water). The excitation is sum Re{X(w, dir) a exp(i w t)}
    /// over the field's components (WAMIT's phase is the field's: the elevation at the
    /// global origin is sum Re{a exp(i w t)}), tabulated once on the field's time grid
    /// and interpolated linearly in time, periodic with its period, as HydroDyn's
    /// WaveExctn; summed at each call when the field has no grid.
    std::shared_ptr<const WaveField> waves;
    Water
        water; // its density and gravity give the buoyancy rho g V0 (the matrices are dimensional)
    PlatformMatrices additional; // HydroDyn applies them with PotMod 1
    Vec3 origin_at_rest{};
    std::vector<int> frame_outputs, loads; // the body role's mesh (18 and 6)
    std::string output_prefix = "B1";
};

/// Outputs (ground axes, at the displaced reference point, as HydroDyn's
/// channels): <prefix>WvsFxi..WvsMzi (excitation), HdSFxi..HdSMzi (hydrostatics),
/// RdtFxi..RdtMzi (radiation memory), AddFxi..AddMzi (additional matrices).
std::shared_ptr<const LoadBlock> potential_flow_block(PotentialFlowSetup setup);

/// The radiation kernel Conv_Radiation computes: K(t) = (2/pi) int_0^wmax B(w)
/// cos(w t) dw by the trapezoid rule on N points, dw = pi / ((N - 1) dt), wmax =
/// pi / dt, N the odd number >= RdtnTMax / dt with (N - 1) / 2 a product of
/// the first nine primes; B linear between the given frequencies (ascending) and
/// held beyond. Throws std::invalid_argument when a frequency other than the
/// last exceeds pi / dt (RdtnDT too large) or dt <= 0.
std::vector<Mat6> radiation_kernel(const std::vector<double>& omega,
                                   const std::vector<Mat6>& damping, double dt, double t_max);

} // namespace yamsc::runtime::hydro
