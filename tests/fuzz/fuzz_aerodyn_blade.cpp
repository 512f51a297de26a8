// libFuzzer target: an AeroDyn blade file through aerodyn::read_blade_file.
// Properties: no crash, no sanitizer report, no exception; a rejected file reports
// an error; an accepted one has 2 nodes or more, BlSpn from 0 and rising, positive
// chords and BlAFID from 1.
#include "aerodyn/blade_file.hpp"

#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace yamsc;
    auto file = std::make_shared<const diag::SourceFile>(
        "fuzz.dat", std::string(reinterpret_cast<const char*>(data), size));
    diag::Diagnostics diags;
    auto blade = aerodyn::read_blade_file(file, diags);
    (void)diags.render();
    if (!blade) {
        if (!diags.has_errors()) std::abort();
        return 0;
    }
    if (blade->nodes.size() < 2 || blade->nodes.front().span != 0) std::abort();
    for (std::size_t i = 0; i < blade->nodes.size(); ++i) {
        const auto& n = blade->nodes[i];
        if (!(n.chord > 0) || n.airfoil_id < 1) std::abort();
        if (i > 0 && !(n.span > blade->nodes[i - 1].span)) std::abort();
    }
    return 0;
}
