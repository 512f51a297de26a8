#include "codegen/emit_c_rk4.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace yamsc::codegen {

std::string rk4_signature(const Rk4Names& names) {
    return fmt::format("void {0}_rk4_step({1} t, {1} h, {1}* x, const {1}* u, const {2}* p)",
                       names.prefix, names.real, names.params_type);
}

std::string rk4_definition(const Rk4Names& names, const Syntax& syntax, int nx) {
    // The runtime computes x[i] += dt / 6.0 * (...): (dt / 6.0) once per step
    // gives the same value, and t + half is the same sum at stages 2 and 3.
    // Mirrors rk4_count below.
    return fmt::format(
        R"(void {prefix}_rk4_step({real} t, {real} h, {real}* x, const {real}* u, const {params}* p) {{
    {type} k1[{size}], k2[{size}], k3[{size}], k4[{size}], stage[{size}];
    const {type} half = {half}*h;
    const {type} sixth = h/{six};
    const {type} t_half = t + half;
    {prefix}_rhs(t, x, u, p, k1);
    for (int i = 0; i < {nx}; ++i) stage[i] = x[i] + half*k1[i];
    {prefix}_rhs(t_half, stage, u, p, k2);
    for (int i = 0; i < {nx}; ++i) stage[i] = x[i] + half*k2[i];
    {prefix}_rhs(t_half, stage, u, p, k3);
    for (int i = 0; i < {nx}; ++i) stage[i] = x[i] + h*k3[i];
    {prefix}_rhs(t + h, stage, u, p, k4);
    for (int i = 0; i < {nx}; ++i) x[i] += sixth*(k1[i] + {two}*(k2[i] + k3[i]) + k4[i]);
}}
)",
        fmt::arg("prefix", names.prefix), fmt::arg("real", names.real),
        fmt::arg("params", names.params_type), fmt::arg("type", syntax.real_type),
        fmt::arg("nx", nx), fmt::arg("size", std::max(nx, 1)),
        fmt::arg("half", format_literal(0.5, syntax)), fmt::arg("six", format_literal(6.0, syntax)),
        fmt::arg("two", format_literal(2.0, syntax)));
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
