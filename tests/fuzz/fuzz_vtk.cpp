// libFuzzer target: the scene's .vtp and .pvd (formats/vtk) through their
// readers; the first byte chooses which. Properties: no crash, no sanitizer
// report; a rejected file throws diag::UserError only; an accepted .vtp has
// 3 numbers per point, cells naming points and parts that exist, kinds 0..4,
// and writes and reads back to the same points; an accepted .pvd has rising times.
#include "vtk/scene.hpp"

#include "diag/errors.hpp"

#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace yamsc;
    if (size == 0) return 0;
    const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
    vtk::Limits limits;
    limits.points = 10000;
    limits.cells = 10000;
    try {
        if (data[0] & 1) {
            const std::vector<vtk::Entry> entries = vtk::parse_pvd(text, "fuzz.pvd", limits);
            for (std::size_t i = 1; i < entries.size(); ++i)
                if (!(entries[i].time > entries[i - 1].time)) std::abort();
            return 0;
        }
        const vtk::PolyData p = vtk::parse_vtp(text, "fuzz.vtp", limits);
        const vtk::Topology& t = p.topology;
        if (p.points.size() != 3 * t.points) std::abort();
        for (const vtk::Cells* c : {&t.verts, &t.lines, &t.polys}) {
            if (c->part.size() != c->size() || c->kind.size() != c->size()) std::abort();
            for (std::int64_t i : c->connectivity)
                if (i < 0 || static_cast<std::size_t>(i) >= t.points) std::abort();
            for (std::int32_t i : c->part)
                if (i < 0 || static_cast<std::size_t>(i) >= t.part_names.size()) std::abort();
        }
        const vtk::PolyData again = vtk::parse_vtp(vtk::write_vtp(t, p.points), "again.vtp");
        if (again.points != p.points || again.topology.part_names != t.part_names) std::abort();
    } catch (const diag::UserError&) {
    }
    return 0;
}
