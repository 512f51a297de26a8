// libFuzzer target: an ElastoDyn file through the tower and the blade reader
// (every input tries both) and, when one accepts it, through check_beam and
// make_sid, as the model checker does for `beam "file" elastodyn_tower {}`.
// Properties: no crash, no sanitizer report, no exception; a rejected file
// reports an error; a beam that passes check_beam gives a SID of finite numbers.
#include "beam/elastodyn.hpp"
#include "beam/make_sid.hpp"
#include "diag/diagnostics.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace {

bool finite(const yamsc::sid::Taylor& t) {
    for (const auto& v : t.m0)
        if (!std::isfinite(v)) return false;
    for (const auto& v : t.m1)
        if (!std::isfinite(v)) return false;
    return true;
}

void try_reader(bool tower, const std::shared_ptr<const yamsc::diag::SourceFile>& file) {
    using namespace yamsc;
    diag::Diagnostics diags;
    auto beam = tower
                    ? beam::read_elastodyn_tower(file, 87.6, beam::elastodyn_tower_modes(), diags)
                    : beam::read_elastodyn_blade(file, 61.5, beam::elastodyn_blade_modes(), diags);
    (void)diags.render();
    if (!beam) {
        if (!diags.has_errors()) std::abort();
        return;
    }
    beam->integration_stations = 8; // few stations: many inputs per second
    if (beam::check_beam(*beam)) return;
    sid::Sid sid = beam::make_sid(*beam);
    if (!std::isfinite(sid.mass) || !finite(sid.J) || !finite(sid.Me) || !finite(sid.Ke))
        std::abort();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    auto file = std::make_shared<const yamsc::diag::SourceFile>(
        "fuzz.dat", std::string(reinterpret_cast<const char*>(data), size));
    try_reader(true, file);
    try_reader(false, file);
    return 0;
}
