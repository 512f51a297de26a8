#pragma once
// Models with constraints in the commands (docs/constraints.md): the view
// constrained where it is bound, the consistent start, lin and trim in the
// independent coordinates, and the runtime's constraint errors as user errors
// located at the constraint.
#include "driver/commands.hpp"

#include <yamsc/constraints.hpp>
#include <yamsc/model_view.hpp>

#include <iosfwd>
#include <vector>

namespace yamsc::analysis {

/// The view of the generated model constrained when it has constraint rows
/// (runtime::constrain), unchanged otherwise.
runtime::ModelView constrained_view(const runtime::ModelView& generated);

/// x = [q, q', z] moved onto the constraints at t (nothing without rows); with
/// `verbose` the dependent coordinates chosen, to `err`. A constraint error is
/// thrown as diag::UserError starting with the constraint's location.
void consistent_start(const runtime::ModelView& v, double t, std::vector<double>& x,
                      const std::vector<double>& u, bool verbose, std::ostream& err);

/// Calls f, turning a runtime::ConstraintError into a located diag::UserError.
template <class F>
auto located_constraint_errors(const runtime::ModelView& v, F f) -> decltype(f());
[[noreturn]] void throw_located(const runtime::ModelView& v, const runtime::ConstraintError& e);

/// `yamsc lin` of a constrained view at (q, q', u): the model in the independent
/// coordinates and speeds, its modes; JSON with --json.
int constrained_lin(const runtime::ModelView& v, const driver::LinOptions& o, std::vector<double> q,
                    std::vector<double> qd, const std::vector<double>& u, std::ostream& out,
                    std::ostream& err);

/// `yamsc trim` of a constrained view from (q, q', u).
int constrained_trim(const runtime::ModelView& v, const driver::TrimOptions& o,
                     const std::vector<double>& q, const std::vector<double>& qd,
                     const std::vector<double>& u, std::ostream& out);

/// The options of lin and trim that do not apply to a constrained model: a
/// usage error naming the first given (--mbc3, --sweep, --hold, --adjust,
/// --format openfast-lin).
void refuse_constrained_options(const driver::LinOptions& o);
void refuse_constrained_options(const driver::TrimOptions& o);

template <class F>
auto located_constraint_errors(const runtime::ModelView& v, F f) -> decltype(f()) {
    try {
        return f();
    } catch (const runtime::ConstraintError& e) {
        throw_located(v, e);
    }
}

} // namespace yamsc::analysis
