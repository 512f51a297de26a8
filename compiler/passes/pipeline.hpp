#pragma once
// The passes a front end asks for, run in their one order: externals
// separated, `approx` groups, then the derivatives (unrolled or tangent), the
// externals' Jacobians and the parameter derivatives. pass_order.hpp checks
// each step; this is the only place that sequences them.
#include "ir/system.hpp"

#include <cstddef>
#include <functional>
#include <vector>

namespace yamsc::passes {

struct PassPlan {
    bool externals = false; // separate_externals (and external_jacobians with unrolled)
    struct Approximation {
        std::vector<ir::SymbolRef> group;
        int order = 0;
    };
    std::vector<Approximation> approximations;
    enum class Derivatives { none, unrolled, tangent } derivatives = Derivatives::none;
    /// Indices into the System's params: parameter_derivatives (unrolled only).
    std::vector<std::size_t> sensitivity_params;
};

/// Runs the plan's passes on `s`; `after(pass)` (may be empty) is called after
/// each. A NotExpandable from an `approx` group carries the group's index.
void run_pipeline(ir::System& s, const PassPlan& plan,
                  const std::function<void(ir::Pass)>& after = {});

} // namespace yamsc::passes
