#include "analysis/scene_surfaces.hpp"

#include "aerodyn_input/rotor.hpp"
#include "diag/errors.hpp"
#include "model/load_kinds.hpp"

namespace yamsc::analysis {

std::vector<BodySurface> scene_surfaces(const model::Model& m, const std::string& aero) {
    using Role = model::BladeElementsRole;
    std::vector<BodySurface> surfaces;
    if (aero.empty()) return surfaces;
    for (const model::LoadBlock& decl : m.loads) {
        if (decl.kind != model::LoadKind::blade_elements) continue;
        std::vector<Role> blades;
        for (Role r : {Role::blade1, Role::blade2, Role::blade3})
            if (!decl.role(r).empty()) blades.push_back(r);
        diag::Diagnostics diags;
        const std::optional<aero::RotorInput> rotor =
            aerodyn_input::read_aerodyn_rotor(aero, static_cast<int>(blades.size()), diags);
        if (!rotor || diags.has_errors()) throw diag::UserError(diags.render());
        for (std::size_t k = 0; k < blades.size() && k < rotor->blades.size(); ++k) {
            BodySurface s;
            s.body = m.body_index(decl.role(blades[k]));
            for (const aero::BladeNode& n : rotor->blades[k])
                s.sections.push_back({n.span, n.chord, n.twist});
            surfaces.push_back(std::move(s));
        }
        if (!decl.role(Role::tower).empty() && !rotor->tower.empty()) {
            BodySurface s;
            s.body = m.body_index(decl.role(Role::tower));
            s.tube = true;
            s.elevations = true;
            for (const aero::TowerNode& n : rotor->tower)
                s.sections.push_back({n.elevation, n.diameter, 0.0});
            surfaces.push_back(std::move(s));
        }
    }
    return surfaces;
}

} // namespace yamsc::analysis
