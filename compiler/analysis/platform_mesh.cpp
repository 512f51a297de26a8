#include "analysis/platform_mesh.hpp"

#include "model/load_kinds.hpp"
#include "model/mesh_channels.hpp"

#include <cmath>

namespace yamsc::analysis {

PlatformMesh platform_mesh(const model::LoadBlock& decl, const BlockContext& c) {
    const model::Model& m = *c.loaded.front.model;
    const runtime::ModelView& v = c.view;
    const int role = static_cast<int>(model::PlatformRole::platform);
    PlatformMesh p;
    const std::vector<std::string> outputs = model::mesh_output_names(m, decl, role);
    const std::vector<std::string> inputs = model::mesh_input_names(m, decl, role);
    for (int i = 0; i < model::mesh_frame_outputs; ++i)
        p.frame_outputs.push_back(index_in(v.output_names, outputs[static_cast<std::size_t>(i)]));
    for (int i = 0; i < model::mesh_frame_inputs; ++i)
        p.loads.push_back(index_in(v.input_names, inputs[static_cast<std::size_t>(i)]));
    // The view's outputs at zero: the frame's position is its first three.
    const std::vector<double> q(static_cast<std::size_t>(v.nq), 0.0);
    const std::vector<double> u(static_cast<std::size_t>(v.nu), 0.0);
    std::vector<double> y(static_cast<std::size_t>(v.ny), 0.0);
    v.outputs(0.0, q.data(), q.data(), u.data(), y.data());
    for (std::size_t i = 0; i < 3; ++i)
        p.origin_at_rest[i] = y[static_cast<std::size_t>(p.frame_outputs[i])];
    for (std::size_t i = 0; i < 9; ++i)
        p.axes_at_rest[i] = y[static_cast<std::size_t>(p.frame_outputs[9 + i])];
    return p;
}

std::array<double, 3> PlatformMesh::body_point(const std::array<double, 3>& global) const {
    std::array<double, 3> b{};
    for (std::size_t a = 0; a < 3; ++a)
        for (std::size_t i = 0; i < 3; ++i)
            b[a] += axes_at_rest[3 * a + i] * (global[i] - origin_at_rest[i]);
    return b;
}

bool PlatformMesh::axes_are_ground() const {
    for (std::size_t a = 0; a < 3; ++a)
        for (std::size_t i = 0; i < 3; ++i)
            if (std::abs(axes_at_rest[3 * a + i] - (a == i ? 1.0 : 0.0)) > 1e-12) return false;
    return true;
}

BoundWater bound_water(const model::LoadBlock& decl, const BlockContext& c) {
    auto value = [&](model::PlatformRole r) -> std::optional<double> {
        const std::string& name = decl.role(r);
        if (name.empty()) return std::nullopt;
        return parameter(c, name);
    };
    return {value(model::PlatformRole::depth), value(model::PlatformRole::density),
            value(model::PlatformRole::gravity)};
}

} // namespace yamsc::analysis
