// linear_sensitivities: d/dp of M0, C0, K0, Q0 (docs/linearization.md). With
// q''0 = M0^-1 F0 and a the vector of dMa_dq:
//
//   dM0/dp = dM/dp,  dC0/dp = -d(dF_dq')/dp,  dQ0/dp = d(dF_du)/dp,
//   dK0/dp = d(dMa_dq)/dp |a=q''0 + dMa_dq |a=dq''0/dp - d(dF_dq)/dp,
//   dq''0/dp = M0^-1 (dF/dp - dM/dp q''0).
//
// The second term of dK0/dp is the chain rule through q''0: dMa_dq = d(M a)/dq
// is linear and homogeneous in a, so its derivative along dq''0/dp is dMa_dq
// itself with a replaced by dq''0/dp. The partial derivatives in p come from the
// pass passes::parameter_derivatives (forward mode on the IR); the solves with
// M0 are steps of the routine, as in `linear`.
#include "codegen/sensitivity_routines.hpp"

#include "codegen/routine_builder.hpp"
#include "codegen/symbol_binding.hpp"
#include "diag/diagnostics.hpp"
#include "ir/param_index.hpp"

#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>

namespace yamsc::codegen {
namespace {

using NodeMatrix = std::vector<std::vector<NodeId>>;

constexpr std::uint32_t acceleration_bit = 1u << static_cast<int>(SymbolKind::acceleration);

/// As the point binding of linear_routines.cpp (q0, qd0, u0, p, t = 0, `a` from
/// the solved accelerations qdd0), plus the derivatives of the accelerations:
/// the symbol q''[s k + j] stands for dq''0_s/dp_j, the local dqdd0 (nq x k,
/// row-major). q'' itself never occurs in M, F or their Jacobians, so the kind
/// is free for this use in this routine.
SymbolSource point_with_acceleration_derivatives() {
    SymbolSource s = SymbolSource::operating_point();
    s.qdd = "dqdd0";
    return s;
}

/// `root` with every acceleration symbol a_s replaced by replacement[s], rebuilt
/// through the Graph's constructors (so the result is in normal form and shares
/// what it can). Iterative; only nodes that depend on `a` are visited, each once
/// per `done` (one memo per replacement).
NodeId substitute_accelerations(Graph& g, NodeId root, const std::vector<NodeId>& replacement,
                                std::unordered_map<NodeId, NodeId>& done) {
    auto settled = [&](NodeId id) {
        return (g.node(id).depends & acceleration_bit) == 0 || done.count(id) > 0;
    };
    auto value = [&](NodeId id) {
        return (g.node(id).depends & acceleration_bit) == 0 ? id : done.at(id);
    };
    struct Frame {
        NodeId node;
        std::size_t next;
    };
    std::vector<Frame> stack;
    if (!settled(root)) stack.push_back({root, 0});
    while (!stack.empty()) {
        const NodeId id = stack.back().node;
        // Copies: the Graph's storage moves when nodes are added.
        const Node n = g.node(id);
        if (n.kind == NodeKind::symbol) {
            if (n.symbol.kind != SymbolKind::acceleration ||
                static_cast<std::size_t>(n.symbol.index) >= replacement.size())
                throw diag::InternalError("code generation: unexpected symbol depending on `a`");
            done[id] = replacement[static_cast<std::size_t>(n.symbol.index)];
            stack.pop_back();
            continue;
        }
        const std::size_t count = g.operands(id).size();
        if (stack.back().next < count) {
            const NodeId child = g.operands(id)[stack.back().next++].node;
            if (!settled(child)) stack.push_back({child, 0});
            continue;
        }
        std::vector<Operand> operands;
        for (const Operand& op : g.operands(id)) operands.push_back({value(op.node), op.weight});
        NodeId rebuilt = id;
        switch (n.kind) {
        case NodeKind::add:
            rebuilt = g.add(std::move(operands), n.value);
            break;
        case NodeKind::mul:
            rebuilt = g.mul(std::move(operands), n.value);
            break;
        case NodeKind::call: {
            std::vector<NodeId> arguments;
            for (const Operand& op : operands) arguments.push_back(op.node);
            rebuilt = g.call(n.function, arguments);
            break;
        }
        case NodeKind::number:
        case NodeKind::symbol:
            break;
        }
        done[id] = rebuilt;
        stack.pop_back();
    }
    return value(root);
}

bool uses_accelerations(const Graph& g, const NodeMatrix& m) {
    for (const auto& row : m)
        for (NodeId id : row)
            if (g.node(id).depends & acceleration_bit) return true;
    return false;
}

using ImportedDerivatives = ir::ParameterDerivatives;

std::vector<std::size_t> parameter_indices(const ir::System& s,
                                           const std::vector<std::string>& names) {
    std::vector<std::size_t> out;
    for (const std::string& name : names) {
        const std::optional<std::size_t> i = ir::param_index(s, name);
        if (!i)
            throw diag::InternalError("code generation: sensitivity of '" + name +
                                      "', which is not a parameter");
        out.push_back(*i);
    }
    return out;
}

Routine sensitivity_routine(Graph& g, const LinearSources& in,
                            const std::vector<ImportedDerivatives>& d, int nq, int nu,
                            const Options& options) {
    const int k = static_cast<int>(d.size()), nn = nq * nq;
    std::string names;
    for (const std::string& name : options.sensitivity_params)
        names += (names.empty() ? "" : ", ") + name;
    RoutineBuilder::Signature signature = api_signature(RoutineId::linear_sensitivities);
    signature.summary += " for p = (" + names +
                         "): one nq x nq block per parameter, in that order (nq x nu for dQ0)";
    RoutineBuilder b(g, std::move(signature), bind(point_with_acceleration_derivatives()));
    // Without `a` in dMa_dq (M independent of q) K0 does not involve q''0.
    const bool accelerations = uses_accelerations(g, in.dMa_dq);
    if (accelerations) {
        b.local("M", nn);
        b.local("qdd0", nq);
        b.local("dqdd0", nq * k);
    }
    for (int j = 0; j < k; ++j) {
        for (int i = 0; i < nq; ++i)
            for (int c = 0; c <= i; ++c) b.assign("dM0", j * nn + i * nq + c, d[j].M[i][c]);
        for (int i = 0; i < nq; ++i)
            for (int c = i + 1; c < nq; ++c)
                b.copy("dM0", j * nn + i * nq + c, "dM0", j * nn + c * nq + i);
    }
    for (int j = 0; j < k; ++j)
        for (int i = 0; i < nq; ++i)
            for (int c = 0; c < nq; ++c)
                b.assign("dC0", j * nn + i * nq + c, g.add({{d[j].dF_dqd[i][c], -1.0}}, 0));
    for (int j = 0; j < k; ++j)
        for (int i = 0; i < nq; ++i)
            for (int c = 0; c < nu; ++c) b.assign("dQ0", (j * nq + i) * nu + c, d[j].dF_du[i][c]);
    if (accelerations) {
        for (int i = 0; i < nq; ++i)
            for (int c = 0; c <= i; ++c) b.assign("M", i * nq + c, in.M[i][c]);
        for (int i = 0; i < nq; ++i) b.assign("qdd0", i, in.F[static_cast<std::size_t>(i)]);
        b.factor("M", nq);
        b.solve("M", nq, "qdd0", 0, 1);
        // dqdd0 = dF/dp - dM/dp q''0, column j for parameter j, then M0^-1 of it.
        for (int s = 0; s < nq; ++s)
            for (int j = 0; j < k; ++j) {
                std::vector<Operand> terms{{d[j].F[static_cast<std::size_t>(s)], 1.0}};
                for (int c = 0; c < nq; ++c) {
                    const NodeId dM = c <= s ? d[j].M[s][c] : d[j].M[c][s];
                    terms.push_back(
                        {g.mul({{dM, 1.0}, {g.symbol({SymbolKind::acceleration, c}), 1.0}}, 1.0),
                         -1.0});
                }
                b.assign("dqdd0", s * k + j, g.add(std::move(terms), 0));
            }
        b.solve("M", nq, "dqdd0", 0, k);
    }
    for (int j = 0; j < k; ++j) {
        std::vector<NodeId> replacement;
        for (int s = 0; s < nq; ++s) replacement.push_back(g.symbol({SymbolKind::qdd, s * k + j}));
        std::unordered_map<NodeId, NodeId> done;
        for (int i = 0; i < nq; ++i)
            for (int c = 0; c < nq; ++c) {
                std::vector<Operand> terms{{d[j].dMa_dq[i][c], 1.0}, {d[j].dF_dq[i][c], -1.0}};
                if (accelerations)
                    terms.push_back(
                        {substitute_accelerations(g, in.dMa_dq[i][c], replacement, done), 1.0});
                b.assign("dK0", j * nn + i * nq + c, g.add(std::move(terms), 0));
            }
    }
    return std::move(b).finish(options);
}

} // namespace

void add_sensitivity_routine(Graph& graph, const ir::System& s, const LinearSources& in,
                             const Options& options, std::vector<Routine>& routines) {
    const int nq = s.nq();
    if (options.sensitivity_params.empty() || nq == 0) return;
    if (parameter_indices(s, options.sensitivity_params) != s.sensitivity_params ||
        s.sensitivities.size() != s.sensitivity_params.size())
        throw diag::InternalError("code generation: the parameter derivatives of the "
                                  "sensitivities were not derived");
    routines.push_back(sensitivity_routine(graph, in, s.sensitivities, nq, s.nu(), options));
}

} // namespace yamsc::codegen
