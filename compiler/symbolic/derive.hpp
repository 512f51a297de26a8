#pragma once
// Kane's method: the checked model -> M(q) q'' = F(q, q', u, t) and outputs.
#include "model/model.hpp"
#include "symbolic/equations.hpp"
#include "symbolic/projection.hpp"

#include <functional>

namespace yamsc::symbolic {

/// What compiled code costs to compute a set of expressions of `eq`'s symbols.
using OperationCount =
    std::function<double(const Equations& eq, const std::vector<GiNaC::ex>& roots)>;

struct DeriveOptions {
    /// false: M is not assembled (eq.M stays empty; M a is): the tangent form,
    /// whose cost is O(bodies x DOFs) instead of O(bodies x DOFs²).
    bool mass_matrix = true;
    /// How M and F are summed (projection.hpp): this grouping, or else the one
    /// whose M and F cost the fewest operations by `cost`, or else Grouping::all.
    /// The count must come from a canonical form (lower::operation_count): the
    /// form GiNaC gives an expression depends on the process (its hashes
    /// include addresses), and the choice must not.
    std::optional<Grouping> grouping;
    OperationCount cost;
};

/// Derives the equations of motion of a checked model (paper eq. 4-10, 21-22).
/// Reports user errors (e.g. loads nonlinear in q'') into `diags` and returns
/// nullopt on error.
std::optional<Equations> derive(const model::Model& m, diag::Diagnostics& diags,
                                const DeriveOptions& options = {});

} // namespace yamsc::symbolic
