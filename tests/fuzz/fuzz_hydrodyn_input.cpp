// libFuzzer target: a HydroDyn input file through hydrodyn::read_hydrodyn_input.
// Properties: no crash, no sanitizer report, no exception; a rejected file reports an
// error; an accepted file's vectors and matrices have the sizes its counts give, and
// every member names joints the file defines.
#include "hydrodyn/hydrodyn_input.hpp"

#include <cstdint>
#include <cstdlib>
#include <set>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace yamsc;
    auto file = std::make_shared<const diag::SourceFile>(
        "fuzz.dat", std::string(reinterpret_cast<const char*>(data), size));
    diag::Diagnostics diags;
    const auto in = hydrodyn::read_hydrodyn_input(file, diags, aerodyn::includes_refused());
    (void)diags.render();
    if (!in) {
        if (!diags.has_errors()) std::abort();
        return 0;
    }
    const auto n = static_cast<std::size_t>(in->matrix_size);
    const auto m = static_cast<std::size_t>(in->matrix_count);
    if (in->add_f0.size() != n * m || in->add_c_lin.size() != n * n * m ||
        in->add_b_lin.size() != n * n * m || in->add_b_quad.size() != n * n * m)
        std::abort();
    if (in->ptfm_vol0.size() != static_cast<std::size_t>(in->n_body) || in->pot_file.size() != m)
        std::abort();
    std::set<int> joints;
    for (const auto& j : in->joints) joints.insert(j.id);
    for (const auto& mem : in->members)
        if (!joints.count(mem.joint1) || !joints.count(mem.joint2) || !(mem.division_size > 0))
            std::abort();
    if (in->out_channel_lines.size() != in->out_channels.size()) std::abort();
    return 0;
}
