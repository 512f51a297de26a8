#include "model/mesh_channels.hpp"

namespace yamsc::model {

namespace {

Expr name_expr(const std::string& name, const Loc& loc, int primes = 0) {
    return Expr{Expr::Kind::name, loc, name, primes, {}};
}

Expr number(const char* text, const Loc& loc) {
    return Expr{Expr::Kind::number, loc, text, 0, {}};
}

/// `fn(target).c`: a ground component of a body's or point's kinematic vector.
Expr kinematic(const char* fn, const std::string& target, int c, const Loc& loc) {
    static const char* const axes[] = {"x", "y", "z"};
    Expr call{Expr::Kind::call, loc, fn, 0, {name_expr(target, loc)}};
    return Expr{Expr::Kind::component, loc, axes[c], 0, {std::move(call)}};
}

const Body& bound_body(const Model& m, const LoadBlock& block, int role) {
    return m.bodies[static_cast<std::size_t>(
        m.body_index(block.bound[static_cast<std::size_t>(role)]))];
}

std::vector<int> mode_dofs(const Body& b) {
    return b.flex ? b.flex->dofs : std::vector<int>{};
}

std::string prefix(const LoadBlock& block, int role) {
    return block.name + "." +
           load_kind_info(block.kind).roles[static_cast<std::size_t>(role)].name + ".";
}

std::string axis_point(const LoadBlock& block, int role, int axis) {
    static const char* const names[] = {"ex", "ey", "ez"};
    return prefix(block, role) + names[axis];
}

bool is_body_role(const LoadBlock& block, std::size_t r) {
    return load_kind_info(block.kind).roles[r].target == RoleTarget::body &&
           !block.bound[r].empty();
}

} // namespace

bool has_mesh(const LoadBlock& block) {
    for (std::size_t r = 0; r < block.bound.size(); ++r)
        if (is_body_role(block, r)) return true;
    return false;
}

std::vector<std::string> mesh_output_names(const Model& m, const LoadBlock& block, int role) {
    const std::string p = prefix(block, role);
    std::vector<std::string> names;
    for (const char* what : {"rx", "ry", "rz", "vx", "vy", "vz", "wx", "wy", "wz", "exx", "exy",
                             "exz", "eyx", "eyy", "eyz", "ezx", "ezy", "ezz"})
        names.push_back(p + what);
    const std::vector<int> dofs = mode_dofs(bound_body(m, block, role));
    for (int d : dofs) names.push_back(p + "q." + m.dofs[static_cast<std::size_t>(d)].name);
    for (int d : dofs) names.push_back(p + "qd." + m.dofs[static_cast<std::size_t>(d)].name);
    return names;
}

std::vector<std::string> mesh_input_names(const Model& m, const LoadBlock& block, int role) {
    const std::string p = prefix(block, role);
    std::vector<std::string> names;
    for (const char* what : {"fx", "fy", "fz", "mx", "my", "mz"}) names.push_back(p + what);
    for (int d : mode_dofs(bound_body(m, block, role)))
        names.push_back(p + "gen." + m.dofs[static_cast<std::size_t>(d)].name);
    return names;
}

void add_mesh_channels(Model& m) {
    for (const LoadBlock& block : m.loads)
        for (std::size_t r = 0; r < block.bound.size(); ++r) {
            if (!is_body_role(block, r)) continue;
            const int role = static_cast<int>(r);
            const Loc& loc = block.loc;
            const int body = m.body_index(block.bound[r]);
            const std::string name = m.bodies[static_cast<std::size_t>(body)].name;
            const std::vector<int> dofs = mode_dofs(m.bodies[static_cast<std::size_t>(body)]);
            const std::string doc = "load block " + block.name + " on " + name;
            for (int a = 0; a < 3; ++a) {
                Vec at{number("0", loc), number("0", loc), number("0", loc)};
                at[static_cast<std::size_t>(a)] = number("1", loc);
                m.points.push_back(Point{axis_point(block, role, a), body, at, loc});
            }
            const std::vector<std::string> out_names = mesh_output_names(m, block, role);
            std::vector<Expr> values;
            for (const char* fn : {"position", "velocity", "angular_velocity"})
                for (int c = 0; c < 3; ++c) values.push_back(kinematic(fn, name, c, loc));
            for (int a = 0; a < 3; ++a)
                for (int c = 0; c < 3; ++c)
                    values.push_back(
                        Expr{Expr::Kind::sub,
                             loc,
                             "",
                             0,
                             {kinematic("position", axis_point(block, role, a), c, loc),
                              kinematic("position", name, c, loc)}});
            for (int primes = 0; primes < 2; ++primes)
                for (int d : dofs)
                    values.push_back(
                        name_expr(m.dofs[static_cast<std::size_t>(d)].name, loc, primes));
            for (std::size_t i = 0; i < out_names.size(); ++i)
                m.outputs.push_back(Output{out_names[i], doc, values[i], -1, -1, loc});

            const std::vector<std::string> in_names = mesh_input_names(m, block, role);
            for (const std::string& n : in_names) m.inputs.push_back(Input{n, doc, 0, loc});
            auto in = [&](std::size_t i) { return name_expr(in_names[i], loc); };
            m.forces.push_back(Force{body,
                                     {number("0", loc), number("0", loc), number("0", loc)},
                                     body,
                                     {in(0), in(1), in(2)},
                                     loc});
            m.torques.push_back(Torque{body, body, {in(3), in(4), in(5)}, loc});
            for (std::size_t k = 0; k < dofs.size(); ++k)
                m.genforces.push_back(GenForce{dofs[k], in(mesh_frame_inputs + k), loc});
        }
}

} // namespace yamsc::model
