#include "passes/pass_order.hpp"

#include "diag/diagnostics.hpp"

#include <array>
#include <string>

namespace yamsc::passes {

namespace {

using ir::Pass;

// The derivative passes: `approx` must have replaced M and F before any of them
// reads the equations, and the externals' arguments must be separated.
constexpr ir::PassSet derivatives{Pass::derive_jacobians, Pass::output_jacobians,
                                  Pass::derive_tangent, Pass::external_jacobians,
                                  Pass::parameter_derivatives};

// In the order of ir::Pass.
const std::array<PassInfo, ir::pass_count> table{{
    {Pass::separate_externals,
     "separate_externals",
     "externals[k].args",
     {},
     {Pass::approximate, Pass::derive_jacobians, Pass::output_jacobians, Pass::derive_tangent,
      Pass::external_jacobians, Pass::parameter_derivatives},
     false},
    {Pass::approximate,
     "approximate",
     "exact_M, exact_F (M and F replaced)",
     {},
     derivatives,
     true},
    {Pass::derive_jacobians,
     "derive_jacobians",
     "dF_dq, dF_dqd, dF_du, dMa_dq",
     {},
     {Pass::parameter_derivatives},
     false},
    {Pass::output_jacobians, "output_jacobians", "C, D", {}, {}, false},
    {Pass::derive_tangent, "derive_tangent", "dG, dY", {}, {}, false},
    {Pass::external_jacobians,
     "external_jacobians",
     "externals[k].dargs_dq, dargs_dqd, dargs_du",
     {Pass::separate_externals},
     {},
     false},
    {Pass::parameter_derivatives,
     "parameter_derivatives",
     "sensitivity_params, sensitivities",
     {Pass::derive_jacobians},
     {},
     false},
    {Pass::constraint_derivatives,
     "constraint_derivatives",
     "B, dr_dq, gamma, dBTl_dq, dacc_dq, dacc_dqd, dBTl_du, dacc_du",
     {},
     {},
     false},
}};

std::string names(ir::PassSet set) {
    std::string out;
    set.for_each(
        [&](Pass p) { out += (out.empty() ? "" : ", ") + std::string(pass_info(p).name); });
    return out;
}

} // namespace

const PassInfo& pass_info(Pass pass) {
    return table[static_cast<std::size_t>(pass)];
}

void enter(ir::System& s, Pass pass) {
    const PassInfo& info = pass_info(pass);
    const std::string what = std::string("pass ") + info.name + " (adds " + info.adds + ")";
    if (!info.repeats && s.passes.contains(pass))
        throw diag::InternalError(what + " ran twice on one System");
    if (const ir::PassSet missing = info.needs.without(s.passes); !missing.empty())
        throw diag::InternalError(what + " needs " + names(missing) + " first");
    if (const ir::PassSet early = info.before.both(s.passes); !early.empty())
        throw diag::InternalError(what + " must run before " + names(early));
    s.passes.insert(pass);
}

} // namespace yamsc::passes
