#pragma once
// The abstract syntax tree of a `.mbd` file: what was written, where, nothing
// resolved. Produced by parse/, consumed by model/ (the checker). Plain data.
#include "diag/diagnostics.hpp"

#include <optional>
#include <string>
#include <vector>

namespace yamsc::ast {

using Loc = diag::Location;

/// An expression as written. Names are not resolved here.
struct Expr {
    enum class Kind {
        number,    // text: the literal as written ("1.5e-3"), kept exact
        name,      // text: identifier; primes: 0, 1 (q') or 2 (q'')
        neg,       // args[0]
        add,       // args[0] + args[1]
        sub,       // args[0] - args[1]
        mul,       // args[0] * args[1]
        div,       // args[0] / args[1]
        pow,       // args[0] ^ args[1]  (right associative)
        deg,       // args[0] deg  (degrees to radians)
        call,      // text: function name (sin, cos, ..., position, velocity, ...); args
        vector,    // (args[0], args[1], args[2]); also longer tuples
        component, // args[0].text  with text one of x, y, z
        // A section of a flexible body: text "tip" (args[0], the body name) or
        // "node" (args[0] the body name, args[1] the node number). The checker
        // resolves it: text is then the body's name, primes the SID node's index
        // (0-based), and args[0] the node's number in the SID (for dumps).
        section,
    };
    Kind kind = Kind::number;
    Loc loc;
    std::string text;
    int primes = 0;
    std::vector<Expr> args;
};

/// A rotation or translation axis: x, y, z with a sign, or a vector expression.
struct Axis {
    int index = 0;              // 0, 1, 2 for x, y, z (when !vec)
    int sign = 1;               // +1 or -1
    std::optional<Expr> vector; // set for `(a, b, c)` axes
    Loc loc;
};

/// `name` in a list of modes: `q`, `_` (skip this mode), or `mode -> dof`.
struct ModeEntry {
    std::string mode; // empty unless written `mode -> dof`
    std::string dof;  // "_" to skip
    Loc loc;
};

/// `(0: 5590.9, 1: 2536.3)`: station fraction -> value, piecewise linear.
struct TablePoint {
    Expr station;
    Expr value;
};

/// The right-hand side of `key = ...` inside a block.
struct Value {
    enum class Kind { expr, string, table, modes };
    Kind kind = Kind::expr;
    Expr expr;                     // kind == expr (vectors are Expr::Kind::vector)
    std::string str;               // kind == string, unescaped
    std::vector<TablePoint> table; // kind == table
    std::vector<ModeEntry> modes;  // kind == modes (key `modes` only)
    Loc loc;
};

struct Property {
    std::string key;
    Value value;
    Loc loc;
};

/// `mode fa1 x = 0.7004 z^2 + ...`: a polynomial shape in the normalised coordinate z.
struct ModeShape {
    std::string name;
    std::string direction; // x, y or z
    Expr shape;
    Loc loc;
};

/// `beam "file" format { ... }` or `beam { ... }`.
struct Beam {
    std::optional<std::string> file; // relative to the .mbd file
    std::string format;              // e.g. elastodyn_blade, elastodyn_tower; empty if inline
    std::vector<Property> properties;
    std::vector<ModeShape> mode_shapes;
    Loc loc;
};

struct RigidBody {
    std::string name;
    std::vector<Property> properties; // mass, com, inertia
    Loc loc;
};

struct FlexibleBody {
    std::string name;
    bool symbolic = false;            // `symbolic modes = (...)`
    std::vector<Property> properties; // sid, modes, taylor, ...
    std::optional<Beam> beam;
    Loc loc;
};

/// The parent side of a joint: `ground`, `body`, `body.tip`, `body.node(k)`.
struct PointRef {
    enum class Kind { origin, tip, node };
    std::string body;
    Kind kind = Kind::origin;
    std::optional<Expr> node; // kind == node
    Loc loc;
};

struct JointStep {
    enum class Kind { at, translate, rotate, free, option };
    Kind kind = Kind::at;
    Expr vector;                 // at: the offset
    Axis axis;                   // translate, rotate
    Expr arg;                    // translate, rotate: DOF name or expression
    std::vector<ModeEntry> dofs; // free: six DOF names (mode empty)
    Property option;             // option: `elastic_rotation = small|exact|exact_<order>`
    Loc loc;
};

struct Joint {
    PointRef parent;
    std::string child;
    Loc child_loc;
    std::vector<JointStep> steps;
    Loc loc;
};

struct Named {
    std::string name;
    Loc loc;
    std::string doc; // trailing comment on the declaring line, without '#'
};

struct Param {
    Named id;
    std::optional<Expr> value;
};

struct Input {
    Named id;
    int order = 0; // number of time derivatives that are inputs too
};

struct Force {
    std::string body;
    Loc body_loc;
    std::optional<Expr> at;
    std::optional<Named> frame; // `in frame`; default: the body's own frame
    Expr value;
    Loc loc;
};

struct Torque {
    std::string body;
    Loc body_loc;
    std::optional<Named> frame;
    Expr value;
    Loc loc;
};

struct Spring {
    Named dof;
    std::optional<Expr> stiffness;
    std::optional<Expr> damping;
    Loc loc;
};

struct GenForce {
    Named dof;
    Expr value;
    Loc loc;
};

struct Approx {
    std::vector<Named> symbols;
    int order = 1;
    Loc loc;
};

struct Assignment {
    std::string name;
    int primes = 0;
    Expr value;
    Loc loc;
};

struct Linearize {
    std::vector<Assignment> point;
    Loc loc;
};

/// `initial { q = 2; psi' = 1.05 }`: the default initial state of a simulation.
struct Initial {
    std::vector<Assignment> state;
    Loc loc;
};

struct Output {
    Named id;
    Expr value;
    std::optional<Named> frame; // `in frame` for kinematic vectors; default ground
    PointRef frame_point;       // `in tower.node(10)`: a node of a flexible frame
    Loc loc;
};

/// A named point fixed in a body: `point tip_pt on blade at (0, 0, L)`.
struct Point {
    Named id;
    std::string body;
    Loc body_loc;
    Expr at;
};

/// One argument of an external function: a scalar expression, `in FRAME` for the
/// components of position(), velocity() and angular_velocity() (default ground).
struct ExternalArg {
    Expr value;
    std::optional<Named> frame;
};

/// `external force on B at (x, y, z) in F = name(args...)`, `external torque on B in F = ...`
/// or `external genforce (q1, q2) = ...`: a load computed by a C function the user provides.
struct External {
    enum class Kind { force, torque, genforce };
    Kind kind = Kind::force;
    std::string body; // force, torque
    Loc body_loc;
    std::optional<Expr> at;     // force: the point, body axes
    std::optional<Named> frame; // force, torque: components' frame (default: the body)
    std::vector<Named> dofs;    // genforce
    Named function;
    std::vector<ExternalArg> args;
    bool without_jacobian = false; // `without jacobian`: derivatives by central differences
    Loc loc;
};

/// `load KIND NAME { role = value ... }`: a load block of the runtime closed around the
/// model when it runs (sim, lin, trim), its roles bound to the model's names. Run-time
/// metadata: the equations and the generated code do not see it.
struct Load {
    Named kind;
    Named id;
    std::vector<Property> roles;
    Loc loc; // the `load` keyword
    Loc end; // the closing `}`
};

/// `constraint KIND NAME { role = value ... }`: rows the coordinates (or their rates) must
/// satisfy, closing a loop of the tree, rolling without slip, relating or prescribing
/// coordinates. The checker knows the kinds (model/constraint_kinds.hpp).
struct Constraint {
    Named kind;
    Named id;
    std::vector<Property> roles;
    Loc loc; // the `constraint` keyword
    Loc end; // the closing `}`
};

struct ModelFile {
    std::shared_ptr<const diag::SourceFile> source;
    std::optional<Named> model; // the model's name
    std::string title;          // the string after the name, if any
    std::vector<Param> params;
    std::vector<Input> inputs;
    std::vector<Named> dofs; // in declaration order: the order of q
    std::optional<Expr> gravity;
    Loc gravity_loc;
    std::vector<RigidBody> rigid_bodies;
    std::vector<FlexibleBody> flexible_bodies;
    std::vector<Joint> joints;
    std::vector<Point> points;
    std::vector<Force> forces;
    std::vector<Torque> torques;
    std::vector<Spring> springs;
    std::vector<GenForce> genforces;
    std::vector<Approx> approximations;
    std::optional<Linearize> linearize;
    std::optional<Initial> initial;
    std::vector<Output> outputs;
    std::vector<External> externals;
    std::vector<Load> loads;
    std::vector<Constraint> constraints;
};

/// A readable dump of the tree, for `yamsc --dump=ast` and tests.
std::string dump(const ModelFile& file);
std::string to_string(const Expr& e);

} // namespace yamsc::ast
