#include "model/model.hpp"

#include <sstream>

namespace yamsc::model {

namespace {

std::string vec(const Vec& v) {
    return "(" + ast::to_string(v[0]) + ", " + ast::to_string(v[1]) + ", " + ast::to_string(v[2]) +
           ")";
}

// The default order (x, y, z) prints as before, so existing dumps stay the same.
std::string order(const std::array<int, 3>& axes) {
    if (axes == std::array<int, 3>{{0, 1, 2}}) return "";
    std::string out = ", about ";
    for (std::size_t i = 0; i < 3; ++i)
        out += std::string(i ? ", " : "") + static_cast<char>('x' + axes[i]);
    return out;
}

std::string frame_name(const Model& m, int frame) {
    return frame < 0 ? "ground" : m.bodies[static_cast<std::size_t>(frame)].name;
}

} // namespace

std::string dump(const Model& m) {
    std::ostringstream out;
    out << "model " << m.name << "\n";
    for (const auto& p : m.params) {
        out << "  param " << p.name;
        if (p.value) out << " = " << *p.value;
        out << "\n";
    }
    for (const auto& i : m.inputs) out << "  input " << i.name << " order " << i.order << "\n";
    for (std::size_t i = 0; i < m.dofs.size(); ++i)
        out << "  dof " << i << " " << m.dofs[i].name << "\n";
    out << "  gravity " << vec(m.gravity) << "\n";
    for (const auto& b : m.bodies) {
        out << "  body " << b.name << " <- " << frame_name(m, b.parent) << "\n";
        if (b.flex) {
            const sid::Sid& sid = *b.flex->sid;
            out << "    flexible from " << b.flex->description << ": mass " << sid.mass << ", "
                << sid.nodes.size() << " nodes, taylor " << b.flex->taylor << ", modes (";
            for (std::size_t k = 0; k < b.flex->dofs.size(); ++k)
                out << (k ? ", " : "") << sid.mode_names[k] << " -> "
                    << m.dofs[static_cast<std::size_t>(b.flex->dofs[k])].name;
            out << ")\n";
        } else {
            out << "    mass " << ast::to_string(b.mass) << " com " << vec(b.com) << " inertia (";
            for (std::size_t i = 0; i < 6; ++i)
                out << (i ? ", " : "") << ast::to_string(b.inertia[i]);
            out << ")\n";
        }
        for (const auto& s : b.steps) {
            switch (s.kind) {
            case Step::Kind::offset:
                out << "    at " << vec(s.vector) << "\n";
                break;
            case Step::Kind::translate:
            case Step::Kind::rotate:
                out << "    " << (s.kind == Step::Kind::rotate ? "rotate " : "translate ")
                    << vec(s.vector) << " " << ast::to_string(s.arg) << "\n";
                break;
            case Step::Kind::node:
                out << "    node " << s.node << " of " << frame_name(m, b.parent)
                    << (s.exact_rotation ? " (exact rotation" + order(s.rotation_order) + ")"
                                         : std::string(" (small rotation)"))
                    << "\n";
                break;
            }
        }
    }
    for (const auto& p : m.points)
        out << "  point " << p.name << " on " << frame_name(m, p.body) << " at " << vec(p.at)
            << "\n";
    for (const auto& f : m.forces)
        out << "  force on " << frame_name(m, f.body) << " at " << vec(f.at) << " in "
            << frame_name(m, f.frame) << " = " << vec(f.value) << "\n";
    for (const auto& t : m.torques)
        out << "  torque on " << frame_name(m, t.body) << " in " << frame_name(m, t.frame) << " = "
            << vec(t.value) << "\n";
    for (const auto& s : m.springs) {
        out << "  spring " << m.dofs[static_cast<std::size_t>(s.dof)].name;
        if (s.stiffness) out << " stiffness " << ast::to_string(*s.stiffness);
        if (s.damping) out << " damping " << ast::to_string(*s.damping);
        out << "\n";
    }
    for (const auto& g : m.genforces)
        out << "  genforce " << m.dofs[static_cast<std::size_t>(g.dof)].name << " = "
            << ast::to_string(g.value) << "\n";
    for (const auto& o : m.outputs)
        out << "  output " << o.name << " = " << ast::to_string(o.value) << " in "
            << frame_name(m, o.frame)
            << (o.frame_node >= 0
                    ? ".node(" +
                          std::to_string(
                              m.bodies[static_cast<std::size_t>(o.frame)]
                                  .flex->sid->nodes[static_cast<std::size_t>(o.frame_node)]
                                  .id) +
                          ")"
                    : "")
            << "\n";
    for (const auto& e : m.externals) {
        out << "  external ";
        if (e.kind == External::Kind::genforce) {
            out << "genforce (";
            for (std::size_t i = 0; i < e.dofs.size(); ++i)
                out << (i > 0 ? ", " : "") << m.dofs[static_cast<std::size_t>(e.dofs[i])].name;
            out << ")";
        } else {
            out << (e.kind == External::Kind::force ? "force" : "torque") << " on "
                << frame_name(m, e.body);
            if (e.kind == External::Kind::force) out << " at " << vec(e.at);
            out << " in " << frame_name(m, e.frame);
        }
        out << " = " << e.name << "(";
        for (std::size_t i = 0; i < e.args.size(); ++i)
            out << (i > 0 ? ", " : "") << ast::to_string(e.args[i]) << " in "
                << frame_name(m, e.arg_frames[i]);
        out << ")" << (e.without_jacobian ? " without jacobian" : "") << "\n";
    }
    for (const LoadBlock& l : m.loads) {
        const LoadKindInfo& kind = load_kind_info(l.kind);
        out << "  load " << kind.name << " " << l.name << " {";
        for (std::size_t r = 0; r < l.bound.size(); ++r)
            if (!l.bound[r].empty()) out << " " << kind.roles[r].name << " = " << l.bound[r] << ";";
        out << " }\n";
    }
    for (const Constraint& c : m.constraints) {
        out << "  constraint " << constraint_kind_info(c.kind).name << " " << c.name << " {";
        if (c.kind == ConstraintKind::loop)
            out << " a = " << c.a.text << "; b = " << c.b.text << ";";
        if (c.kind == ConstraintKind::prescribed)
            out << " coordinate = " << m.dofs[static_cast<std::size_t>(c.coordinate)].name << ";";
        if (c.kind == ConstraintKind::rolling)
            out << " wheel = " << frame_name(m, c.wheel)
                << "; radius = " << ast::to_string(c.radius) << ";";
        if (!c.value.text.empty() || !c.value.args.empty())
            out << " value = " << ast::to_string(c.value) << ";";
        for (int d : c.dependent)
            out << " dependent " << m.dofs[static_cast<std::size_t>(d)].name << ";";
        out << " }\n";
        for (const ConstraintRow& r : c.rows)
            out << "    row " << r.name << (r.holonomic ? " holonomic" : " nonholonomic") << "\n";
    }
    return out.str();
}

} // namespace yamsc::model
