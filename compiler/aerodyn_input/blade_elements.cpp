#include "aerodyn_input/blade_elements.hpp"

#include "aerodyn_input/rotor.hpp"
#include "diag/errors.hpp"

#include <ostream>

namespace yamsc::aerodyn_input {

aero::BladeElementSetup with_aerodyn_rotor(aero::BladeElementSetup s,
                                           const std::filesystem::path& aerodyn,
                                           double inflow_angle_tolerance, std::ostream& warnings) {
    diag::Diagnostics diags;
    std::optional<aero::RotorInput> rotor =
        read_aerodyn_rotor(aerodyn, static_cast<int>(s.channels.blades.size()), diags);
    if (!rotor || diags.has_errors()) throw diag::UserError(diags.render());
    if (!diags.all().empty()) warnings << diags.render();
    s.rotor = std::move(*rotor);
    if (inflow_angle_tolerance > 0) s.rotor.inflow_angle_tolerance = inflow_angle_tolerance;
    return s;
}

} // namespace yamsc::aerodyn_input
