#include "codegen/tangent_routines.hpp"

#include "codegen/output_routines.hpp"
#include "codegen/routine_builder.hpp"
#include "codegen/symbol_binding.hpp"
#include "diag/diagnostics.hpp"

#include <algorithm>
#include <string>
#include <unordered_map>
#include <utility>

namespace yamsc::codegen {
namespace {

using NodeRow = std::vector<NodeId>;

/// The nodes the routines need, in the System's graph.
struct Imported {
    NodeRow Ma, F, dG, dY, y;
    bool mass_short_form = false; // M a depends on q, p and a only
};

class TangentModule {
public:
    TangentModule(Module& module, const ir::System& s)
        : m_(module), nq_(s.nq()), nu_(s.nu()), ny_(s.ny()), graph_(s.graph) {
        in_.Ma = s.Ma;
        in_.F = s.F;
        in_.dG = s.dG;
        in_.dY = s.dY;
        for (const ir::Output& o : s.outputs) in_.y.push_back(o.value);
        std::uint32_t depends = 0;
        for (NodeId id : in_.Ma) depends |= graph_.node(id).depends;
        const std::uint32_t allowed =
            bit(SymbolKind::q) | bit(SymbolKind::param) | bit(SymbolKind::acceleration);
        in_.mass_short_form = (depends & ~allowed) == 0;
    }

    void build() {
        m_.mass_matrix_short_form = in_.mass_short_form;
        mass_ = split(in_.Ma, SymbolKind::acceleration);
        NodeRow dgy = in_.dG;
        dgy.insert(dgy.end(), in_.dY.begin(), in_.dY.end());
        tangent_ = split(dgy, SymbolKind::seed);
        add_internal_routines();
        m_.routines.push_back(mass_matrix());
        m_.routines.push_back(forcing());
        m_.routines.push_back(jacobians());
        // The tangent form's outputs never read q'' (passes/tangent.cpp).
        add_output_routines(graph_, in_.y, nq_, false, m_.options, m_.routines);
        m_.routines.push_back(rhs());
        m_.routines.push_back(rhs_jacobian());
        if (!m_.options.linear_model || nq_ == 0) return;
        m_.routines.push_back(linear());
        m_.routines.push_back(state_space());
        m_.routines.push_back(output_matrices());
    }

private:
    static std::uint32_t bit(SymbolKind k) { return 1u << static_cast<int>(k); }
    int nx() const { return 2 * nq_; }
    int seeds() const { return 2 * nq_ + nu_; }

    RoutineBuilder builder(const char* name, const char* summary, std::vector<Argument> args,
                           SymbolSource names) {
        return RoutineBuilder(graph_, name, summary, std::move(args), bind(std::move(names)));
    }

    /// A function of the generated API, with the signature the unrolled form has.
    RoutineBuilder api(RoutineId id, SymbolSource names) {
        return RoutineBuilder(graph_, api_signature(id), bind(std::move(names)));
    }

    // ---- internal routines ----------------------------------------------------------------
    // Each sweep's callee is cut in two: a prologue that computes, once per call
    // of the public function, every value the columns share (what does not
    // depend on `a` or on the direction: kinematics, partial velocities, trig of
    // q) into a work array, and the column routine that computes only the part
    // linear in `a` or the direction from it.

    /// The nodes without `kind` that the part of `roots` with `kind` reads
    /// (numbers aside), in the order a depth-first walk meets them: the
    /// prologue's work array, slot by slot.
    std::vector<NodeId> shared_values(const NodeRow& roots, SymbolKind kind) const {
        std::vector<NodeId> values;
        std::vector<char> seen(graph_.size(), 0);
        auto visit_leaf = [&](NodeId id) {
            if (seen[id] || graph_.node(id).kind == NodeKind::number) return;
            seen[id] = 1;
            values.push_back(id);
        };
        std::vector<NodeId> stack;
        for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back(*it);
        while (!stack.empty()) {
            const NodeId id = stack.back();
            stack.pop_back();
            if (!(graph_.node(id).depends & bit(kind))) {
                visit_leaf(id);
                continue;
            }
            if (seen[id]) continue;
            seen[id] = 1;
            const OperandSpan operands = graph_.operands(id);
            for (std::size_t i = operands.size(); i-- > 0;) stack.push_back(operands[i].node);
        }
        return values;
    }

    struct Split {
        std::vector<NodeId> shared; // the prologue's outputs, by slot
        std::unordered_map<NodeId, int> slot;
    };

    Split split(const NodeRow& roots, SymbolKind kind) const {
        Split out;
        out.shared = shared_values(roots, kind);
        for (std::size_t i = 0; i < out.shared.size(); ++i)
            out.slot.emplace(out.shared[i], static_cast<int>(i));
        return out;
    }

    Routine prologue(const char* name, const char* summary, std::vector<Argument> args,
                     SymbolSource source, const char* work, const Split& part) {
        args.push_back(argument(work, ArgumentKind::output_array));
        RoutineBuilder b = builder(name, summary, std::move(args), std::move(source));
        for (std::size_t i = 0; i < part.shared.size(); ++i)
            b.assign(work, static_cast<int>(i), part.shared[i]);
        Routine r = std::move(b).finish(m_.options);
        r.internal = true;
        return r;
    }

    /// The column routine: reads the shared values from `work` (a frontier the
    /// builder does not cross) and only `own` (a or dx) otherwise.
    Routine columns(const char* name, const char* summary, const char* work, const char* own,
                    const char* output, const NodeRow& values, const Split& part,
                    SymbolSource source) {
        RoutineBuilder b = builder(name, summary,
                                   {argument(work, ArgumentKind::input_array),
                                    argument(own, ArgumentKind::input_array),
                                    argument(output, ArgumentKind::output_array)},
                                   std::move(source));
        b.set_frontier([&part, work](NodeId id) -> std::optional<Expr> {
            auto it = part.slot.find(id);
            if (it == part.slot.end()) return std::nullopt;
            return load(work, it->second);
        });
        for (std::size_t i = 0; i < values.size(); ++i)
            b.assign(output, static_cast<int>(i), values[i]);
        Routine r = std::move(b).finish(m_.options);
        r.internal = true;
        return r;
    }

    std::vector<Argument> mass_prologue_arguments() const {
        std::vector<Argument> args;
        if (!in_.mass_short_form) args.push_back(argument("t", ArgumentKind::scalar));
        args.push_back(argument("q", ArgumentKind::input_array));
        if (!in_.mass_short_form) args.push_back(argument("u", ArgumentKind::input_array));
        args.push_back(argument("p", ArgumentKind::params));
        return args;
    }

    void add_internal_routines() {
        SymbolSource only_a;
        only_a.time = only_a.q = only_a.qd = only_a.u = "";
        only_a.a = "a";
        SymbolSource only_dx;
        only_dx.time = only_dx.q = only_dx.qd = only_dx.u = "";
        only_dx.seed = "dx";
        // A time-free routine reads t as 0: the column routines have no t, and
        // the frontier leaves them none to read (bind() only asks for symbols met).
        m_.routines.push_back(prologue("mass_prologue", "what the columns of M share",
                                       mass_prologue_arguments(), SymbolSource{}, "shared", mass_));
        m_.routines.push_back(columns("mass_times", "M(q) a from the shared values", "shared", "a",
                                      "Ma", in_.Ma, mass_, only_a));
        NodeRow dgy = in_.dG;
        dgy.insert(dgy.end(), in_.dY.begin(), in_.dY.end());
        SymbolSource with_a;
        with_a.a = "a";
        m_.routines.push_back(prologue(
            "tangent_prologue", "what the directional derivatives share (a held)",
            {argument("t", ArgumentKind::scalar), argument("q", ArgumentKind::input_array),
             argument("qd", ArgumentKind::input_array), argument("u", ArgumentKind::input_array),
             argument("a", ArgumentKind::input_array), argument("p", ArgumentKind::params)},
            with_a, "shared", tangent_));
        m_.routines.push_back(columns(
            "tangent",
            "along dx = [dq, dq', du]: d(F - M a) (a held), then dy, from the shared values",
            "shared", "dx", "dgy", dgy, tangent_, only_dx));
    }

    // ---- sweeps ---------------------------------------------------------------------------
    /// M, all nq x nq entries, into `target` (row-major) by nq calls of mass_times
    /// after one mass_prologue, made exactly symmetric (lower triangle mirrored).
    void sweep_mass(RoutineBuilder& b, const std::string& target, const std::string& t,
                    const std::string& q, const std::string& u) {
        b.local("wm", std::max<int>(1, static_cast<int>(mass_.shared.size())));
        b.call({"mass_prologue", in_.mass_short_form
                                     ? std::vector<std::string>{q, "p", "wm"}
                                     : std::vector<std::string>{t, q, u, "p", "wm"}});
        Sweep s;
        s.callee = "mass_times";
        s.arguments = {"wm", ""};
        s.seed_argument = 1;
        s.seed_size = nq_;
        s.count = nq_;
        s.result_size = nq_;
        s.rows = nq_;
        s.target = target;
        s.stride = nq_;
        b.sweep(std::move(s));
        for (int i = 0; i < nq_; ++i)
            for (int j = i + 1; j < nq_; ++j) b.copy(target, i * nq_ + j, target, j * nq_ + i);
    }

    /// The shared values of the directional derivatives at `point` (t, q, qd, u,
    /// a), into the local wt: once per routine, before its tangent sweeps.
    void prepare_tangent(RoutineBuilder& b, std::vector<std::string> point) {
        b.local("wt", std::max<int>(1, static_cast<int>(tangent_.shared.size())));
        point.push_back("p");
        point.push_back("wt");
        b.call({"tangent_prologue", std::move(point)});
    }

    /// Columns [first, first + count) of the derivative of G (rows 0..nq) or of
    /// y (rows nq..nq+ny) into target[offset + i * stride + k], times scale.
    void sweep_tangent(RoutineBuilder& b, int first, int count, bool outputs,
                       const std::string& target, int offset, int stride, double scale) {
        if (count == 0 || (outputs && ny_ == 0)) return;
        Sweep s;
        s.callee = "tangent";
        s.arguments = {"wt", ""};
        s.seed_argument = 1;
        s.seed_size = seeds();
        s.first = first;
        s.count = count;
        s.result_size = nq_ + ny_;
        s.result_first = outputs ? nq_ : 0;
        s.rows = outputs ? ny_ : nq_;
        s.target = target;
        s.offset = offset;
        s.stride = stride;
        s.scale = scale;
        b.sweep(std::move(s));
    }

    void zeros(RoutineBuilder& b, const char* local) {
        b.local(local, nq_);
        for (int i = 0; i < nq_; ++i) b.assign(local, i, graph_.number(0.0));
    }

    // ---- public routines ------------------------------------------------------------------
    Routine mass_matrix() {
        RoutineBuilder b = api(RoutineId::mass_matrix, SymbolSource{});
        sweep_mass(b, "M", "t", "q", "u");
        return std::move(b).finish(m_.options);
    }

    Routine forcing() {
        RoutineBuilder b = api(RoutineId::forcing, SymbolSource{});
        for (int i = 0; i < nq_; ++i) b.assign("F", i, in_.F[static_cast<std::size_t>(i)]);
        return std::move(b).finish(m_.options);
    }

    Routine jacobians() {
        RoutineBuilder b = api(RoutineId::jacobians, SymbolSource{});
        zeros(b, "a0"); // with a = 0 the derivative of F - M a is that of F
        prepare_tangent(b, {"t", "q", "qd", "u", "a0"});
        sweep_tangent(b, 0, nq_, false, "dF_dq", 0, nq_, 1.0);
        sweep_tangent(b, nq_, nq_, false, "dF_dqd", 0, nq_, 1.0);
        sweep_tangent(b, nx(), nu_, false, "dF_du", 0, nu_, 1.0);
        return std::move(b).finish(m_.options);
    }

    Routine rhs() {
        RoutineBuilder b = api(RoutineId::rhs, SymbolSource::state_vector(nq_));
        if (nq_ == 0) return std::move(b).finish(m_.options);
        b.local("M", nq_ * nq_);
        for (int i = 0; i < nq_; ++i) b.assign("xdot", i, graph_.symbol({SymbolKind::qd, i}));
        for (int i = 0; i < nq_; ++i) b.assign("xdot", nq_ + i, in_.F[static_cast<std::size_t>(i)]);
        sweep_mass(b, "M", "t", "x", "u");
        b.factor("M", nq_);
        b.solve("M", nq_, "xdot", nq_, 1);
        return std::move(b).finish(m_.options);
    }

    // J = [[0, I], [M^-1 dG/dq, M^-1 dG/dq']] with a = q'' (as in the unrolled form).
    Routine rhs_jacobian() {
        RoutineBuilder b = api(RoutineId::rhs_jacobian, SymbolSource::state_vector(nq_));
        if (nq_ == 0) return std::move(b).finish(m_.options);
        const int nx = this->nx();
        b.local("M", nq_ * nq_);
        b.local("qdd", nq_);
        for (int i = 0; i < nq_; ++i)
            for (int j = 0; j < nx; ++j)
                b.assign("J", i * nx + j, graph_.number(j == nq_ + i ? 1.0 : 0.0));
        for (int i = 0; i < nq_; ++i) b.assign("qdd", i, in_.F[static_cast<std::size_t>(i)]);
        sweep_mass(b, "M", "t", "x", "u");
        b.factor("M", nq_);
        b.solve("M", nq_, "qdd", 0, 1);
        prepare_tangent(b, {"t", "x", "x + " + std::to_string(nq_), "u", "qdd"});
        sweep_tangent(b, 0, nx, false, "J", nq_ * nx, nx, 1.0);
        b.solve("M", nq_, "J", nq_ * nx, nx);
        return std::move(b).finish(m_.options);
    }

    /// The local M factorised and the accelerations qdd0 = M^-1 F at the point;
    /// M copied from `mass` when the routine has computed it there already.
    void factor_at_point(RoutineBuilder& b, const char* mass = nullptr) {
        b.local("M", nq_ * nq_);
        b.local("qdd0", nq_);
        for (int i = 0; i < nq_; ++i) b.assign("qdd0", i, in_.F[static_cast<std::size_t>(i)]);
        if (mass == nullptr)
            sweep_mass(b, "M", "0.0", "q0", "u0");
        else
            for (int i = 0; i < nq_; ++i)
                for (int j = 0; j <= i; ++j) b.copy("M", i * nq_ + j, mass, i * nq_ + j);
        b.factor("M", nq_);
        b.solve("M", nq_, "qdd0", 0, 1);
    }

    Routine linear() {
        RoutineBuilder b = api(RoutineId::linear, SymbolSource::operating_point());
        sweep_mass(b, "M0", "0.0", "q0", "u0");
        factor_at_point(b, "M0");
        prepare_tangent(b, {"0.0", "q0", "qd0", "u0", "qdd0"});
        sweep_tangent(b, nq_, nq_, false, "C0", 0, nq_, -1.0);
        sweep_tangent(b, 0, nq_, false, "K0", 0, nq_, -1.0);
        sweep_tangent(b, nx(), nu_, false, "Q0", 0, nu_, 1.0);
        return std::move(b).finish(m_.options);
    }

    Routine state_space() {
        RoutineBuilder b = api(RoutineId::state_space, SymbolSource::operating_point());
        const int nx = this->nx();
        for (int i = 0; i < nq_; ++i)
            for (int j = 0; j < nx; ++j)
                b.assign("A", i * nx + j, graph_.number(j == nq_ + i ? 1.0 : 0.0));
        for (int i = 0; i < nq_; ++i)
            for (int j = 0; j < nu_; ++j) b.assign("B", i * nu_ + j, graph_.number(0.0));
        factor_at_point(b);
        prepare_tangent(b, {"0.0", "q0", "qd0", "u0", "qdd0"});
        sweep_tangent(b, 0, nx, false, "A", nq_ * nx, nx, 1.0);
        sweep_tangent(b, nx, nu_, false, "B", nq_ * nu_, nu_, 1.0);
        b.solve("M", nq_, "A", nq_ * nx, nx);
        if (nu_ > 0) b.solve("M", nq_, "B", nq_ * nu_, nu_);
        return std::move(b).finish(m_.options);
    }

    Routine output_matrices() {
        RoutineBuilder b = api(RoutineId::output_matrices, SymbolSource::operating_point());
        if (ny_ > 0) zeros(b, "a0");
        if (ny_ > 0) prepare_tangent(b, {"0.0", "q0", "qd0", "u0", "a0"});
        sweep_tangent(b, 0, nx(), true, "C", 0, nx(), 1.0);
        sweep_tangent(b, nx(), nu_, true, "D", 0, nu_, 1.0);
        return std::move(b).finish(m_.options);
    }

    Module& m_;
    const int nq_, nu_, ny_;
    Graph graph_;
    Imported in_;
    Split mass_, tangent_; // what the prologues compute for the column routines
};

} // namespace

void add_tangent_routines(Module& module, const ir::System& s) {
    const int nq = s.nq(), ny = s.ny();
    if (!s.tangent_form || static_cast<int>(s.Ma.size()) != nq ||
        static_cast<int>(s.F.size()) != nq || static_cast<int>(s.dG.size()) != nq ||
        static_cast<int>(s.dY.size()) != ny)
        throw diag::InternalError("code generation: the equations are not in tangent form");
    if (s.graph.max_multiplied_power() != module.options.max_multiplied_power)
        throw diag::InternalError("code generation: the IR's normal form has another "
                                  "max_multiplied_power");
    TangentModule(module, s).build();
}

} // namespace yamsc::codegen
