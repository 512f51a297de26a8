#pragma once
// Import of GiNaC expressions into the IR graph: the one conversion of the
// equations' representation, made after Kane's method. The expressions of
// symbolic::Equations are DAGs with heavy sharing, so the walk is memoised on
// node identity (the address of the GiNaC node, kept alive while the importer
// lives so that no address is reused) and never calls GiNaC's own recursive
// operations. It is iterative: deep expressions cannot overflow the stack.
// Beware that GiNaC's compare() re-points one of two equal handles to the
// other's object ("sharing"): a handle whose identity is memoised must never
// be compared (look symbols up through copies).
#include "ir/graph.hpp"
#include "lower/identity_map.hpp"
#include "symbolic/equations.hpp"

#include <map>
#include <utility>
#include <vector>

namespace yamsc::lower {

using ir::Graph;
using ir::NodeId;
using ir::SymbolRef;

class GinacImporter {
public:
    /// Knows every symbol of `eq` (t, q, q', q'', inputs, parameters, `a`).
    GinacImporter(Graph& graph, const symbolic::Equations& eq);

    /// The node of `e`. Throws diag::InternalError on what generated code cannot
    /// express: unknown symbols, complex numbers, unsupported functions or classes.
    NodeId import(const GiNaC::ex& e);

private:
    struct Frame;
    void expand(Frame& frame);
    NodeId build(const Frame& frame);
    NodeId leaf(GiNaC::ex e);
    NodeId memoised(const GiNaC::ex& e) const;
    void remember(const GiNaC::ex& e, NodeId id);

    Graph& graph_;
    std::map<GiNaC::ex, SymbolRef, GiNaC::ex_is_less> symbols_;
    IdentityMap memo_;
    std::vector<GiNaC::ex> keep_alive_;
    // The operands of the frames being imported, each frame's contiguous.
    std::vector<std::pair<GiNaC::ex, double>> pending_;
};

} // namespace yamsc::lower
