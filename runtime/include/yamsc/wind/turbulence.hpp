#pragma once
// A turbulent wind field of IEC 61400-1 Ed. 3's Kaimal model on a y-z grid, as
// TurbSim generates it for TurbModel IECKAI (modules/turbsim/src: TSsubs.f90,
// VelocitySpectra.f90, TS_FileIO.f90 CalcIECScalingParams), with yamsc's own random
// phases (docs/turbulence.md):
// - sigma_u: NTM I_ref (0.75 V_hub + 5.6), I_ref 0.16/0.14/0.12 for A/B/C; ETM
//   c I_ref (0.072 (V_ave/c + 3)(V_hub/c - 4) + 10), V_ave = 0.2 V_ref, V_ref 50,
//   42.5, 37.5 m/s for turbine classes 1-3; or a given intensity times V_hub;
//   sigma_v = 0.8 sigma_u, sigma_w = 0.5 sigma_u;
// - Lambda_1 = 0.7 min(z_hub, 60 m); Kaimal length scales L_u, L_v, L_w = 8.1, 2.7,
//   0.66 Lambda_1; one-sided S_k(f) = 4 sigma_k^2 L_k / V_hub / (1 + 6 f L_k / V_hub)^(5/3),
//   the same at every point;
// - u coherence exp(-12 sqrt((f r / V_hub)^2 + (0.12 r / L_c)^2)), L_c = 8.1 Lambda_1;
//   v and w have none (TurbSim's default SCMod2 = SCMod3 = NONE for IECKAI);
// - Veers' method: per frequency f_k = k / (N dt), k = 1 .. N/2, the coherence matrix's
//   Cholesky factor L, the Fourier coefficients sqrt(S(f_k) df / 2) sum_j L_ij e^(i theta_jk)
//   with uniform random phases theta, the Nyquist term set to zero, one inverse FFT of
//   length N per point and component (amplitude sqrt(2 S df) per frequency);
// - N and the times written as TurbSim chooses them; the mean u(z) added (power law or
//   neutral log law through (RefHt, URef)); ScaleIEC 1 or 2 as TurbSim's scaling.
#include <cstdint>
#include <functional>
#include <vector>

namespace yamsc::runtime {

enum class TurbulenceClass { A, B, C, intensity };
enum class TurbulenceModel { normal, extreme }; // NTM, ETM
enum class MeanProfile { power_law, logarithmic };
/// TurbSim's ScaleIEC: no scaling, every point scaled by the factor that gives the hub
/// point its target sigma, or every point scaled to the target sigma.
enum class SigmaScaling { none, hub, each_point };

struct TurbulenceSpec {
    int ny = 0, nz = 0;           // grid points across and up (>= 2)
    double width = 0, height = 0; // the grid's extent [m]
    double hub_height = 0;        // [m]
    double time_step = 0;         // [s]
    double analysis_time = 0;     // [s]
    double usable_time = 0;       // [s]: written, plus the grid width / V_hub
    bool periodic = false;        // usable time "ALL": N steps written, file id 8
    TurbulenceClass turbulence_class = TurbulenceClass::B;
    double intensity = 0; // for TurbulenceClass::intensity: sigma_u / V_hub
    TurbulenceModel model = TurbulenceModel::normal;
    int turbine_class = 1; // ETM's V_ref: 1, 2 or 3
    double etm_c = 2;      // [m/s]
    MeanProfile profile = MeanProfile::power_law;
    double ref_height = 0, ref_speed = 0; // the mean speed URef at RefHt
    double power_law = 0.2;
    double roughness = 0.03; // z0 of the log law [m]
    std::int64_t seed = 0;
    SigmaScaling scaling = SigmaScaling::none;
};

/// The IEC parameters of a spec (TurbSim's .sum "Turbulence Simulation Scaling").
struct IecParameters {
    double u_hub = 0;            // the mean speed at the hub [m/s]
    double sigma[3] = {};        // target standard deviations u, v, w [m/s]
    double lambda1 = 0;          // the turbulence scale parameter [m]
    double length[3] = {};       // Kaimal's integral scales L_u, L_v, L_w [m]
    double coherence_length = 0; // L_c [m]
    double coherence_decay = 12;
};

/// Throws std::invalid_argument for a spec that cannot be generated.
IecParameters iec_parameters(const TurbulenceSpec& s);
/// The one-sided Kaimal spectrum of component c (0 u, 1 v, 2 w) [m^2/s^2/Hz].
double kaimal_spectrum(const IecParameters& p, int component, double frequency);
/// The IEC coherence of u at a separation r [m].
double iec_coherence(const IecParameters& p, double frequency, double r);
/// The mean wind speed at height z [m/s].
double mean_speed(const TurbulenceSpec& s, double z);
/// TurbSim's PSF: the smallest n' >= n whose prime factors are all <= 23.
int small_prime_product(int n);

/// The field's layout, as TurbSim lays out its grid.
struct TurbulenceLayout {
    int steps_written = 0; // NumOutSteps
    int fft_steps = 0;     // NumSteps: the FFT's length, even
    double dy = 0, dz = 0, z_bottom = 0;
    bool hub_on_grid = false; // else an extra point at the hub, not written
};
TurbulenceLayout turbulence_layout(const TurbulenceSpec& s);

struct TurbulenceField {
    TurbulenceLayout layout;
    IecParameters iec;
    int ny = 0, nz = 0;
    /// u, v, w [m/s] (mean included) of the steps written:
    /// [((it * nz + iz) * ny + iy) * 3 + component], the .bts grid's order.
    std::vector<float> grid;
    /// The hub point's u, v, w over all fft_steps (before the mean of u), [it * 3 + c].
    std::vector<double> hub;
};

/// Calls `progress` with the fraction done (0 to 1) now and then.
TurbulenceField generate_turbulence(const TurbulenceSpec& s,
                                    const std::function<void(double)>& progress = {});

} // namespace yamsc::runtime
