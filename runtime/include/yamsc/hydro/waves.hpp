#pragma once
// Linear wave fields as OpenFAST's SeaState generates them (docs/hydrodynamics.md,
// "Waves"): still water, regular Airy waves and irregular JONSWAP/Pierson-Moskowitz
// seas on SeaState's frequency grid (WaveDOmega = 2 pi / WaveTMax), with its random
// draws (RANLUX, Box-Muller per frequency), so that a seed gives SeaState's
// realization. Kinematics are finite-depth Airy theory; the field is periodic in
// WaveTMax. Ground axes, z up, z = 0 at the still-water level (SWL).
#include <array>
#include <complex>
#include <memory>
#include <optional>
#include <vector>

namespace yamsc::runtime::hydro {

using Vec3 = std::array<double, 3>;

struct Water {
    double density = 1025, gravity = 9.80665, depth = 320 /*below SWL*/;
};

struct FlowAt {
    Vec3 velocity{}, acceleration{};
    double dynamic_pressure = 0;
};

/// One component of a linear field: the elevation is
/// Re(amplitude exp(i (omega t - wave_number (x cos(dir) + y sin(dir))))).
struct WaveComponent {
    double omega = 0, wave_number = 0;
    std::complex<double> amplitude;
};

/// The flow at one fixed point, tabulated on the field's time grid at construction
/// and interpolated in time as SeaState interpolates its grid (periodic cubic,
/// Catmull-Rom): O(1) a call.
class PointWaves {
public:
    virtual ~PointWaves() = default;
    virtual double elevation(double t) const = 0; // above SWL, at the point's (x, y)
    virtual FlowAt flow(double t) const = 0;
};

class WaveField : public std::enable_shared_from_this<WaveField> {
public:
    virtual ~WaveField() = default;
    virtual const Water& water() const = 0;
    virtual double elevation(double t, double x, double y) const = 0; // above SWL
    /// The undisturbed flow at p (ground axes, z up from SWL): zero above the surface
    /// (above SWL without stretching); the stretching is the field's.
    virtual FlowAt flow(double t, const Vec3& p) const = 0;

    /// The components (empty for still water), all travelling toward direction().
    virtual const std::vector<WaveComponent>& components() const;
    /// The heading the waves travel toward [rad], from x toward y.
    virtual double direction() const { return 0; }
    /// The period of the field in time (SeaState's WaveTMax after its FFT sizing), 0: none.
    virtual double period() const { return 0; }
    /// The time step of the grid the field is tabulated on (SeaState's WaveDT), 0: none.
    virtual double time_step() const { return 0; }
    /// A fixed point's flow, precomputed for cheap calls (points that do not move, as
    /// HydroDyn's WaveDisp = 0 nodes). The default evaluates flow(t, p) at each call.
    virtual std::shared_ptr<const PointWaves> at(const Vec3& p) const;
};

enum class WaveKind { still, regular, irregular };
enum class Stretching { none, vertical, extrapolation, wheeler };

struct WaveSettings {
    WaveKind kind = WaveKind::still;
    Water water;
    double height = 0;                // H (regular) or Hs (irregular)
    double period = 0;                // T (regular) or Tp (irregular)
    std::optional<double> peak_shape; // gamma; nullopt: SeaState's DEFAULT from Hs, Tp
    double direction = 0;             // rad, heading the waves travel toward, from x toward y
    double t_max = 600, dt = 0.25, low_cutoff = 0,
           high_cutoff = 500; // SeaState's WaveTMax, WaveDT, cut-offs [rad/s]
    int seed1 = 0;
    std::optional<int> seed2;
    bool ranlux = true;
    bool normal_amplitudes = true;
    std::optional<double> phase; // regular wave's phase (1P#), rad
    Stretching stretching = Stretching::none;
};

/// Throws std::invalid_argument for settings SeaState refuses (dt <= 0, t_max < dt,
/// a regular period off the grid, depth <= 0, ...).
std::shared_ptr<const WaveField> make_wave_field(const WaveSettings&);

/// Spectrum (one-sided, m^2 s / rad) SeaState uses for irregular waves.
double jonswap(double omega, double hs, double tp, double gamma);
double default_peak_shape(double hs, double tp);

/// The root k >= 0 of omega^2 = g k tanh(k h) (finite-depth linear dispersion).
double wave_number(double omega, double gravity, double depth);

/// SeaState's time grid: NStepWave >= WaveTMax / WaveDT, even, and twice a product of
/// primes up to 23 (its FFT's lengths); the field's period is NStepWave WaveDT.
int wave_time_steps(double t_max, double dt);

/// The complex amplitudes SeaState's Get_1Spsd_and_WaveElevC0 forms for a kind
/// (regular or irregular), index m at omega = m 2 pi / (n dt), m = 0 .. n/2.
std::vector<std::complex<double>> sea_state_amplitudes(const WaveSettings&, int n);

} // namespace yamsc::runtime::hydro
