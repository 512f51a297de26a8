#include "codegen/output_routines.hpp"

#include "codegen/routine_builder.hpp"
#include "codegen/symbol_binding.hpp"

#include <algorithm>
#include <string>
#include <utility>

namespace yamsc::codegen {

void add_output_routines(Graph& g, const std::vector<NodeId>& y, int nq, bool accelerations,
                         const Options& options, std::vector<Routine>& routines) {
    {
        SymbolSource source;
        source.qdd = "qdd";
        RoutineBuilder b(g, api_signature(RoutineId::outputs_from_qdd), bind(source));
        for (std::size_t i = 0; i < y.size(); ++i) b.assign("y", static_cast<int>(i), y[i]);
        routines.push_back(std::move(b).finish(options));
    }
    RoutineBuilder b(g, api_signature(RoutineId::outputs), bind({}));
    std::string qdd = "qdd";
    if (accelerations && nq > 0) {
        // rhs reads the state as one array x = [q, q'].
        b.local("x", 2 * nq);
        b.local("xdot", 2 * nq);
        for (int i = 0; i < nq; ++i) b.copy("x", i, "q", i);
        for (int i = 0; i < nq; ++i) b.copy("x", nq + i, "qd", i);
        b.call({routine_name(RoutineId::rhs), {"t", "x", "u", "p", "xdot"}});
        qdd = "xdot + " + std::to_string(nq);
    } else {
        b.local("qdd", std::max(nq, 1));
        for (int i = 0; i < std::max(nq, 1); ++i) b.assign("qdd", i, g.number(0.0));
    }
    b.call({routine_name(RoutineId::outputs_from_qdd), {"t", "q", "qd", qdd, "u", "p", "y"}});
    routines.push_back(std::move(b).finish(options));
}

} // namespace yamsc::codegen
