#pragma once
// A wind field: the undisturbed wind velocity at any time and point, as
// InflowWind gives it to AeroDyn (IfW_FlowField_GetVelAcc). Ground axes
// throughout: x downwind at zero propagation direction, z up, the origin on the
// ground below the tower (InflowWind's global frame; heights from the ground).
//
// A model's `wind` input (V_wind, which the controller and the rotor table read)
// is the field's reference speed: its horizontal speed at the reference height
// (InflowWind's HWindSpeed, with a uniform file's gust). A block that samples
// the field at its nodes passes the V_wind it reads: the field then answers with
// its reference speed replaced by that value (as InflowWind's linearization
// perturbs HWindSpeed), so that a simulation, whose V_wind follows the field,
// sees the field itself, and `lin`/`trim` move the whole field with V_wind.
//
// Kinds of field (uniform_field.hpp, and full-field files later) register in
// src/wind/wind_kinds.cpp: an InflowWind WindType and the function that makes
// the field from the InflowWind file's entries.
#include <Eigen/Core>

#include <cstddef>

namespace yamsc::runtime {

class WindField {
public:
    virtual ~WindField() = default;
    /// The horizontal speed at the reference height at time t [m/s]: the V_wind
    /// the model's wind input carries.
    virtual double reference_speed(double t) const = 0;
    /// The wind velocity at time t and `position` (ground axes) [m/s], with the
    /// field's reference speed at t replaced by `reference_speed`.
    virtual Eigen::Vector3d velocity(double t, const Eigen::Vector3d& position,
                                     double reference_speed) const = 0;
    /// Whether the field is the same at every time (steady wind).
    virtual bool steady() const = 0;
    /// velocity() at n points at one time (a block's nodes), into `out`; a field
    /// with work per time (interpolating its samples) overrides it to do that once.
    virtual void velocities(double t, const Eigen::Vector3d* positions, std::size_t n,
                            double reference_speed, Eigen::Vector3d* out) const {
        for (std::size_t i = 0; i < n; ++i) out[i] = velocity(t, positions[i], reference_speed);
    }
};

} // namespace yamsc::runtime
