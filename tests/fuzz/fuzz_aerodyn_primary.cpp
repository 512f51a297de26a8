// libFuzzer target: an AeroDyn primary file through aerodyn::read_primary_file
// ('@' includes refused: nothing is read from the disk). Properties: no crash, no
// sanitizer report, no exception; a rejected file reports an error; an accepted
// one names max(3, blades) blade files and at least one airfoil file.
#include "aerodyn/primary_file.hpp"

#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace yamsc;
    auto file = std::make_shared<const diag::SourceFile>(
        "fuzz.dat", std::string(reinterpret_cast<const char*>(data), size));
    const aerodyn::IncludeReader none = aerodyn::includes_refused();
    diag::Diagnostics diags;
    auto primary = aerodyn::read_primary_file(file, 3, diags, none);
    (void)diags.render();
    if (!primary) {
        if (!diags.has_errors()) std::abort();
        return 0;
    }
    if (primary->blade_files.size() != 3 || primary->airfoils.empty()) std::abort();
    return 0;
}
