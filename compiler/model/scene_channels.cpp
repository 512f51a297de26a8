#include "model/scene_channels.hpp"

namespace yamsc::model {

namespace {

Expr name_expr(const std::string& name, const Loc& loc) {
    return Expr{Expr::Kind::name, loc, name, 0, {}};
}

Expr number(const char* text, const Loc& loc) {
    return Expr{Expr::Kind::number, loc, text, 0, {}};
}

/// `position(target).c`.
Expr position(const std::string& target, int c, const Loc& loc) {
    static const char* const axes[] = {"x", "y", "z"};
    Expr call{Expr::Kind::call, loc, "position", 0, {name_expr(target, loc)}};
    return Expr{Expr::Kind::component, loc, axes[c], 0, {std::move(call)}};
}

const char* const xyz = "xyz";

} // namespace

std::string scene_output(const std::string& body, const std::string& what) {
    return "scene." + body + "." + what;
}

std::string scene_point_output(const std::string& point, char c) {
    // `point` is a word of the language: no body can be named so.
    return "scene.point." + point + "." + c;
}

bool is_declared_point(const Point& p) {
    return p.name.find('.') == std::string::npos;
}

void add_scene_channels(Model& m) {
    const std::vector<Point> declared = m.points;
    for (const Body& b : m.bodies) {
        const Loc& loc = b.loc;
        const int body = m.body_index(b.name);
        const std::string doc = "the scene of body " + b.name;
        auto add = [&](const std::string& what, Expr value) {
            m.outputs.push_back(
                Output{scene_output(b.name, what), doc, std::move(value), -1, -1, loc});
        };
        for (int c = 0; c < 3; ++c) add(std::string("r") + xyz[c], position(b.name, c, loc));
        for (int a = 0; a < 3; ++a) {
            const std::string axis_point = scene_output(b.name, std::string("e") + xyz[a]);
            Vec at{number("0", loc), number("0", loc), number("0", loc)};
            at[static_cast<std::size_t>(a)] = number("1", loc);
            m.points.push_back(Point{axis_point, body, at, loc});
            for (int c = 0; c < 3; ++c)
                add(std::string("e") + xyz[a] + xyz[c],
                    Expr{Expr::Kind::sub,
                         loc,
                         "",
                         0,
                         {position(axis_point, c, loc), position(b.name, c, loc)}});
        }
        if (b.kind != Body::Kind::rigid) continue;
        add("mass", b.mass);
        for (int c = 0; c < 3; ++c)
            add(std::string("com") + xyz[c], b.com[static_cast<std::size_t>(c)]);
        static const char* const inertia[] = {"Ixx", "Iyy", "Izz", "Ixy", "Iyz", "Ixz"};
        for (std::size_t i = 0; i < 6; ++i) add(inertia[i], b.inertia[i]);
    }
    for (const Point& p : declared) {
        if (!is_declared_point(p)) continue;
        for (int c = 0; c < 3; ++c)
            m.outputs.push_back(Output{scene_point_output(p.name, xyz[c]),
                                       "the scene: point " + p.name, position(p.name, c, p.loc), -1,
                                       -1, p.loc});
    }
}

} // namespace yamsc::model
