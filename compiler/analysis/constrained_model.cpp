#include "analysis/constrained_model.hpp"

#include "analysis/linear_report.hpp"
#include "diag/errors.hpp"
#include "driver/json.hpp"

#include <cstdio>
#include <ostream>
#include <string>

namespace yamsc::analysis {

namespace json = driver::json;
using diag::UsageError;

namespace {

std::size_t at(int i) {
    return static_cast<std::size_t>(i);
}

std::vector<std::string> names_of(const runtime::ModelView& v, const std::vector<int>& dofs) {
    std::vector<std::string> out;
    for (int j : dofs) out.push_back(v.dof_names[at(j)]);
    return out;
}

std::vector<double> state_of(const runtime::ModelView& v, const std::vector<double>& q,
                             const std::vector<double>& qd) {
    std::vector<double> x = q;
    x.insert(x.end(), qd.begin(), qd.end());
    x.insert(x.end(), v.block_initial_states.begin(), v.block_initial_states.end());
    return x;
}

} // namespace

runtime::ModelView constrained_view(const runtime::ModelView& generated) {
    return generated.nc > 0 ? runtime::constrain(generated) : generated;
}

void throw_located(const runtime::ModelView& v, const runtime::ConstraintError& e) {
    const int row = e.row();
    const bool located =
        row >= 0 && at(row) < v.constraint_sources.size() && !v.constraint_sources[at(row)].empty();
    if (!located) throw diag::UserError(e.what());
    // The location first, as diagnostics have it, and not again after the row's name.
    const std::string& source = v.constraint_sources[at(row)];
    std::string message = e.what();
    const std::string again = "'" + v.constraint_names[at(row)] + "' (" + source + ")";
    const std::size_t pos = message.find(again);
    if (pos != std::string::npos)
        message.replace(pos, again.size(), "'" + v.constraint_names[at(row)] + "'");
    throw diag::UserError(source + ": " + message);
}

void consistent_start(const runtime::ModelView& v, double t, std::vector<double>& x,
                      const std::vector<double>& u, bool verbose, std::ostream& err) {
    if (v.nc == 0) return;
    const runtime::ConsistentState s =
        located_constraint_errors(v, [&] { return runtime::consistent_initial_state(v, t, x, u); });
    x = s.x;
    if (verbose)
        err << "yamsc: constraints: the start made consistent in " << s.iterations
            << " Newton steps\n"
            << runtime::describe_choice(v, s.choice);
}

void refuse_constrained_options(const driver::LinOptions& o) {
    const char* option = o.mbc3                                        ? "--mbc3"
                         : o.sweep                                     ? "--sweep"
                         : !o.hold.empty()                             ? "--hold"
                         : !o.adjust.empty()                           ? "--adjust"
                         : o.format == driver::LinFormat::openfast_lin ? "--format openfast-lin"
                                                                       : nullptr;
    if (option)
        throw UsageError(std::string("lin ") + option +
                         " does not take a model with constraints: its linear model is in the "
                         "independent coordinates (docs/constraints.md)");
}

void refuse_constrained_options(const driver::TrimOptions& o) {
    const char* option = !o.hold.empty() ? "--hold" : !o.adjust.empty() ? "--adjust" : nullptr;
    if (option)
        throw UsageError(std::string("trim ") + option +
                         " does not take a model with constraints: it trims the independent "
                         "coordinates with the speeds as given (docs/constraints.md)");
}

int constrained_lin(const runtime::ModelView& v, const driver::LinOptions& o, std::vector<double> q,
                    std::vector<double> qd, const std::vector<double>& u, std::ostream& out,
                    std::ostream& err) {
    std::vector<double> x = state_of(v, q, qd);
    consistent_start(v, 0.0, x, u, false, err);
    if (o.trim) {
        const runtime::ConstrainedTrimResult r =
            located_constraint_errors(v, [&] { return runtime::trim_constrained(v, x, u); });
        if (!r.converged)
            err << "yamsc: warning: the trim did not converge (max |q''| over the independent "
                   "speeds "
                << r.max_residual << ")\n";
        x = r.x;
    }
    const runtime::ReducedLinearModel m =
        located_constraint_errors(v, [&] { return runtime::reduced_linear_model(v, x, u); });
    const int ns = static_cast<int>(m.state_names.size()), nu = v.nu, mq = m.n_coordinates;
    q.assign(x.begin(), x.begin() + v.nq);
    qd.assign(x.begin() + v.nq, x.begin() + 2 * v.nq);
    if (o.json) {
        out << "{\"dofs\":" << json::strings(v.dof_names)
            << ",\"inputs\":" << json::strings(v.input_names)
            << ",\"states\":" << json::strings(m.state_names)
            << ",\"dependent_coordinates\":" << json::strings(names_of(v, m.choice.coordinates))
            << ",\"dependent_speeds\":" << json::strings(names_of(v, m.choice.speeds))
            << ",\"A\":" << json::matrix(matrix_rows(m.A, ns, ns))
            << ",\"B\":" << json::matrix(matrix_rows(m.B, ns, nu))
            << ",\"T\":" << json::matrix(matrix_rows(m.T, v.nx(), ns));
        if (m.second_order && !m.M.empty())
            out << ",\"M\":" << json::matrix(matrix_rows(m.M, mq, mq))
                << ",\"C\":" << json::matrix(matrix_rows(m.C, mq, mq))
                << ",\"K\":" << json::matrix(matrix_rows(m.K, mq, mq));
        out << ",\"q0\":" << json::array(q) << ",\"qd0\":" << json::array(qd)
            << ",\"u0\":" << json::array(u) << ",\"modes\":" << modes_json(m.modes) << "}\n";
        return 0;
    }
    out << "linear model in the independent coordinates (" << mq << ") and speeds (" << m.n_speeds
        << "):\n"
        << runtime::describe_choice(v, m.choice);
    out << format_mode_table(v.dof_names, m.modes);
    return 0;
}

int constrained_trim(const runtime::ModelView& v, const driver::TrimOptions& o,
                     const std::vector<double>& q, const std::vector<double>& qd,
                     const std::vector<double>& u, std::ostream& out) {
    const std::vector<double> x0 = state_of(v, q, qd);
    const runtime::ConstrainedTrimResult r =
        located_constraint_errors(v, [&] { return runtime::trim_constrained(v, x0, u); });
    const std::vector<double> qt(r.x.begin(), r.x.begin() + v.nq),
        qdt(r.x.begin() + v.nq, r.x.begin() + 2 * v.nq);
    if (o.json) {
        out << "{\"dofs\":" << json::strings(v.dof_names) << ",\"q\":" << json::array(qt)
            << ",\"qd\":" << json::array(qdt) << ",\"u\":" << json::array(u)
            << ",\"inputs\":" << json::strings(v.input_names)
            << ",\"dependent_coordinates\":" << json::strings(names_of(v, r.choice.coordinates))
            << ",\"residual\":" << json::array(r.residual) << ",\"iterations\":" << r.iterations
            << ",\"max_free_residual\":" << json::number(r.max_residual)
            << ",\"converged\":" << (r.converged ? "true" : "false") << "}\n";
        return 0;
    }
    char line[200];
    std::snprintf(line, sizeof line,
                  "trimmed in %d Newton steps over the independent coordinates: max |q''| over "
                  "the independent speeds %.3g%s\n",
                  r.iterations, r.max_residual, r.converged ? "" : " (not converged)");
    out << line << runtime::describe_choice(v, r.choice);
    out << "dof                           q0             q0'\n";
    for (int i = 0; i < v.nq; ++i) {
        std::snprintf(line, sizeof line, "%-16s %16.10g %15.10g\n", v.dof_names[at(i)].c_str(),
                      qt[at(i)], qdt[at(i)]);
        out << line;
    }
    return r.converged ? 0 : 1;
}

} // namespace yamsc::analysis
