// `yamsc trim`: the operating point at rest in the model's own equations
// (yamsc/trim.hpp), from the model's `linearize` point moved by --at/--u;
// with --aero and --wind, in steady wind, the --adjust inputs trimmed too.
#include "analysis/constrained_model.hpp"
#include "analysis/load_blocks.hpp"
#include "analysis/loaded_model.hpp"
#include "analysis/trim_point.hpp"
#include "analysis/wind_input.hpp"
#include "driver/json.hpp"

#include <cmath>
#include <cstdio>
#include <ostream>

namespace yamsc::analysis {

using driver::TrimOptions;
namespace json = driver::json;

int trim(const TrimOptions& o, std::ostream& out, std::ostream& err) {
    codegen::RoutineSet routines = linear_model_routines();
    add_block_routines(block_options(o), false, routines);
    auto loaded = load(o.model, o.set, o.sid, false, err, {}, routines, o.external);
    if (!loaded || refuse_without_dofs(*loaded, "trim", "trim", err)) return 1;
    const runtime::ModelView v = with_load_blocks(*loaded, trim_block_options(o));
    std::vector<double> q, qd, u0;
    operating_point(*loaded, loaded->params, o.at, o.u, q, qd, u0);
    if (!o.wind.empty()) set_wind_at_start(*loaded, v, u0, o.wind);
    if (v.nc > 0) {
        refuse_constrained_options(o);
        return constrained_trim(v, o, q, qd, u0, out);
    }
    const runtime::TrimResult r =
        trim_point(v, q, qd, u0, o.hold, o.adjust, trim_settings(*loaded, block_options(o)));
    const std::vector<double>& u = r.u;
    if (o.json) {
        std::vector<std::string> held;
        for (std::size_t i = 0; i < r.held.size(); ++i)
            if (r.held[i]) held.push_back(v.dof_names[i]);
        out << "{\"dofs\":" << json::strings(v.dof_names) << ",\"q\":" << json::array(r.q)
            << ",\"qd\":" << json::array(r.qd) << ",\"u\":" << json::array(u)
            << ",\"inputs\":" << json::strings(v.input_names)
            << ",\"adjusted\":" << json::strings(o.adjust) << ",\"held\":" << json::strings(held)
            << ",\"residual\":" << json::array(r.residual) << ",\"iterations\":" << r.iterations
            << ",\"discrete_passes\":" << r.discrete_passes
            << ",\"max_free_residual\":" << json::number(r.max_free_residual) << "}\n";
        return 0;
    }
    char line[200];
    std::snprintf(line, sizeof line,
                  "trimmed in %d Newton steps: max |F| over the free DOFs %.3g (tolerance %.3g)\n",
                  r.iterations, r.max_free_residual, r.tolerance);
    out << line;
    if (r.discrete_passes > 0) {
        // Unsteady airfoils and dynamic inflow steady at the point (runtime/trim.hpp).
        std::snprintf(line, sizeof line,
                      "the blocks' discrete states (unsteady airfoils, dynamic inflow) settled "
                      "at the point in %d passes\n",
                      r.discrete_passes);
        out << line;
    }
    out << "dof                           q0             q0'  F (held: what holds it)\n";
    for (std::size_t i = 0; i < r.q.size(); ++i) {
        std::snprintf(line, sizeof line, "%-16s %16.10g %15.10g  %.6g%s\n", v.dof_names[i].c_str(),
                      r.q[i], r.qd[i], r.residual[i], r.held[i] ? " (held)" : "");
        out << line;
    }
    for (const std::string& name : o.adjust)
        for (std::size_t k = 0; k < v.input_names.size(); ++k)
            if (v.input_names[k] == name) {
                std::snprintf(line, sizeof line, "%-16s %16.10g  (adjusted input)\n", name.c_str(),
                              u[k]);
                out << line;
            }
    return 0;
}

} // namespace yamsc::analysis
