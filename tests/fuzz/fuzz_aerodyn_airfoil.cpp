// libFuzzer target: an AeroDyn airfoil file through aerodyn::read_airfoil_file
// ('@' includes refused), and every table it accepts through the unsteady
// constants and the separation function AirfoilInfo computes
// (analysis/aerodyn_airfoil.cpp, compiled in), for a Cn-based (UA_Mod 3) and a
// Cl-based (UA_Mod 6) model. Properties: no crash, no sanitizer report, no
// exception; a rejected file reports an error; an accepted one has tables of
// rising angles with a value in every column.
#include "aerodyn/airfoil_file.hpp"
#include "aerodyn_input/airfoil.hpp"

#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace yamsc;
    auto file = std::make_shared<const diag::SourceFile>(
        "fuzz.dat", std::string(reinterpret_cast<const char*>(data), size));
    const aerodyn::IncludeReader none = aerodyn::includes_refused();
    diag::Diagnostics diags;
    auto airfoil = aerodyn::read_airfoil_file(file, {1, 2, 3, 4, 0}, diags, none);
    (void)diags.render();
    if (!airfoil) {
        if (!diags.has_errors()) std::abort();
        return 0;
    }
    if (airfoil->tables.empty()) std::abort();
    for (const auto& t : airfoil->tables) {
        if (t.alpha.empty() || t.cl.size() != t.alpha.size() || t.cd.size() != t.alpha.size() ||
            t.cm.size() != t.alpha.size())
            std::abort();
        for (std::size_t i = 1; i < t.alpha.size(); ++i)
            if (!(t.alpha[i] > t.alpha[i - 1])) std::abort();
    }
    for (auto model : {aero::UnsteadyModel::minnema_pierce, aero::UnsteadyModel::oye}) {
        const aero::Airfoil converted = aerodyn_input::to_airfoil(*airfoil, model);
        for (const auto& t : converted.tables)
            if (t.unsteady) {
                aero::UnsteadyConstants k = *t.unsteady;
                const auto s = aerodyn_input::separation_function(t, k, model);
                if (s.f.size() != t.alpha.size()) std::abort();
            }
    }
    return 0;
}
