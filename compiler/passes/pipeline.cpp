#include "passes/pipeline.hpp"

#include "diag/diagnostics.hpp"
#include "passes/passes.hpp"
#include "passes/taylor.hpp"

namespace yamsc::passes {

void run_pipeline(ir::System& s, const PassPlan& plan, const std::function<void(ir::Pass)>& after) {
    auto done = [&](ir::Pass p) {
        if (after) after(p);
    };
    if (plan.externals) {
        separate_externals(s);
        done(ir::Pass::separate_externals);
    }
    for (std::size_t i = 0; i < plan.approximations.size(); ++i) {
        try {
            approximate(s, plan.approximations[i].group, plan.approximations[i].order);
        } catch (NotExpandable& x) {
            x.group = i;
            throw;
        }
        done(ir::Pass::approximate);
    }
    using Derivatives = PassPlan::Derivatives;
    if (!plan.sensitivity_params.empty() && plan.derivatives != Derivatives::unrolled)
        throw diag::InternalError("parameter derivatives need the unrolled Jacobians");
    if (plan.derivatives == Derivatives::tangent) {
        derive_tangent(s);
        done(ir::Pass::derive_tangent);
    } else if (plan.derivatives == Derivatives::unrolled) {
        derive_jacobians(s);
        done(ir::Pass::derive_jacobians);
        output_jacobians(s);
        done(ir::Pass::output_jacobians);
        if (plan.externals) {
            external_jacobians(s);
            done(ir::Pass::external_jacobians);
        }
        if (!plan.sensitivity_params.empty()) {
            parameter_derivatives(s, plan.sensitivity_params);
            done(ir::Pass::parameter_derivatives);
        }
    }
    if (!s.constraints.empty()) {
        constraint_derivatives(s);
        done(ir::Pass::constraint_derivatives);
    }
}

} // namespace yamsc::passes
