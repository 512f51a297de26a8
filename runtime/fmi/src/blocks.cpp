#include "yamsc/fmi/blocks.hpp"

#include "yamsc/load_block.hpp"
#include "yamsc/performance_table.hpp"
#include "yamsc/rotor_aero.hpp"

#include <stdexcept>
#include <utility>

namespace yamsc::fmi {
namespace {

double parameter(const std::vector<double>& params, int index, const std::string& block,
                 const char* role) {
    if (index < 0 || static_cast<std::size_t>(index) >= params.size())
        throw std::invalid_argument("rotor block '" + block + "': its " + role + " is parameter " +
                                    std::to_string(index) + " of " + std::to_string(params.size()));
    return params[static_cast<std::size_t>(index)];
}

std::shared_ptr<const runtime::LoadBlock> rotor_table(const RotorTablePlan& r,
                                                      const runtime::ModelView& base,
                                                      const std::string& resources,
                                                      const std::vector<double>& params) {
    const double radius = parameter(params, r.radius_parameter, r.name, "radius");
    const double density = parameter(params, r.density_parameter, r.name, "density");
    if (!(radius > 0) || !(density > 0))
        throw std::invalid_argument("rotor block '" + r.name +
                                    "': its radius and density must be positive");
    runtime::RotorAero a = runtime::bind_rotor_aero(
        base, runtime::read_performance_table(resources + r.table), radius, density, r.wind,
        r.pitch, r.thrust, r.torque, r.speed, r.hub_velocity);
    a.name = r.name;
    return runtime::rotor_table_block(std::move(a));
}

} // namespace

BlockHook block_hook(BlockPlan plan) {
    if (plan.rotor_tables.empty()) return {};
    return [plan = std::move(plan)](const runtime::ModelView& base, const std::string& resources,
                                    const std::vector<double>& params) {
        runtime::LoadBlocks blocks;
        // Each binds channels of the model itself: the views closed before it
        // keep the model's inputs and only append outputs (load_block.hpp).
        for (const RotorTablePlan& r : plan.rotor_tables)
            blocks.push_back(rotor_table(r, base, resources, params));
        return runtime::close_blocks(base, blocks);
    };
}

} // namespace yamsc::fmi
