// libFuzzer target: a MoorDyn input file through moordyn::read_moordyn_input and
// its conversion into mooring lines (analysis/moordyn_mooring.cpp).
// Properties: no crash, no sanitizer report, no exception; a rejected file reports
// an error; accepted lines have positive lengths, stiffness and weight in water,
// and finite anchors and fairleads.
#include "analysis/moordyn_mooring.hpp"
#include "moordyn/moordyn_input.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace yamsc;
    auto file = std::make_shared<const diag::SourceFile>(
        "fuzz.dat", std::string(reinterpret_cast<const char*>(data), size));
    diag::Diagnostics diags;
    const auto input = moordyn::read_moordyn_input(file, diags);
    if (!input) {
        (void)diags.render();
        if (!diags.has_errors()) std::abort();
        return 0;
    }
    const auto lines = analysis::moordyn_lines(*input, {320, 1025, 9.80665}, diags);
    (void)diags.render();
    if (!lines) {
        if (!diags.has_errors()) std::abort();
        return 0;
    }
    for (const auto& l : *lines) {
        if (!(l.properties.length > 0) || !(l.properties.axial_stiffness > 0) ||
            !(l.properties.weight_in_fluid > 0))
            std::abort();
        for (int k = 0; k < 3; ++k)
            if (!std::isfinite(l.anchor[k]) || !std::isfinite(l.fairlead[k])) std::abort();
    }
    return 0;
}
