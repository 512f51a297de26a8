#include "analysis/fmu_blocks.hpp"

#include "diag/errors.hpp"
#include "model/load_kinds.hpp"

#include <algorithm>

namespace yamsc::analysis {

namespace {

/// A C++ string literal of `s`.
std::string literal(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

std::string parameter_index(const std::vector<std::string>& names, const std::string& name) {
    const auto at = std::find(names.begin(), names.end(), name);
    if (at == names.end())
        throw diag::InternalError("load block: '" + name + "' is not a parameter of the model");
    return std::to_string(at - names.begin());
}

std::string rotor_table(const model::LoadBlock& d, const std::vector<std::string>& params,
                        const std::string& table) {
    using Role = model::RotorTableRole;
    return "        {\n"
           "            ::yamsc::fmi::RotorTablePlan r;\n"
           "            r.name = " +
           literal(d.name) + ";\n            r.table = " + literal(table) +
           ";\n            r.radius_parameter = " + parameter_index(params, d.role(Role::radius)) +
           ";\n            r.density_parameter = " +
           parameter_index(params, d.role(Role::density)) +
           ";\n            r.wind = " + literal(d.role(Role::wind)) +
           ";\n            r.pitch = " + literal(d.role(Role::pitch)) +
           ";\n            r.thrust = " + literal(d.role(Role::thrust)) +
           ";\n            r.torque = " + literal(d.role(Role::torque)) +
           ";\n            r.speed = " + literal(d.role(Role::speed)) +
           ";\n            r.hub_velocity = " + literal(d.role(Role::hub_velocity)) +
           ";\n            plan.rotor_tables.push_back(r);\n        }\n";
}

} // namespace

std::string block_plan_source(const model::Model& m, const std::vector<std::string>& param_names,
                              const BlockOptions& b,
                              const std::vector<std::string>& resource_names) {
    if (b.aero.empty()) return "";
    std::string blocks;
    for (const model::LoadBlock& d : m.loads) {
        if (d.kind == model::LoadKind::blade_elements)
            throw diag::UsageError(
                "yamsc fmu: the blade elements of 'load blade_elements " + d.name +
                "' cannot be carried in a unit yet (their AeroDyn reader is the compiler's); "
                "a `load rotor_table` block can");
        if (d.kind == model::LoadKind::rotor_table)
            blocks += rotor_table(d, param_names, resource_names.front());
    }
    if (blocks.empty()) return "";
    return "    {\n        ::yamsc::fmi::BlockPlan plan;\n" + blocks +
           "        s.close_blocks = ::yamsc::fmi::block_hook(plan);\n    }\n";
}

} // namespace yamsc::analysis
