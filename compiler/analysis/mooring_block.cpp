// `load mooring NAME { platform = BODY; depth = PARAM ... }` with `--mooring
// FILE`, MAP++'s or MoorDyn's (mooring_files.hpp): quasi-static lines
// (yamsc/mooring/mooring_block.hpp) on the platform's mesh channels, the
// fairleads placed from the body's origin at rest.
#include "analysis/load_block_kinds.hpp"
#include "analysis/mooring_files.hpp"
#include "analysis/platform_mesh.hpp"
#include "diag/errors.hpp"
#include "model/load_kinds.hpp"

#include <yamsc/mooring/mooring_block.hpp>

#include <iostream>

namespace yamsc::analysis {

std::shared_ptr<const runtime::LoadBlock> build_mooring(const model::LoadBlock& decl,
                                                        const BlockContext& c) {
    const PlatformMesh mesh = platform_mesh(decl, c);
    const BoundWater water = bound_water(decl, c);
    MooringEnvironment env;
    env.water_depth = water.depth.value_or(0); // required by the kind's row
    if (water.density) env.water_density = *water.density;
    if (water.gravity) env.gravity = *water.gravity;
    diag::Diagnostics diags;
    std::optional<std::vector<runtime::mooring::Line>> lines =
        read_mooring_file(c.options.mooring, env, diags);
    if (!lines || diags.has_errors()) throw diag::UserError(diags.render());
    if (!diags.all().empty()) std::cerr << diags.render();
    // MAP++'s Vessel nodes and MoorDyn's Vessel points are in global
    // coordinates with the platform undisplaced (the glue code maps the platform's motion onto
    // them); the block's fairleads are from the body's origin in body axes.
    for (runtime::mooring::Line& line : *lines) line.fairlead = mesh.body_point(line.fairlead);
    runtime::mooring::MooringSetup s;
    s.lines = std::move(*lines);
    s.output_prefix = model::load_kind_info(decl.kind).output_name(decl.name, "");
    s.frame_outputs = mesh.frame_outputs;
    s.loads = mesh.loads;
    return runtime::mooring::mooring_block(std::move(s));
}

} // namespace yamsc::analysis
