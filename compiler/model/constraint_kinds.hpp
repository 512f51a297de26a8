#pragma once
// The kinds of constraint a model may declare (`constraint KIND NAME { role = ... }`,
// docs/language.md, Constraints), the roles each accepts and the rows each gives.
// The checker (model/constraint_check.cpp) validates a declaration against this
// table into a model::Constraint; symbolic/constraints/<kind>.cpp builds its rows.
// A new kind is a ConstraintKind, a row here and its builder there.
#include <string>
#include <vector>

namespace yamsc::model {

enum class ConstraintKind { loop, relation, speed, rolling, prescribed };

/// Every role of every kind: each kind accepts some of them (ConstraintKindInfo::roles).
enum class ConstraintRole {
    a,          // loop: the first frame or point
    b,          // loop: the second
    joint,      // loop: point | spherical | revolute | prismatic | weld
    axis,       // loop: the axis of a revolute or prismatic joint, in a's axes
    components, // loop: the position components kept, in a's axes
    value,      // relation, speed, prescribed: the expression
    coordinate, // prescribed: the DOF
    wheel,      // rolling: the wheel's body
    radius,     // rolling
    axle,       // rolling: the wheel's axle, in its axes
    normal,     // rolling: the ground's up axis
    contact,    // rolling: kept | by_tree
    dependent,  // every kind: the DOF(s) the constraint's rows solve for
};

/// What a role's value is.
enum class RoleValue {
    frame,      // a body, a point, `ground`, `body.tip`, `body.node(k)`
    word,       // one of ConstraintRoleInfo::words
    axis,       // x, y or z, optionally negated
    components, // a list of x, y, z
    expression, // a scalar expression (what it may use depends on the kind)
    constant,   // a scalar expression of parameters
    dof,        // a DOF
    dofs,       // a DOF or a list of DOFs
    body,       // a body
};

struct ConstraintRoleInfo {
    ConstraintRole role;
    std::string name;
    RoleValue value;
    bool required;
    std::string what; // for messages and docs
    std::vector<std::string> words = {};
};

struct ConstraintKindInfo {
    ConstraintKind kind;
    std::string name;
    std::vector<ConstraintRoleInfo> roles;
    std::string rows; // what its rows are and their names, for docs and messages
};

const std::vector<ConstraintKindInfo>& constraint_kinds();
const ConstraintKindInfo& constraint_kind_info(ConstraintKind kind);

} // namespace yamsc::model
