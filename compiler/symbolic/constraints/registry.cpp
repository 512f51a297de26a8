#include "symbolic/constraints/registry.hpp"

#include "diag/errors.hpp"
#include "model/constraint_check.hpp"

#include <array>

namespace yamsc::symbolic {

using GiNaC::ex;

namespace {

struct Registered {
    model::ConstraintKind kind;
    ConstraintBuilder build;
};

const std::array<Registered, 5> registry{{
    {model::ConstraintKind::loop, &loop_rows},
    {model::ConstraintKind::relation, &relation_rows},
    {model::ConstraintKind::speed, &speed_rows},
    {model::ConstraintKind::rolling, &rolling_rows},
    {model::ConstraintKind::prescribed, &prescribed_rows},
}};

} // namespace

ConstraintBuilder constraint_builder(model::ConstraintKind kind) {
    for (const Registered& r : registry)
        if (r.kind == kind) return r.build;
    throw diag::InternalError("no builder for a kind of constraint");
}

FrameMotion ConstraintContext::motion(const model::FrameRef& ref) {
    FrameMotion out;
    out.R = Mat3::identity();
    if (ref.body < 0) return out;
    const auto b = static_cast<std::size_t>(ref.body);
    const FrameState* f = &frames[b];
    if (ref.node >= 0) {
        auto it = nodes_.find({ref.body, ref.node});
        if (it == nodes_.end()) {
            model::Step step;
            step.kind = model::Step::Kind::node;
            step.node = ref.node;
            step.exact_rotation = true;
            it = nodes_
                     .emplace(std::make_pair(ref.body, ref.node),
                              apply_step(frames[b], step, symbols, &model.bodies[b]))
                     .first;
        }
        f = &it->second;
    }
    out.R = f->R;
    out.r = f->r;
    out.w = f->R * f->w;
    if (!ref.at) {
        out.v = f->R * f->v;
        return out;
    }
    const Vec3 at = to_ginac(*ref.at, symbols);
    out.r = f->r + f->R * at;
    out.v = f->R * (f->v + cross(f->w, at));
    return out;
}

std::vector<ConstraintRow> derive_constraints(const model::Model& m, Symbols& symbols,
                                              const std::vector<FrameState>& frames) {
    ConstraintContext ctx(m, symbols, frames);
    std::vector<ConstraintRow> holonomic, speed;
    for (const model::Constraint& c : m.constraints) {
        const KindRows rows = constraint_builder(c.kind)(c, ctx);
        std::size_t h = 0, s = 0;
        const std::string source = model::constraint_source(m, c);
        for (std::size_t i = 0; i < c.rows.size(); ++i) {
            ConstraintRow row;
            row.name = c.rows[i].name;
            row.holonomic = c.rows[i].holonomic;
            row.source = source;
            row.dependent = i < c.dependent.size() ? c.dependent[i] : -1;
            if (row.holonomic) {
                if (h >= rows.holonomic.size()) break;
                row.phi = rows.holonomic[h++];
                row.r = symbols.time_derivative(row.phi, false);
            } else {
                if (s >= rows.speed.size()) break;
                row.r = rows.speed[s++];
            }
            row.r_t = symbols.explicit_time_derivative(row.r);
            (row.holonomic ? holonomic : speed).push_back(std::move(row));
        }
        if (h != rows.holonomic.size() || s != rows.speed.size() || h + s != c.rows.size())
            throw diag::InternalError("constraint '" + c.name +
                                      "': its builder's rows differ from its kind's");
    }
    holonomic.insert(holonomic.end(), speed.begin(), speed.end());
    return holonomic;
}

} // namespace yamsc::symbolic
