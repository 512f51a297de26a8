// `constraint rolling`: a disk rolling without slip on the ground plane. The
// contact point is the wheel's lowest point: from the centre, the radius along
// d = -n + (n.a) a normalised (n the ground's normal, a the axle). Rows: its
// height (contact kept), and the material velocity of the wheel there,
// v_centre + w x (contact - centre), along the ground axes across n.
#include "symbolic/constraints/registry.hpp"

namespace yamsc::symbolic {

KindRows rolling_rows(const model::Constraint& c, ConstraintContext& ctx) {
    model::FrameRef wheel;
    wheel.body = c.wheel;
    const FrameMotion f = ctx.motion(wheel);
    const auto normal = static_cast<std::size_t>(c.normal);
    const auto axle = static_cast<std::size_t>(c.axle);
    const Vec3 a{{f.R.m[0][axle], f.R.m[1][axle], f.R.m[2][axle]}};
    const GiNaC::ex na = a[normal];
    Vec3 d = na * a;
    d[normal] = d[normal] - 1;
    const GiNaC::ex radius = to_ginac(c.radius, ctx.symbols);
    const Vec3 rho = (radius / GiNaC::sqrt(1 - na * na)) * d;
    const Vec3 v = f.v + cross(f.w, rho);
    KindRows rows;
    if (c.contact == model::RollingContact::kept)
        rows.holonomic.push_back(f.r[normal] + rho[normal]);
    for (std::size_t i = 0; i < 3; ++i)
        if (i != normal) rows.speed.push_back(v[i]);
    return rows;
}

} // namespace yamsc::symbolic
