#include "model/constraint_kinds.hpp"

namespace yamsc::model {

const std::vector<ConstraintKindInfo>& constraint_kinds() {
    using R = ConstraintRole;
    using V = RoleValue;
    static const ConstraintRoleInfo dependent{
        R::dependent, "dependent", V::dofs, false,
        "the DOF or DOFs (a list) the rows are solved for; others are chosen at the initial state"};
    static const std::vector<ConstraintKindInfo> kinds{
        {ConstraintKind::loop,
         "loop",
         {
             {R::a, "a", V::frame, true,
              "the first frame: a body, a point, ground, `body.tip` or `body.node(k)`"},
             {R::b, "b", V::frame, true, "the second frame, joined to the first"},
             {R::joint,
              "joint",
              V::word,
              false,
              "the joint closing the loop (default point)",
              {"point", "spherical", "revolute", "prismatic", "weld"}},
             {R::axis, "axis", V::axis, false,
              "the axis of a revolute or prismatic joint, in a's axes (x, y or z)"},
             {R::components, "components", V::components, false,
              "the position components kept, in a's axes (default (x, y, z))"},
             dependent,
         },
         "NAME.x, NAME.y, NAME.z: the position of a less that of b, in a's axes (those of "
         "`components`; for prismatic those across the axis); NAME.rx, NAME.ry, NAME.rz: the "
         "orientation (revolute: the components of b's axis across the axis, in a's axes; weld "
         "and prismatic: a_z.b_y, a_x.b_z, a_y.b_x). Holonomic"},
        {ConstraintKind::relation,
         "relation",
         {
             {R::value, "value", V::expression, true,
              "an expression of coordinates, t, inputs and parameters that is held at 0"},
             dependent,
         },
         "NAME: value = 0. Holonomic"},
        {ConstraintKind::speed,
         "speed",
         {
             {R::value, "value", V::expression, true,
              "an expression linear in the rates q' that is held at 0"},
             dependent,
         },
         "NAME: value = 0. Nonholonomic"},
        {ConstraintKind::rolling,
         "rolling",
         {
             {R::wheel, "wheel", V::body, true, "the wheel, a disk about its axle"},
             {R::radius, "radius", V::constant, true, "the wheel's radius"},
             {R::axle, "axle", V::axis, false, "the wheel's axle in its own axes (default y)"},
             {R::normal, "normal", V::axis, false, "the ground's up axis (default z)"},
             {R::contact,
              "contact",
              V::word,
              false,
              "kept: the contact point's height is a row; by_tree: the tree keeps the wheel "
              "on the ground (default kept)",
              {"kept", "by_tree"}},
             dependent,
         },
         "NAME.height (contact kept): the contact point's height, holonomic; NAME.x, NAME.y "
         "(the ground axes across the normal): the contact point's velocity, nonholonomic"},
        {ConstraintKind::prescribed,
         "prescribed",
         {
             {R::coordinate, "coordinate", V::dof, true, "the DOF the value is given to"},
             {R::value, "value", V::expression, true,
              "its value, an expression of t, inputs (declared `order 2`) and parameters"},
             dependent,
         },
         "NAME: coordinate - value = 0; its reaction is the force or torque that holds it. "
         "Holonomic"},
    };
    return kinds;
}

const ConstraintKindInfo& constraint_kind_info(ConstraintKind kind) {
    for (const ConstraintKindInfo& k : constraint_kinds())
        if (k.kind == kind) return k;
    return constraint_kinds().front(); // every kind has a row
}

} // namespace yamsc::model
