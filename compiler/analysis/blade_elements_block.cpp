// `load blade_elements NAME { ... }` with `--aero AeroDyn.dat`: AeroDyn's blade
// elements (yamsc/aero/blade_element_block.hpp) on the model's hub and blades,
// reached through the declaration's mesh channels (model/mesh_channels.hpp).
#include "aerodyn_input/blade_elements.hpp"
#include "analysis/body_points.hpp"
#include "analysis/load_block_kinds.hpp"
#include "diag/errors.hpp"
#include "model/mesh_channels.hpp"

#include <yamsc/aero/blade_element_block.hpp>

#include <iostream>

namespace yamsc::analysis {

namespace {

std::vector<int> indices(const std::vector<std::string>& names,
                         const std::vector<std::string>& wanted) {
    std::vector<int> out;
    for (const std::string& w : wanted) out.push_back(index_in(names, w));
    return out;
}

} // namespace

aero::BladeElementSetup blade_element_channels(const model::LoadBlock& decl, const model::Model& m,
                                               const runtime::ModelView& v, const BlockOptions& o) {
    using Role = model::BladeElementsRole;
    std::vector<Role> blades;
    for (Role r : {Role::blade1, Role::blade2, Role::blade3})
        if (!decl.role(r).empty()) blades.push_back(r);

    aero::BladeElementSetup s;
    const model::LoadKindInfo& kind = model::load_kind_info(decl.kind);
    s.output_prefix = kind.output_name(decl.name, "");
    s.frozen_wake = o.frozen_wake;
    s.difference_step = o.difference_step;
    s.channels.wind = index_in(v.input_names, decl.role(Role::wind));
    s.channels.pitch =
        decl.role(Role::pitch).empty() ? -1 : index_in(v.input_names, decl.role(Role::pitch));
    s.channels.hub_outputs =
        indices(v.output_names, model::mesh_output_names(m, decl, static_cast<int>(Role::hub)));
    for (Role r : blades) {
        const int role = static_cast<int>(r);
        aero::BladeElementChannels::Blade b;
        b.outputs = indices(v.output_names, model::mesh_output_names(m, decl, role));
        b.loads = indices(v.input_names, model::mesh_input_names(m, decl, role));
        b.points = body_points(m.bodies[static_cast<std::size_t>(m.body_index(decl.role(r)))]);
        s.channels.blades.push_back(std::move(b));
    }
    if (!decl.role(Role::tower).empty()) {
        const int role = static_cast<int>(Role::tower);
        aero::TowerChannels& t = s.channels.tower;
        t.outputs = indices(v.output_names, model::mesh_output_names(m, decl, role));
        t.loads = indices(v.input_names, model::mesh_input_names(m, decl, role));
        t.points =
            body_points(m.bodies[static_cast<std::size_t>(m.body_index(decl.role(Role::tower)))]);
    }
    return s;
}

std::shared_ptr<const runtime::LoadBlock> build_blade_elements(const model::LoadBlock& decl,
                                                               const BlockContext& c) {
    aero::BladeElementSetup s = aerodyn_input::with_aerodyn_rotor(
        blade_element_channels(decl, *c.loaded.front.model, c.view, c.options), c.options.aero,
        c.options.inflow_angle_tolerance, std::cerr);
    s.wind_field = c.wind_field;
    return aero::blade_element_block(std::move(s));
}

} // namespace yamsc::analysis
