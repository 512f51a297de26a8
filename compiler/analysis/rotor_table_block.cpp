// `load rotor_table NAME { ... }` with `--aero TABLE`: the runtime's
// quasi-steady rotor block (yamsc/rotor_aero.hpp) on the channels the
// declaration binds.
#include "analysis/load_block_kinds.hpp"

#include <yamsc/performance_table.hpp>
#include <yamsc/rotor_aero.hpp>

namespace yamsc::analysis {

std::shared_ptr<const runtime::LoadBlock> build_rotor_table(const model::LoadBlock& decl,
                                                            const BlockContext& c) {
    using Role = model::RotorTableRole;
    const runtime::ModelView& v = c.view;
    runtime::RotorAero a;
    a.table = runtime::read_performance_table(c.options.aero);
    a.radius = parameter(c, decl.role(Role::radius));
    a.density = parameter(c, decl.role(Role::density));
    if (!(a.radius > 0) || !(a.density > 0))
        throw std::invalid_argument("rotor block '" + decl.name + "': its radius (" +
                                    decl.role(Role::radius) + ") and density (" +
                                    decl.role(Role::density) + ") must be positive");
    a.wind_input = index_in(v.input_names, decl.role(Role::wind));
    a.pitch_input =
        decl.role(Role::pitch).empty() ? -1 : index_in(v.input_names, decl.role(Role::pitch));
    a.thrust_input = index_in(v.input_names, decl.role(Role::thrust));
    a.torque_input = index_in(v.input_names, decl.role(Role::torque));
    a.speed_output = index_in(v.output_names, decl.role(Role::speed));
    a.hub_velocity_output = index_in(v.output_names, decl.role(Role::hub_velocity));
    a.name = decl.name;
    return runtime::rotor_table_block(std::move(a));
}

} // namespace yamsc::analysis
