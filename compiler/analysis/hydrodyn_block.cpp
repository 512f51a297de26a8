// `load hydrodyn NAME { platform = BODY ... }` with `--hydro HydroDyn.dat
// [--sea-state SeaState.dat]`: HydroDyn's loads on the platform's mesh channels,
// one declaration for the whole file (docs/hydrodynamics.md, "Using it"). The
// water is the declaration's (its depth, density and gravity roles), else the
// SeaState file's, else 1025 kg/m^3 and 9.80665 m/s^2; one wave field from the
// SeaState file (still water without). The file's parts are the blocks of
// hydrodyn_parts(): each part applies to the files or not.
#include "analysis/hydrodyn_parts.hpp"
#include "analysis/load_block_kinds.hpp"
#include "analysis/platform_mesh.hpp"
#include "analysis/sea_state_setup.hpp"
#include "diag/errors.hpp"
#include "model/load_kinds.hpp"

#include <iostream>

namespace yamsc::analysis {

namespace {

runtime::hydro::Water water_of(const BoundWater& bound, const seastate::Input* sea) {
    runtime::hydro::Water w;
    if (sea && sea->water_density) w.density = *sea->water_density;
    if (bound.density) w.density = *bound.density;
    if (bound.gravity) w.gravity = *bound.gravity;
    std::optional<double> depth = bound.depth;
    if (!depth && sea && sea->water_depth)
        depth = *sea->water_depth + (sea->msl2swl ? *sea->msl2swl : 0.0);
    if (!depth)
        throw diag::UserError("load hydrodyn: no water depth: bind the declaration's `depth` "
                              "role to a parameter, or give a SeaState file whose WtrDpth is a "
                              "number (--sea-state)");
    w.depth = *depth;
    return w;
}

} // namespace

runtime::LoadBlocks build_hydrodyn(const model::LoadBlock& decl, const BlockContext& c) {
    HydroContext h;
    h.mesh = platform_mesh(decl, c);
    if (!h.mesh.axes_are_ground())
        throw diag::UserError("load hydrodyn " + decl.name +
                              ": the platform body's axes at rest "
                              "must be the ground's (HydroDyn's coordinates are)");
    diag::Diagnostics diags;
    std::optional<hydrodyn::Input> hd = hydrodyn::read_hydrodyn_input(c.options.hydro, diags);
    std::optional<seastate::Input> sea;
    if (!c.options.sea_state.empty())
        sea = seastate::read_seastate_input(c.options.sea_state, diags);
    if (!hd || (!c.options.sea_state.empty() && !sea) || diags.has_errors())
        throw diag::UserError(diags.render());
    if (!diags.all().empty()) std::cerr << diags.render();
    h.water = water_of(bound_water(decl, c), sea ? &*sea : nullptr);
    h.hydrodyn = &*hd;
    h.sea_state = sea ? &*sea : nullptr;
    h.output_prefix = model::load_kind_info(decl.kind).output_name(decl.name, "");
    if (sea) {
        // SeaState's waves in the declaration's water (its roles win over the file's).
        diag::Diagnostics wave_diags;
        runtime::hydro::WaveSettings w = wave_settings(*sea, h.water, wave_diags);
        if (wave_diags.has_errors()) throw diag::UserError(wave_diags.render());
        if (!wave_diags.all().empty()) std::cerr << wave_diags.render();
        w.water = h.water;
        try {
            h.waves = runtime::hydro::make_wave_field(w);
        } catch (const std::invalid_argument& e) {
            throw diag::UserError(c.options.sea_state + ": " + e.what());
        }
    }
    if (c.options.waves) h.waves = c.options.waves(h.water);
    runtime::LoadBlocks blocks;
    for (const HydroPart& part : hydrodyn_parts())
        if (part.applies(h)) blocks.push_back(part.build(h));
    if (blocks.empty())
        throw diag::UserError("load hydrodyn " + decl.name + ": " + c.options.hydro +
                              " gives no loads this build models (" + hydrodyn_part_names() + ")");
    return blocks;
}

} // namespace yamsc::analysis
