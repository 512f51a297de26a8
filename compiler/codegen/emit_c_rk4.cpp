#include "codegen/emit_c_rk4.hpp"

#include "codegen/helper_sources.hpp"

#include <fmt/format.h>

namespace yamsc::codegen {

std::string rk4_signature(const Rk4Names& names) {
    return fmt::format("void {0}_rk4_step({1} t, {1} h, {1}* x, const {1}* u, const {2}* p)",
                       names.prefix, names.real, names.params_type);
}

std::string rk4_definition(const Rk4Names& names, const Syntax& syntax, int nx) {
    // helpers/rk4.inc; mirrors rk4_count below.
    return rk4_source(syntax, names.prefix, names.real, names.params_type, nx);
}

OperationCount rk4_count(int nx, const OperationCount& rhs) {
    OperationCount c;
    for (int k = 0; k < 4; ++k) c += rhs;
    c.adds += 2;       // t + half, t + h
    c.muls += 1;       // half
    c.divs += 1;       // sixth
    c.adds += 3L * nx; // the three stages: x + s*k
    c.muls += 3L * nx;
    c.adds += 4L * nx; // x += sixth*(k1 + 2*(k2 + k3) + k4)
    c.muls += 2L * nx;
    return c;
}

} // namespace yamsc::codegen
