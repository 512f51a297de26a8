#pragma once
// The checked model: every name resolved, the body tree built and ordered
// (parents before children), joints reduced to elementary steps, loads attached
// to bodies. Expressions are still ast::Expr, but every name in them is known to
// be declared and allowed where it stands (see checker.hpp). Plain data.
#include "ast/ast.hpp"
#include "model/constraint_kinds.hpp"
#include "model/load_kinds.hpp"
#include "sid/sid.hpp"

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace yamsc::model {

using ast::Expr;
using Loc = diag::Location;
using Vec = std::array<Expr, 3>;

/// What a name denotes.
enum class NameKind { param, input, dof, body, point, time };

struct Param {
    std::string name, doc;
    std::optional<double> value; // default, evaluated
    Loc loc;
};

struct Input {
    std::string name, doc;
    int order = 0; // derivatives u', u'' ... that are inputs too
    Loc loc;
};

struct Dof {
    std::string name, doc;
    Loc loc;
};

/// One elementary motion of a joint, applied in the current (moving) frame.
/// `node` moves to a node of the parent's flexible body and follows its elastic
/// displacement and rotation (paper section 4.4, Appendix D2).
struct Step {
    enum class Kind { offset, translate, rotate, node };
    Kind kind = Kind::offset;
    Vec vector;          // offset: the displacement; translate/rotate: the axis (not normalised)
    int axis_index = -1; // 0..2 when the axis is a signed coordinate axis, else -1
    int axis_sign = 1;
    Expr arg;      // translate/rotate: distance or angle, a function of q, u, t, p
    int node = -1; // node: index into the parent's SID nodes
    /// node: rotation matrices of the slopes (`exact`, the default), or the rotation
    /// nearest to I + skew(psi q) (`small`)
    bool exact_rotation = false;
    /// node, exact rotation: the axes (0 x, 1 y, 2 z) in the order the slope rotations
    /// apply, each about the frame the previous one left (`exact` = `exact_xyz`).
    std::array<int, 3> rotation_order{{0, 1, 2}};
    Loc loc;
};

/// The elastic description of a flexible body: its SID reduced to the modes in use,
/// mode k driven by DOF dofs[k].
struct Flexible {
    std::shared_ptr<const sid::Sid> sid;
    std::vector<int> dofs;
    int taylor = 1;          // order of the shape-integral expansion used (0 or 1)
    std::string description; // where the data came from, for dumps and headers
    /// `symbolic modes`: every non-zero entry of the SID is the parameter named by
    /// shape_parameter_name(); the SID holds their defaults (NaN: no default).
    bool symbolic = false;
    std::vector<int> sid_modes; // index in the original SID of each mode kept
    /// Per SID node index cut by an output (`reaction_moment(tower.node(10))`): the
    /// inertia integrals of the part beyond it (beam::make_section_sid).
    std::map<int, std::shared_ptr<const sid::Sid>> sections;
};

/// The parameter of a SID entry of body `body` (1-based indices, as in SID files):
/// `tower_Me_1_1`, first-order terms `tower_Ct1_1_3_1` (row, column, mode), node
/// terms `tower_n50_phi_1_1`, the mass `tower_mass`. Symmetric blocks (J, Me, Ke, De)
/// name (i, j) and (j, i) alike, smaller index first.
std::string shape_parameter_name(const std::string& body, const std::string& term, int i, int j,
                                 int k = -1, int node_id = -1);

struct Body {
    enum class Kind { rigid, flexible };
    std::string name;
    Kind kind = Kind::rigid;
    int parent = -1;         // index into Model::bodies, -1 for ground
    std::vector<Step> steps; // from the parent's origin to this body's frame
    Expr mass;
    Vec com;                      // centre of mass in body axes
    std::array<Expr, 6> inertia;  // about the COM: Ixx, Iyy, Izz, Ixy, Iyz, Ixz (tensor entries)
    std::optional<Flexible> flex; // kind == flexible
    Loc loc;
};

/// A point fixed in a body.
struct Point {
    std::string name;
    int body = -1;
    Vec at;
    Loc loc;
};

/// A force on a body at a point (body axes), components in a frame (-1: ground).
struct Force {
    int body = -1;
    Vec at;
    int frame = -1;
    Vec value;
    Loc loc;
};

struct Torque {
    int body = -1;
    int frame = -1;
    Vec value;
    Loc loc;
};

struct Spring {
    int dof = -1;
    std::optional<Expr> stiffness, damping;
    Loc loc;
};

struct GenForce {
    int dof = -1;
    Expr value;
    Loc loc;
};

struct Output {
    std::string name, doc;
    Expr value;     // scalar; may use position(), velocity(), angular_velocity() of bodies/points
    int frame = -1; // frame of kinematic vectors (-1: ground)
    int frame_node = -1; // >= 0: that SID node's frame of flexible body `frame` instead
    Loc loc;
};

/// `external force|torque|genforce ... = name(args)`: a load a C function of the
/// user computes from the arguments (docs/language.md). with_external_channels()
/// turns it into hidden inputs (the results) and hidden outputs (the arguments).
struct External {
    enum class Kind { force, torque, genforce };
    std::string name; // the C function
    Kind kind = Kind::force;
    int body = -1;               // force, torque
    Vec at;                      // force: point of application, body axes
    int frame = -1;              // force, torque: components' frame (-1: ground)
    std::vector<int> dofs;       // genforce: one result per DOF
    std::vector<Expr> args;      // scalars of t, q, q', u, p and kinematics
    std::vector<int> arg_frames; // frame of each argument's kinematic vectors (-1: ground)
    bool without_jacobian = false;
    Loc loc; // the function's name in the declaration

    int results() const { return kind == Kind::genforce ? static_cast<int>(dofs.size()) : 3; }
};

/// `linearize { q = 0; psi' = Omega }`: the operating point of the linear model.
/// One value per DOF, per DOF rate and per input channel (an input of order 2 has
/// the channels u, u', u''), in the order of Model::dofs and of the channels;
/// values not written are 0. Every value is an expression of parameters.
struct OperatingPoint {
    std::vector<Expr> q, qd, u;
    Loc loc;
};

/// `approx a, b order N`: the equations are replaced by their Taylor expansion
/// about 0 in these symbols (parameters, DOFs or inputs), truncated at total order
/// N in the group's symbols (paper sections 4.5-4.6).
struct Approximation {
    struct Symbol {
        std::string name;
        NameKind kind = NameKind::param; // param, dof or input
        int index = 0;                   // into Model::params, dofs or inputs
        Loc loc;
    };
    std::vector<Symbol> symbols;
    int order = 1;
    Loc loc;
};

/// `initial { q = 2; psi' = 1.05 }`: the default initial state of `yamsc sim` (the
/// command's --ic overrides single values). One value per DOF and per DOF rate, in the
/// order of Model::dofs; values not written are 0. Every value is an expression of
/// parameters.
struct InitialState {
    std::vector<Expr> q, qd;
    Loc loc;
};

/// `load KIND NAME { role = name ... }`: a load block the runtime closes around the
/// model when it runs, its roles bound to the model's names. Run-time metadata:
/// the derivation and the generated code do not read it.
struct LoadBlock {
    LoadKind kind = LoadKind::rotor_table;
    std::string name;
    // Per role of the kind (load_kinds.hpp): the name bound, "" if unbound.
    std::vector<std::string> bound;
    Loc loc, end; // the statement: `load` to its closing `}`

    template <class Role> const std::string& role(Role r) const {
        return bound[static_cast<std::size_t>(r)];
    }
};

/// A frame of the tree a constraint names: a body's frame (ground when body is -1), a
/// point fixed in a body (`at`, body axes; the body's axes), or the frame of a node of a
/// flexible body (as a joint on it would start).
struct FrameRef {
    int body = -1;
    int node = -1;         // >= 0: that SID node of flexible `body`
    std::optional<Vec> at; // a point's position in the body's axes
    std::string text;      // as written, for dumps
    Loc loc;
};

enum class LoopJoint { point, revolute, prismatic, weld };
enum class RollingContact { kept, by_tree };

/// One row of a constraint: its name (`closing.x`) and whether it is holonomic.
struct ConstraintRow {
    std::string name;
    bool holonomic = true;
};

/// `constraint KIND NAME { role = value ... }` checked: the fields of its kind's roles
/// (model/constraint_kinds.hpp) resolved; the others keep their defaults.
struct Constraint {
    ConstraintKind kind = ConstraintKind::loop;
    std::string name;
    // loop
    FrameRef a, b;
    LoopJoint joint = LoopJoint::point;
    int axis = 2;                                       // revolute, prismatic: 0, 1, 2 (x, y, z)
    std::array<bool, 3> components{{true, true, true}}; // position rows kept
    // relation, speed, prescribed
    Expr value;
    int coordinate = -1; // prescribed
    // rolling
    int wheel = -1;
    Expr radius;
    int axle = 1;
    int normal = 2;
    RollingContact contact = RollingContact::kept;
    std::vector<int> dependent;      // DOFs named `dependent`
    std::vector<ConstraintRow> rows; // holonomic rows first
    Loc loc, end;                    // the statement: `constraint` to its closing `}`
};

struct Model {
    std::string name, title;
    std::vector<std::string> files_read; // data files (SID, ElastoDyn), for digests and depfiles
    std::shared_ptr<const diag::SourceFile> source;
    std::vector<Param> params;
    std::vector<Input> inputs;
    std::vector<Dof> dofs;
    Vec gravity;              // ground axes; zeros if none
    std::vector<Body> bodies; // topological order: parent index < own index
    std::vector<Point> points;
    std::vector<Force> forces;
    std::vector<Torque> torques;
    std::vector<Spring> springs;
    std::vector<GenForce> genforces;
    std::vector<Output> outputs;
    std::vector<External> externals;
    std::optional<OperatingPoint> operating_point; // the `linearize` block, if any
    std::optional<InitialState> initial_state;     // the `initial` block, if any
    std::vector<Approximation> approximations;     // `approx` groups, in file order
    std::vector<LoadBlock> loads;                  // `load` blocks, in file order
    std::vector<Constraint> constraints;           // `constraint`s, in file order

    int body_index(const std::string& name) const;
    int point_index(const std::string& name) const;
};

/// The model the derivation sees: each external's results appended to the inputs
/// (channels named `name[i]`, after every declared channel), its load applied with
/// them, and its arguments appended to the outputs (named `name(i)`). The
/// pipeline moves those outputs into ir::System::externals after lowering.
Model with_external_channels(const Model& model);

/// A readable dump, for `yamsc --dump=model`.
std::string dump(const Model& model);

} // namespace yamsc::model
