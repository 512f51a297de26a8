#pragma once
// AeroDyn's BEM (BEM_Mod 1) on a rotor in any motion: the hub's frame and each
// blade node's position, velocity and orientation, as the structure gives them
// (the flexible blades' meshes, or the rigid rotor's kinematics). It forms
// AeroDyn's frames from the orientations (Calculate_MeshOrientation_
// NoSweepPitchTwist: the annulus frame without sweep, pitch and twist; the
// twist, pitch and elastic twist extracted as the node's angle about the
// blade), the disk-averaged relative wind, the skew angle and azimuths
// (DiskAvgValues), solves each element (bem.hpp) and integrates the rotor's
// loads about the hub (RtFld*).
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "yamsc/aero/bem.hpp"
#include "yamsc/aero/rotor_cache.hpp"
#include "yamsc/aero/rotor_input.hpp"

namespace yamsc::aero {

struct NodeResult {
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    // AeroDyn's element frame (orientationAnnulus for BEM_Mod 1): x along the
    // coned rotor axis (downwind), y opposite to the motion, z along the blade.
    Eigen::Vector3d x = Eigen::Vector3d::Zero(), y = Eigen::Vector3d::Zero(),
                    z = Eigen::Vector3d::Zero();
    double r_local = 0; // distance from the rotor axis [m]
    double vx = 0, vy = 0;
    ElementInput input;
    ElementSolution bem;
};

struct RotorResult {
    std::vector<std::vector<NodeResult>> blades; // [blade][node], AeroDyn's node order
    double fxh = 0, mxh = 0, power = 0;          // RtFldFxh [N], RtFldMxh [N m], RtFldPwr [W]
    double cp = 0, ct = 0, cq = 0, tsr = 0;      // RtFldCp, RtFldCt, RtFldCq, RtTSR
    double skew = 0;                             // RtSkew [rad]
    double v_avg_xh = 0;                         // RtVAvgxh [m/s]
    double r_max = 0;                            // largest local radius [m]
    // The nodes' loads and the integrals are those of their solutions; false:
    // only the roots and inductions are (BemRotor::evaluate without loads).
    bool loads = true;
};

/// Ground axes throughout; orientations as rotation matrices whose columns are
/// the frame's axes (the transposes of AeroDyn's orientation matrices).
struct RotorMotion {
    Eigen::Vector3d hub_position = Eigen::Vector3d::Zero();
    Eigen::Matrix3d hub_axes = Eigen::Matrix3d::Identity(); // x: the rotor axis, downwind
    Eigen::Vector3d hub_angular_velocity = Eigen::Vector3d::Zero();
    struct Blade {
        Eigen::Matrix3d root_axes = Eigen::Matrix3d::Identity(); // pitched root: z along the blade
        std::vector<Eigen::Vector3d> position, velocity;         // per AeroDyn node
        std::vector<Eigen::Matrix3d> axes; // per node: the root axes turned by the node's
                                           // curve and twist (and its elastic rotation)
        std::vector<Eigen::Vector3d> wind; // per node, if not empty: the wind there (the
                                           // tower's influence), else the uniform wind
    };
    std::vector<Blade> blades;
};

class BemRotor {
public:
    /// `hub_radius`: the blades' roots from the rotor axis (Prandtl's hub loss, zLocal).
    BemRotor(const RotorInput& input, double hub_radius);

    /// The rotor in uniform wind `wind` (ground axes) at `motion`; warm_start
    /// tries each node's previous inflow angle first (AeroDyn's constraint
    /// state). The result's storage is reused.
    /// Without `loads`, each node only its root and inductions (solve_inductions):
    /// a caller that replaces the inductions (DBEMT) needs no more; an evaluate
    /// with loads at a point kept without them completes them.
    const RotorResult& evaluate(const RotorMotion& motion, const Eigen::Vector3d& wind,
                                bool warm_start, bool loads = true);
    const RotorResult& result() const {
        return view_ == RotorCache::no_entry ? result_ : cache_.entry(view_);
    }
    /// The nodes' element inputs at `motion` (their frames, relative winds, radii,
    /// the disk's average wind, skew and TSR) without solving the BEM: the nodes'
    /// solutions and the rotor's integrals stay those of the last evaluate, and
    /// the next evaluate solves again. DBEMT's input at a step's start needs no
    /// more: it takes the last step's inflow angle (AeroDyn's z%phi).
    const RotorResult& element_inputs(const RotorMotion& motion, const Eigen::Vector3d& wind);

    /// Frozen wake, as OpenFAST linearizes AeroDyn (DBEMT_Mod -1, BEMT's
    /// computeFrozenWake): each node's induced velocities, a Vx and a' Vy, are
    /// held at those of the last evaluation; evaluate then solves no BEM and
    /// takes a = (a Vx)_0 / Vx, a' = (a' Vy)_0 / Vy at the node's new inflow
    /// (0 where that is 0), with no skew or low-TSR correction on top.
    void freeze_wake();
    void release_wake() { frozen_.clear(); }
    bool wake_frozen() const { return !frozen_.empty(); }
    /// The rotor's loads and coefficients (RtFld*) again from the nodes' element
    /// solutions, after a caller replaced them (dynamic inflow, unsteady
    /// airfoil coefficients); `motion` as given to the last evaluate.
    const RotorResult& integrate(const RotorMotion& motion);
    /// The nodes' loads and the integrals of an evaluate without loads.
    void complete_loads(const RotorMotion& motion) { finish(motion); }
    /// The nodes' results, for such a replacement.
    std::vector<std::vector<NodeResult>>& nodes() { return mutable_result().blades; }
    /// A caller replacing the nodes keeps its result with the solution just
    /// evaluated (rotor_cache.hpp: `generation` and `omega` are what that result
    /// depends on besides the solution) and recalls it instead of replacing
    /// them again. A warm-started evaluate at a motion and wind the cache holds
    /// returns the kept solution (its roots within the solver's tolerance of a
    /// new solve's).
    bool recall_applied(std::uint64_t generation, const std::vector<double>& omega) {
        const int kept = cache_.recall_applied(generation, omega);
        if (kept != RotorCache::no_entry) view_ = kept;
        return kept != RotorCache::no_entry;
    }
    void keep_applied(std::uint64_t generation, const std::vector<double>& omega) {
        materialize();
        const int kept = cache_.keep_applied(generation, omega, result_);
        if (kept != RotorCache::no_entry) mirror_ = kept;
    }

    /// Each later warm-started evaluate solves its nodes with a warm bracket
    /// (bem.hpp: solve_inductions with a BracketMemory): the roots agree with
    /// AeroDyn's search to the solver's tolerances. Time stepping asks for it.
    void use_warm_bracket() { warm_bracket_ = true; }

    /// A node's orientation relative to its blade's root, from the blade file:
    /// curve angle about y, then the twist about -z (AeroDyn's EulerConstruct(0, crv, -twist)).
    static Eigen::Matrix3d node_axes_in_root(const BladeNode& node);

private:
    const RotorInput& input_;
    double hub_radius_;
    BemOptions options_;
    std::vector<std::vector<double>> z_local_;
    std::vector<std::optional<IndexedPolar>> polars_; // per airfoil: its first table, indexed
    RotorResult result_;
    bool solved_ = false;
    struct Induced {
        double axial = 0, tangential = 0; // a Vx, a' Vy [m/s]
    };
    std::vector<std::vector<Induced>> frozen_; // [blade][node]; empty: the BEM is solved
    RotorCache cache_;
    // result() is the cache's entry view_ (a recall's, read in place) or, with
    // no_entry, result_. mirror_: the entry result_ equals bit for bit (a keep's
    // source, or the entry last copied into it), so that a recall of it copies
    // nothing; no_entry once result_ changes.
    int view_ = RotorCache::no_entry;
    int mirror_ = RotorCache::no_entry;
    void materialize();            // result_ holds result()'s numbers
    RotorResult& mutable_result(); // result_, to be changed
    bool warm_bracket_ = false;
    std::vector<std::vector<BracketMemory>> brackets_; // [blade][node]
    void set_inputs(const RotorMotion& motion, const Eigen::Vector3d& wind, bool warm_start);
    void finish(const RotorMotion& motion); // the loads (finish_element) and integrals
    void frozen_element(NodeResult& n, const Induced& induced) const;
};

} // namespace yamsc::aero
