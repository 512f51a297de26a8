#pragma once
// The last rotor solutions of a BemRotor, by the motion and wind they were
// solved at. A simulation step asks for the rotor at the same motion several
// times: the controller's measurement and the integrator's first stage at the
// start of a step, the discrete states' update at both ends of it. Each
// quasi-steady solution is kept with the exact motion and wind it came from
// (compared bit for bit) and, once the unsteady parts (element_dynamics.hpp)
// have replaced its nodes, with that result too, the state generation and the
// node angular velocities it used. A hit returns the stored numbers; anything
// else solves.
#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

namespace yamsc::aero {

struct RotorMotion;
struct RotorResult; // complete before a RotorCache is made (bem_rotor.hpp)

class RotorCache {
public:
    /// The quasi-steady solution at (motion, wind), if kept: copied into `result`.
    bool recall(const RotorMotion& motion, const Eigen::Vector3d& wind, RotorResult& result);
    /// `result`, just solved at the (motion, wind) of the last recall that
    /// missed, into the least recently used slot.
    void keep(const RotorResult& result);

    /// The current solution (the last recalled or kept) with the unsteady parts
    /// of state `generation` applied at the node angular velocities `omega`
    /// (flattened), if kept: copied into `result`.
    bool recall_applied(std::uint64_t generation, const std::vector<double>& omega,
                        RotorResult& result) const;
    void keep_applied(std::uint64_t generation, const std::vector<double>& omega,
                      const RotorResult& result);

    /// Nothing is current and nothing kept (a frozen wake, new options).
    void clear();

private:
    struct Slot {
        std::vector<double> key, omega;
        std::vector<RotorResult> quasi_steady, applied; // 1 element each, once used
        bool solved = false, has_applied = false;
        std::uint64_t generation = 0, used = 0;
    };
    std::vector<double> key_; // of the last recall
    std::array<Slot, 2>
        slots_; // a step's start (measured, integrated, updated) and its other point
    std::uint64_t clock_ = 0;
    int current_ = -1;
};

} // namespace yamsc::aero
