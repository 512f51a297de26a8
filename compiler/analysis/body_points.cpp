#include "analysis/body_points.hpp"

namespace yamsc::analysis {

namespace {

runtime::BodyPoint point_of(const sid::Node& node, int nq) {
    runtime::BodyPoint p;
    for (int i = 0; i < 3; ++i) p.origin[i] = node.origin.m0.empty() ? 0.0 : node.origin.at0(i, 0);
    const bool second_order = node.phi.order == 1 && !node.phi.m1.empty();
    for (int k = 0; k < nq; ++k) {
        Eigen::Vector3d phi, psi;
        for (int i = 0; i < 3; ++i) {
            phi[i] = node.phi.m0.empty() ? 0.0 : node.phi.at0(i, k);
            psi[i] = node.psi.m0.empty() ? 0.0 : node.psi.at0(i, k);
        }
        p.phi.push_back(phi);
        p.psi.push_back(psi);
    }
    if (second_order)
        for (int k = 0; k < nq; ++k)
            for (int j = 0; j < nq; ++j) {
                Eigen::Vector3d c;
                for (int i = 0; i < 3; ++i) c[i] = node.phi.at1(i, k, j);
                p.phi1.push_back(c);
            }
    if (!node.ap.m0.empty())
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) p.orientation(i, j) = node.ap.at0(i, j);
    return p;
}

} // namespace

std::vector<runtime::BodyPoint> body_points(const model::Body& body) {
    std::vector<runtime::BodyPoint> points;
    if (!body.flex || body.flex->symbolic || !body.flex->sid) return points;
    const sid::Sid& sid = *body.flex->sid;
    for (const sid::Node& node : sid.nodes) points.push_back(point_of(node, sid.nq));
    return points;
}

std::vector<double> spans(const std::vector<runtime::BodyPoint>& points) {
    std::vector<double> z;
    for (const runtime::BodyPoint& p : points) z.push_back(p.origin.z());
    return z;
}

} // namespace yamsc::analysis
