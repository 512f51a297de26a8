// `yamsc eval --compiled`: M, F and the outputs at a state from the model's
// compiled code (the routines `sim`, `lin` and the Python module run), where
// plain `eval` interprets the derived equations. The two agree to rounding
// (a few 1e-15 relative); this one is the reference for the compiled code to
// the last bit.
#include "analysis/loaded_model.hpp"
#include "driver/bindings.hpp"
#include "driver/json.hpp"

#include <ostream>

namespace yamsc::analysis {

using driver::EvalOptions;
using driver::sized;
namespace json = driver::json;

int eval_compiled(const EvalOptions& o, std::ostream& out, std::ostream& err) {
    auto loaded = load(o.model, o.set, o.sid, false, err, {},
                       {codegen::RoutineId::rhs, codegen::RoutineId::mass_matrix,
                        codegen::RoutineId::forcing, codegen::RoutineId::outputs},
                       o.external);
    if (!loaded) return 1;
    const runtime::ModelView& v = loaded->view;
    const auto nq = static_cast<std::size_t>(v.nq);
    const std::vector<double> q =
        o.q.empty() ? std::vector<double>(nq, 0.0) : sized(o.q, nq, "--q");
    const std::vector<double> qd =
        o.qd.empty() ? std::vector<double>(nq, 0.0) : sized(o.qd, nq, "--qd");
    const std::vector<double> u = inputs_of(v, o.u);
    const double* inputs = u.empty() ? nullptr : u.data();
    std::vector<double> m(nq * nq), F(nq), y(static_cast<std::size_t>(v.ny));
    v.mass_matrix(o.t, q.data(), inputs, m.data());
    v.forcing(o.t, q.data(), qd.data(), inputs, F.data());
    if (!y.empty()) v.outputs(o.t, q.data(), qd.data(), inputs, y.data());
    std::vector<std::vector<double>> M(nq);
    for (std::size_t r = 0; r < nq; ++r) M[r].assign(m.begin() + r * nq, m.begin() + (r + 1) * nq);
    out << "{\"nq\":" << nq << ",\"dofs\":" << json::strings(v.dof_names)
        << ",\"M\":" << json::matrix(M) << ",\"F\":" << json::array(F)
        << ",\"outputs\":" << json::strings(v.output_names) << ",\"y\":" << json::array(y) << "}\n";
    return 0;
}

} // namespace yamsc::analysis
