#include "analysis/load_blocks.hpp"

#include "analysis/load_block_kinds.hpp"
#include "diag/errors.hpp"
#include "model/load_kinds.hpp"

#include <yamsc/wind.hpp>

#include <algorithm>
#include <stdexcept>

namespace yamsc::analysis {

using diag::InternalError;
using diag::UserError;

namespace {

using Builder = runtime::LoadBlocks (*)(const model::LoadBlock&, const BlockContext&);

/// A builder of one block as a Builder.
template <std::shared_ptr<const runtime::LoadBlock> (*build)(const model::LoadBlock&,
                                                             const BlockContext&)>
runtime::LoadBlocks one(const model::LoadBlock& decl, const BlockContext& c) {
    return {build(decl, c)};
}

/// A kind of load block: the option that supplies its data and its builder.
struct Registration {
    model::LoadKind kind;
    const char* option;
    std::string BlockOptions::*file; // the file that option names
    Builder build;
};

const Registration registry[] = {
    {model::LoadKind::rotor_table, "--aero", &BlockOptions::aero, one<build_rotor_table>},
    {model::LoadKind::blade_elements, "--aero", &BlockOptions::aero, one<build_blade_elements>},
    {model::LoadKind::mooring, "--mooring", &BlockOptions::mooring, one<build_mooring>},
    {model::LoadKind::hydrodyn, "--hydro", &BlockOptions::hydro, build_hydrodyn},
};

bool supplied(const Registration& r, const BlockOptions& b) {
    return !(b.*r.file).empty();
}

const model::Model* model_of(const Loaded& l) {
    return l.front.model ? &*l.front.model : nullptr;
}

const char* target_noun(model::RoleTarget t) {
    switch (t) {
    case model::RoleTarget::input_read:
        return "INPUT";
    case model::RoleTarget::load_input:
        return "INPUT";
    case model::RoleTarget::output_read:
        return "OUTPUT";
    case model::RoleTarget::parameter:
        return "PARAM";
    case model::RoleTarget::body:
        return "BODY";
    }
    return "NAME";
}

/// The declaration a model lacks, written out with its roles.
std::string declaration_to_add(const model::LoadKindInfo& k) {
    std::string text = "    load " + k.name + " NAME {\n";
    for (const model::LoadRole& r : k.roles) {
        std::string line = "        " + r.name + " = " + target_noun(r.target);
        line.resize(std::max<std::size_t>(line.size() + 1, 36), ' ');
        text += line + "# " + r.what + (r.required ? "" : " (optional)") + "\n";
    }
    return text + "    }";
}

} // namespace

int index_in(const std::vector<std::string>& names, const std::string& name) {
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return static_cast<int>(i);
    throw InternalError("load block: '" + name + "' is not a channel of the model's view");
}

double parameter(const BlockContext& c, const std::string& name) {
    const int i = c.loaded.library->param_index(name);
    if (i < 0) throw InternalError("load block: '" + name + "' is not a parameter of the model");
    return c.params[static_cast<std::size_t>(i)];
}

bool any_blocks(const BlockOptions& b) {
    for (const Registration& r : registry)
        if (supplied(r, b)) return true;
    return false;
}

void add_block_routines(const BlockOptions& b, bool exact_jacobian, codegen::RoutineSet& routines) {
    if (!any_blocks(b)) return;
    routines.insert(codegen::RoutineId::outputs);
    // HydroDyn's added mass is solved with the structure's (close_blocks).
    if (!b.hydro.empty()) routines.insert(codegen::RoutineId::mass_matrix);
    if (exact_jacobian)
        routines.insert({codegen::RoutineId::mass_matrix, codegen::RoutineId::jacobians});
}

std::vector<driver::NamedFile> block_files(const BlockOptions& b) {
    std::vector<driver::NamedFile> files;
    for (const Registration& r : registry)
        if (supplied(r, b)) files.push_back({r.option, b.*r.file});
    if (!b.sea_state.empty()) files.push_back({"--sea-state", b.sea_state});
    return files;
}

runtime::LoadBlocks load_blocks(const Loaded& l, const runtime::ModelView& v,
                                const std::vector<double>& params, const BlockOptions& b) {
    const model::Model* m = model_of(l);
    // The field is opened here, its errors --wind's; its warnings are printed
    // where --wind drives the wind input (wind_input.hpp).
    std::shared_ptr<const runtime::WindField> field;
    if (!b.wind.empty()) {
        try {
            field = runtime::open_wind(b.wind).field;
        } catch (const std::invalid_argument& e) {
            throw diag::UsageError(e.what());
        } catch (const std::runtime_error& e) {
            throw UserError(e.what());
        }
    }
    const BlockContext context{l, v, params, b, field};
    runtime::LoadBlocks blocks;
    // Several kinds may take their data from one option (--aero: a Cp/Ct/Cq
    // table or an AeroDyn file): the model's declarations say which.
    std::vector<std::string> options_done;
    for (const Registration& r : registry) {
        if (!supplied(r, b) ||
            std::find(options_done.begin(), options_done.end(), r.option) != options_done.end())
            continue;
        options_done.push_back(r.option);
        bool declared = false;
        std::string kinds, declarations;
        for (const Registration& same : registry) {
            if (std::string(same.option) != r.option) continue;
            const model::LoadKindInfo& kind = model::load_kind_info(same.kind);
            kinds += (kinds.empty() ? "`load " : " or `load ") + kind.name + "`";
            declarations += "\n" + declaration_to_add(kind);
            for (const model::LoadBlock& decl : m ? m->loads : std::vector<model::LoadBlock>{}) {
                if (decl.kind != same.kind) continue;
                declared = true;
                try {
                    for (auto& block : same.build(decl, context)) blocks.push_back(block);
                } catch (const std::invalid_argument& e) {
                    throw UserError(std::string(same.option) + ": " + e.what());
                } catch (const std::runtime_error& e) {
                    throw UserError(std::string(same.option) + ": " + e.what());
                }
            }
        }
        if (!declared)
            throw UserError(std::string(r.option) + ": the model declares no " + kinds +
                            " block for it; add one that binds its roles to the model's " +
                            "names (docs/language.md, Load blocks):" + declarations);
    }
    return blocks;
}

runtime::ModelView with_load_blocks(const Loaded& l, const BlockOptions& b) {
    return with_load_blocks(l, l.view, l.params, b);
}

runtime::ModelView with_load_blocks(const Loaded& l, const runtime::ModelView& v,
                                    const std::vector<double>& params, const BlockOptions& b) {
    if (!any_blocks(b)) return v;
    const runtime::LoadBlocks blocks = load_blocks(l, v, params, b);
    try {
        return runtime::close_blocks(v, blocks, b.coupling);
    } catch (const std::invalid_argument& e) {
        throw UserError(std::string("load blocks: ") + e.what());
    }
}

BlockOptions sim_block_options(const driver::SimOptions& o) {
    BlockOptions b = block_options(o);
    b.coupling.mode = o.coupling == driver::SimCoupling::loose ? runtime::Coupling::loose
                                                               : runtime::Coupling::tight;
    b.coupling.interp_order = o.interp_order;
    return b;
}

BlockOptions linear_block_options(const driver::LinOptions& o) {
    BlockOptions b = trim_block_options(o);
    b.frozen_wake = o.wake == driver::Wake::frozen;
    return b;
}

runtime::TrimSettings trim_settings(const Loaded& l, const BlockOptions& b) {
    runtime::TrimSettings s;
    if (const model::Model* m = model_of(l); m && !b.aero.empty())
        for (const model::LoadBlock& decl : m->loads)
            if (decl.kind == model::LoadKind::blade_elements) s.relative_tolerance = 1e-6;
    return s;
}

int wind_input(const Loaded& l, const runtime::ModelView& v) {
    if (const model::Model* m = model_of(l))
        for (const model::LoadBlock& decl : m->loads) {
            const model::LoadKindInfo& kind = model::load_kind_info(decl.kind);
            if (kind.wind_role < 0) continue;
            const std::string& name = decl.bound[static_cast<std::size_t>(kind.wind_role)];
            if (!name.empty()) return index_in(v.input_names, name);
        }
    throw UserError("--wind: the model declares no load block with a wind input; add one that "
                    "binds it (docs/language.md, Load blocks), e.g.\n" +
                    declaration_to_add(model::load_kinds().front()));
}

} // namespace yamsc::analysis
