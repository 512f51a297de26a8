#include "model/flexible.hpp"

#include <algorithm>
#include <cmath>

namespace yamsc::model {

namespace {

bool symmetric_term(const std::string& term) {
    return term == "J" || term == "Me" || term == "Ke" || term == "De";
}

} // namespace

std::string shape_parameter_name(const std::string& body, const std::string& term, int i, int j,
                                 int k, int node_id) {
    if (term == "mass") return body + "_mass";
    if (symmetric_term(term) && j < i) std::swap(i, j);
    std::string name = body + "_";
    if (node_id >= 0) name += "n" + std::to_string(node_id) + "_";
    name += term + (k >= 0 ? "1" : "") + "_" + std::to_string(i + 1) + "_" + std::to_string(j + 1);
    if (k >= 0) name += "_" + std::to_string(k + 1);
    return name;
}

void for_each_block(const sid::Sid& s,
                    const std::function<void(const std::string&, int, const sid::Taylor&)>& f) {
    for (const auto& n : s.nodes) {
        f("origin", n.id, n.origin);
        f("phi", n.id, n.phi);
        f("psi", n.id, n.psi);
        f("AP", n.id, n.ap);
    }
    f("mdCM", -1, s.md_cm);
    f("J", -1, s.J);
    f("Ct", -1, s.Ct);
    f("Cr", -1, s.Cr);
    f("Me", -1, s.Me);
    f("Gr", -1, s.Gr);
    f("Ge", -1, s.Ge);
    f("Oe", -1, s.Oe);
    f("ksigma", -1, s.ksigma);
    f("Ke", -1, s.Ke);
    f("De", -1, s.De);
}

std::vector<ShapeParameter> shape_parameters(const std::string& body, const Flexible& flex) {
    std::vector<ShapeParameter> out;
    std::set<std::string> seen;
    auto add = [&](const std::string& name, double v) {
        if (!seen.insert(name).second) return;
        ShapeParameter p{name, std::nullopt};
        if (std::isfinite(v)) p.value = v;
        out.push_back(p);
    };
    const sid::Sid& s = *flex.sid;
    add(shape_parameter_name(body, "mass", 0, 0), s.mass);
    for_each_block(s, [&](const std::string& term, int node, const sid::Taylor& t) {
        for (int i = 0; i < t.nrow; ++i)
            for (int j = 0; j < t.ncol; ++j) {
                if (!t.m0.empty() && t.at0(i, j) != 0.0)
                    add(shape_parameter_name(body, term, i, j, -1, node), t.at0(i, j));
                if (flex.taylor < 1 || t.order < 1 || t.m1.empty()) continue;
                for (int k = 0; k < t.nq; ++k)
                    if (t.at1(i, j, k) != 0.0)
                        add(shape_parameter_name(body, term, i, j, k, node), t.at1(i, j, k));
            }
    });
    return out;
}

} // namespace yamsc::model
