#include "analysis/scene.hpp"

#include "analysis/body_points.hpp"
#include "diag/errors.hpp"
#include "model/scene_channels.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <map>

namespace yamsc::analysis {

namespace {

using vtk::CellKind;

/// The axes' length against the model's extent at the first row.
constexpr double axis_fraction = 0.05;

class Outputs {
public:
    Outputs(const runtime::SimulationResult& run) {
        for (int i = 0; i < run.ny; ++i)
            index_[run.columns[static_cast<std::size_t>(1 + run.nx + i)]] = i;
    }
    int at(const std::string& name) {
        const auto it = index_.find(name);
        if (it == index_.end())
            throw diag::InternalError("the scene's output '" + name + "' is not compiled");
        used_.push_back(it->second);
        return it->second;
    }
    std::vector<int> used() const {
        std::vector<int> u = used_;
        std::sort(u.begin(), u.end());
        u.erase(std::unique(u.begin(), u.end()), u.end());
        return u;
    }

private:
    std::map<std::string, int> index_;
    std::vector<int> used_;
};

void add_cell(vtk::Cells& cells, std::vector<std::int64_t> points, int part, CellKind kind) {
    cells.connectivity.insert(cells.connectivity.end(), points.begin(), points.end());
    cells.offsets.push_back(static_cast<std::int64_t>(cells.connectivity.size()));
    cells.part.push_back(part);
    cells.kind.push_back(kind);
}

runtime::BodyFrame frame_at(const Scene::BodySource& b, const double* q, const double* y) {
    runtime::BodyFrame f;
    for (int c = 0; c < 3; ++c) f.r[c] = y[b.r + c];
    for (int a = 0; a < 3; ++a)
        for (int c = 0; c < 3; ++c) f.R(c, a) = y[b.e + 3 * a + c];
    for (int d : b.modes) f.q.push_back(q[d]);
    f.qd.assign(b.modes.size(), 0.0);
    f.v.setZero();
    f.w.setZero();
    return f;
}

/// The half sides of the uniform box with mass `m` and principal moments `I`.
Eigen::Vector3d half_sides(double m, const Eigen::Vector3d& I) {
    Eigen::Vector3d h;
    for (int i = 0; i < 3; ++i) {
        const double side2 = 6.0 * (I[(i + 1) % 3] + I[(i + 2) % 3] - I[i]) / m;
        h[i] = side2 > 0 ? 0.5 * std::sqrt(side2) : 0.0;
    }
    return h;
}

} // namespace

namespace {

/// Points around a section.
constexpr int section_points = 12;
/// An elliptic blade section's thickness against its chord.
constexpr double thickness_ratio = 0.2;

/// The body's point at `span` along z: between the two SID nodes around it.
runtime::BodyPoint point_at_span(const std::vector<runtime::BodyPoint>& nodes, double span) {
    if (span <= nodes.front().origin.z()) return nodes.front();
    for (std::size_t i = 1; i < nodes.size(); ++i)
        if (span <= nodes[i].origin.z()) {
            const double z0 = nodes[i - 1].origin.z(), z1 = nodes[i].origin.z();
            return runtime::blend(nodes[i - 1], nodes[i], z1 > z0 ? (span - z0) / (z1 - z0) : 0.0);
        }
    return nodes.back();
}

} // namespace

Scene::Scene(const model::Model& m, const runtime::SimulationResult& run,
             const std::vector<BodySurface>& surfaces) {
    using model::scene_output;
    Outputs out(run);
    const double* q = run.state_row(0);
    const double* y = run.output_row(0);
    for (const model::Body& b : m.bodies) {
        BodySource s;
        s.r = out.at(scene_output(b.name, "rx"));
        for (const char* w : {"ry", "rz"}) out.at(scene_output(b.name, w));
        s.e = out.at(scene_output(b.name, "exx"));
        for (const char* w : {"exy", "exz", "eyx", "eyy", "eyz", "ezx", "ezy", "ezz"})
            out.at(scene_output(b.name, w));
        if (b.flex) {
            s.modes = b.flex->dofs;
            s.nodes = body_points(b);
        }
        bodies_.push_back(std::move(s));
        topology_.part_names.push_back(b.name);
    }
    auto add_point = [&](PointSource p) {
        sources_.push_back(p);
        return static_cast<std::int64_t>(sources_.size() - 1);
    };
    auto fixed = [&](int body, const Eigen::Vector3d& local) {
        PointSource p;
        p.kind = PointSource::Kind::body_fixed;
        p.body = body;
        p.local = local;
        return add_point(p);
    };
    // The model's extent at the first row scales the axes.
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(HUGE_VAL), hi = -lo;
    auto extend = [&](const Eigen::Vector3d& p) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    };
    std::vector<runtime::BodyFrame> frames;
    for (const BodySource& b : bodies_) {
        frames.push_back(frame_at(b, q, y));
        extend(frames.back().r);
        for (const runtime::BodyPoint& n : b.nodes)
            extend(runtime::point_position(frames.back(), n));
    }
    std::vector<int> point_outputs;
    for (const model::Point& p : m.points) {
        if (!model::is_declared_point(p)) continue;
        const int first = out.at(model::scene_point_output(p.name, 'x'));
        out.at(model::scene_point_output(p.name, 'y'));
        out.at(model::scene_point_output(p.name, 'z'));
        extend(Eigen::Vector3d(y[first], y[first + 1], y[first + 2]));
        point_outputs.push_back(first);
    }
    const double extent = bodies_.empty() ? 0.0 : (hi - lo).norm();
    const double axis_length = extent > 0 ? axis_fraction * extent : 1.0;

    for (std::size_t i = 0; i < m.bodies.size(); ++i) {
        const model::Body& b = m.bodies[i];
        const int body = static_cast<int>(i);
        const std::int64_t origin = fixed(body, Eigen::Vector3d::Zero());
        for (int a = 0; a < 3; ++a)
            add_cell(topology_.lines, {origin, fixed(body, axis_length * Eigen::Vector3d::Unit(a))},
                     body, CellKind::frame_axis);
        if (b.flex) {
            // The deflected line: the origin, then the nodes in SID order.
            std::vector<std::int64_t> line{origin};
            for (std::size_t n = 0; n < bodies_[i].nodes.size(); ++n) {
                PointSource p;
                p.kind = PointSource::Kind::node;
                p.body = body;
                p.node = n;
                line.push_back(add_point(p));
            }
            if (line.size() > 1) add_cell(topology_.lines, line, body, CellKind::line);
            continue;
        }
        // The skeleton: to every child's joint and every declared point.
        for (std::size_t c = 0; c < m.bodies.size(); ++c)
            if (m.bodies[c].parent == body) {
                PointSource p;
                p.body = static_cast<int>(c);
                p.output = bodies_[c].r;
                add_cell(topology_.lines, {origin, add_point(p)}, body, CellKind::line);
            }
        const double mass = y[out.at(scene_output(b.name, "mass"))];
        Eigen::Vector3d com;
        for (int c = 0; c < 3; ++c)
            com[c] = y[out.at(scene_output(b.name, std::string("com") + "xyz"[c]))];
        Eigen::Matrix3d I;
        const double Ixx = y[out.at(scene_output(b.name, "Ixx"))],
                     Iyy = y[out.at(scene_output(b.name, "Iyy"))],
                     Izz = y[out.at(scene_output(b.name, "Izz"))],
                     Ixy = y[out.at(scene_output(b.name, "Ixy"))],
                     Iyz = y[out.at(scene_output(b.name, "Iyz"))],
                     Ixz = y[out.at(scene_output(b.name, "Ixz"))];
        I << Ixx, Ixy, Ixz, Ixy, Iyy, Iyz, Ixz, Iyz, Izz;
        if (!(mass > 0) || I.isZero()) continue;
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> principal(I);
        const Eigen::Vector3d h = half_sides(mass, principal.eigenvalues());
        if (h.isZero()) continue;
        const Eigen::Matrix3d E = principal.eigenvectors();
        std::int64_t corner[8];
        for (int k = 0; k < 8; ++k) {
            const Eigen::Vector3d s((k & 1) ? 1.0 : -1.0, (k & 2) ? 1.0 : -1.0,
                                    (k & 4) ? 1.0 : -1.0);
            corner[k] = fixed(body, com + E * h.cwiseProduct(s));
        }
        static const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                        {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
        for (const auto& f : faces)
            add_cell(topology_.polys, {corner[f[0]], corner[f[1]], corner[f[2]], corner[f[3]]},
                     body, CellKind::box);
    }
    // Surfaces: rings of points around each section, quadrilaterals between rings.
    for (const BodySurface& surface : surfaces) {
        const std::vector<runtime::BodyPoint>& nodes =
            bodies_[static_cast<std::size_t>(surface.body)].nodes;
        if (nodes.empty() || surface.sections.size() < 2) continue;
        std::vector<std::int64_t> previous;
        // Elevations (a tower's) from the ground: the body's origin where it starts.
        const double base =
            surface.elevations ? frames[static_cast<std::size_t>(surface.body)].r.z() : 0.0;
        for (const SurfaceSection& section : surface.sections) {
            sections_.push_back(point_at_span(nodes, section.span - base));
            std::vector<std::int64_t> ring;
            for (int k = 0; k < section_points; ++k) {
                const double a = 2.0 * M_PI * k / section_points;
                // Chord along the section's y (leading edge at -c/4), thickness along x.
                const double half = 0.5 * section.chord;
                Eigen::Vector2d p =
                    surface.tube ? Eigen::Vector2d(half * std::cos(a), half * std::sin(a))
                                 : Eigen::Vector2d(thickness_ratio * half * std::cos(a),
                                                   half * std::sin(a) + 0.25 * section.chord);
                // The twist turns the section about -z, as AeroDyn turns its nodes
                // (aero::BemRotor::node_axes_in_root).
                const double c = std::cos(section.twist), sn = -std::sin(section.twist);
                PointSource source;
                source.kind = PointSource::Kind::section;
                source.body = surface.body;
                source.node = sections_.size() - 1;
                source.local = Eigen::Vector3d(c * p.x() - sn * p.y(), sn * p.x() + c * p.y(), 0.0);
                ring.push_back(add_point(source));
            }
            if (!previous.empty())
                for (std::size_t k = 0; k < ring.size(); ++k) {
                    const std::size_t next = (k + 1) % ring.size();
                    add_cell(topology_.polys, {previous[k], previous[next], ring[next], ring[k]},
                             surface.body, CellKind::surface);
                }
            previous = std::move(ring);
        }
    }
    // Declared points: a marker each, and on a rigid body a skeleton line.
    int ground = -1;
    std::size_t k = 0;
    for (const model::Point& p : m.points) {
        if (!model::is_declared_point(p)) continue;
        PointSource s;
        s.body = p.body;
        s.output = point_outputs[k++];
        const std::int64_t at = add_point(s);
        if (p.body < 0 && ground < 0) {
            ground = static_cast<int>(topology_.part_names.size());
            topology_.part_names.push_back("ground");
        }
        const int part = p.body >= 0 ? p.body : ground;
        add_cell(topology_.verts, {at}, part, CellKind::point_marker);
        if (p.body >= 0 && !m.bodies[static_cast<std::size_t>(p.body)].flex) {
            const std::int64_t origin = fixed(p.body, Eigen::Vector3d::Zero());
            add_cell(topology_.lines, {origin, at}, part, CellKind::line);
        }
    }
    topology_.points = sources_.size();
    scene_outputs_ = out.used();
}

std::vector<double> Scene::points(const runtime::SimulationResult& run, std::size_t row) const {
    const double* q = run.state_row(row);
    const double* y = run.output_row(row);
    std::vector<runtime::BodyFrame> frames;
    frames.reserve(bodies_.size());
    for (const BodySource& b : bodies_) frames.push_back(frame_at(b, q, y));
    std::vector<double> xyz;
    xyz.reserve(3 * sources_.size());
    for (const PointSource& p : sources_) {
        Eigen::Vector3d r = Eigen::Vector3d::Zero();
        switch (p.kind) {
        case PointSource::Kind::output:
            r = Eigen::Vector3d(y[p.output], y[p.output + 1], y[p.output + 2]);
            break;
        case PointSource::Kind::body_fixed: {
            const runtime::BodyFrame& f = frames[static_cast<std::size_t>(p.body)];
            r = p.local.isZero() ? f.r : Eigen::Vector3d(f.r + f.R * p.local);
            break;
        }
        case PointSource::Kind::section: {
            const runtime::PointMotion motion =
                runtime::point_motion(frames[static_cast<std::size_t>(p.body)], sections_[p.node]);
            r = motion.r + motion.R * p.local;
            break;
        }
        case PointSource::Kind::node:
            r = runtime::point_position(frames[static_cast<std::size_t>(p.body)],
                                        bodies_[static_cast<std::size_t>(p.body)].nodes[p.node]);
            break;
        }
        xyz.insert(xyz.end(), {r.x(), r.y(), r.z()});
    }
    return xyz;
}

runtime::SimulationResult without_outputs(const runtime::SimulationResult& run,
                                          const std::vector<int>& columns) {
    std::vector<bool> drop(static_cast<std::size_t>(run.ny), false);
    for (int c : columns) drop[static_cast<std::size_t>(c)] = true;
    runtime::SimulationResult r;
    r.nx = run.nx;
    r.time = run.time;
    r.states = run.states;
    r.completed = run.completed;
    for (std::size_t i = 0; i < static_cast<std::size_t>(1 + run.nx); ++i)
        r.columns.push_back(run.columns[i]);
    for (int i = 0; i < run.ny; ++i)
        if (!drop[static_cast<std::size_t>(i)])
            r.columns.push_back(run.columns[static_cast<std::size_t>(1 + run.nx + i)]);
    r.ny = static_cast<int>(r.columns.size()) - 1 - r.nx;
    r.outputs.reserve(run.rows() * static_cast<std::size_t>(r.ny));
    for (std::size_t row = 0; row < run.rows(); ++row) {
        const double* y = run.output_row(row);
        for (int i = 0; i < run.ny; ++i)
            if (!drop[static_cast<std::size_t>(i)]) r.outputs.push_back(y[i]);
    }
    return r;
}

} // namespace yamsc::analysis
