#include "analysis/fmu_blocks.hpp"

#include "aerodyn_input/rotor.hpp"
#include "analysis/load_block_kinds.hpp"

#include "diag/errors.hpp"
#include "model/load_kinds.hpp"

#include <algorithm>
#include <filesystem>

#include <yamsc/fmi/blade_elements.hpp>

namespace yamsc::analysis {

namespace {

/// A C++ string literal of `s`.
std::string literal(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        if (c == '\n')
            out += "\\n";
        else
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

/// The AeroDyn files under resources/aerodyn/, at their paths relative to
/// the deepest folder that holds them all.
void aerodyn_resources(const std::string& primary, int blades, UnitBlocks& u) {
    namespace fs = std::filesystem;
    diag::Diagnostics diags;
    const std::vector<std::string> files = aerodyn_input::aerodyn_files(primary, blades, diags);
    if (files.empty() || diags.has_errors()) throw diag::UserError(diags.render());
    std::vector<fs::path> paths;
    for (const std::string& f : files) paths.push_back(fs::absolute(f).lexically_normal());
    fs::path common = paths.front().parent_path();
    for (const fs::path& p : paths)
        while (!p.lexically_relative(common).empty() &&
               *p.lexically_relative(common).begin() == "..")
            common = common.parent_path();
    for (std::size_t k = 0; k < files.size(); ++k) {
        u.files.push_back(files[k]);
        u.names.push_back("aerodyn/" + paths[k].lexically_relative(common).generic_string());
    }
}

std::string blade_elements(const model::LoadBlock& d, const model::Model& m,
                           const runtime::ModelView& base, const BlockOptions& b, UnitBlocks& u) {
    if (!u.files.empty())
        throw diag::UsageError("yamsc fmu: a unit carries one `load blade_elements` block; '" +
                               d.name + "' is another");
    fmi::BladeElementsPlan plan;
    plan.setup = blade_element_channels(d, m, base, b);
    plan.inflow_angle_tolerance = b.inflow_angle_tolerance;
    aerodyn_resources(b.aero, static_cast<int>(plan.setup.channels.blades.size()), u);
    plan.aerodyn = u.names.front();
    u.blade_elements = true;
    return literal(fmi::blade_elements_plan_text(plan));
}

} // namespace

UnitBlocks unit_blocks(const model::Model& m, const runtime::ModelView& base,
                       const std::vector<std::string>& param_names, const BlockOptions& b) {
    UnitBlocks u;
    if (b.aero.empty()) return u;
    std::string tables, plans;
    bool rotor_tables = false;
    for (const model::LoadBlock& d : m.loads) {
        if (d.kind == model::LoadKind::blade_elements)
            plans += (plans.empty() ? "" : ", ") + blade_elements(d, m, base, b, u);
        if (d.kind == model::LoadKind::rotor_table) rotor_tables = true;
    }
    if (!plans.empty() && rotor_tables)
        throw diag::UsageError("yamsc fmu: --aero is an AeroDyn file for the blade elements; "
                               "a unit does not also carry the model's rotor tables");
    if (!plans.empty()) {
        u.source = "    s.close_blocks = ::yamsc::fmi::blade_elements_hook({" + plans + "});\n";
        return u;
    }
    u.files = {b.aero};
    u.names = {std::filesystem::path(b.aero).filename().string()};
    for (const model::LoadBlock& d : m.loads)
        if (d.kind == model::LoadKind::rotor_table)
            tables += rotor_table(d, param_names, u.names.front());
    if (!tables.empty())
        u.source = "    {\n        ::yamsc::fmi::BlockPlan plan;\n" + tables +
                   "        s.close_blocks = ::yamsc::fmi::block_hook(plan);\n    }\n";
    return u;
}

} // namespace yamsc::analysis
