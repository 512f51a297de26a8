#pragma once
// The last rotor solutions of a BemRotor, by the motion and wind they were
// solved at. A simulation step asks for the rotor at the same motion several
// times: the controller's measurement and the integrator's first stage at the
// start of a step, the discrete states' update at both ends of it. Each
// quasi-steady solution is kept with the exact motion and wind it came from
// (compared bit for bit) and, once the unsteady parts (element_dynamics.hpp)
// have replaced its nodes, with that result too, the state generation and the
// node angular velocities it used. A hit returns the stored numbers; anything
// else solves. The kept results stay where they are: a recall names the kept
// entry (entry()), for the rotor to read in place or to copy when it changes
// its result.
#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

namespace yamsc::aero {

struct RotorMotion;
struct RotorResult; // complete before a RotorCache is made (bem_rotor.hpp)

class RotorCache {
public:
    /// The entry of the quasi-steady solution at (motion, wind), if kept, else
    /// no_entry. An entry's result stays until a keep into it.
    int recall(const RotorMotion& motion, const Eigen::Vector3d& wind);
    /// `result`, just solved at the (motion, wind) of the last recall that
    /// missed, into the least recently used slot; returns its entry.
    int keep(const RotorResult& result);

    /// The current solution (the last recalled or kept) with the unsteady parts
    /// of state `generation` applied at the node angular velocities `omega`
    /// (flattened): its entry if kept, else no_entry.
    int recall_applied(std::uint64_t generation, const std::vector<double>& omega) const;
    /// Returns the entry kept, or no_entry when nothing is current.
    int keep_applied(std::uint64_t generation, const std::vector<double>& omega,
                     const RotorResult& result);

    static constexpr int no_entry = -1;
    /// The result an entry of recall, keep, recall_applied or keep_applied holds.
    const RotorResult& entry(int id) const;

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
