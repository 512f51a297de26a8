#include "symbolic/derive.hpp"

#include "model/names.hpp"
#include "symbolic/constraints/registry.hpp"
#include "symbolic/flexible_body.hpp"
#include "symbolic/kinematics.hpp"
#include "symbolic/projection.hpp"
#include "symbolic/reactions.hpp"

namespace yamsc::symbolic {

using namespace GiNaC;

namespace {

/// Components in `frame`'s axes of a vector whose components are in `from`'s axes
/// (-1 is ground).
Vec3 change_axes(const Vec3& v, int from, int to, const std::vector<FrameState>& frames) {
    if (from == to) return v;
    Vec3 g = from < 0 ? v : frames[static_cast<std::size_t>(from)].R * v;
    return to < 0 ? g : transpose_times(frames[static_cast<std::size_t>(to)].R, g);
}

class Kane {
public:
    Kane(const model::Model& m, diag::Diagnostics& diags, const DeriveOptions& options)
        : m_(m), diags_(diags), sym_(m), mass_matrix_(options.mass_matrix), options_(options) {}

    std::optional<Equations> run() {
        frames_ = body_frames(m_, sym_);
        const std::size_t nq = m_.dofs.size();
        eq_.M.assign(nq, Row(nq, 0));
        for (const auto& d : sym_.dofs()) eq_.a.emplace_back("a_" + d.name);
        eq_.t = sym_.t(); // the symbols first: options_.cost reads them
        eq_.dofs = sym_.dofs();
        eq_.inputs = sym_.inputs();
        eq_.params = sym_.params();
        Ma_terms_.assign(nq, exvector{});
        std::vector<exvector> F_terms(nq);
        std::vector<exvector> load_terms(nq); // may contain q'': moved into M below

        Vec3 g = to_ginac(m_.gravity, sym_);
        std::vector<Wrench> applied = applied_wrenches();
        std::vector<BodyTerms> terms;
        for (std::size_t b = 0; b < m_.bodies.size(); ++b) {
            const model::Body& body = m_.bodies[b];
            const FrameState& f = frames_[b];
            add_applied_loads(f, applied[b], load_terms);
            const Vec3 g_local = transpose_times(f.R, g);
            terms.push_back(body.flex ? flexible_body_terms(body, f, g_local, sym_)
                                      : rigid_body_terms(body, f, g_local, sym_));
        }
        project(relative_frames(), terms, F_terms);
        for (std::size_t r = 0; r < nq; ++r)
            for (std::size_t s = 0; s < r; ++s) eq_.M[r][s] = eq_.M[s][r];
        generalized_loads(load_terms);
        if (!move_accelerations_into_mass(load_terms)) return std::nullopt;
        if (!mass_matrix_) eq_.M.clear(); // only the loads' q'' terms
        eq_.Ma.resize(nq);
        for (std::size_t r = 0; r < nq; ++r)
            eq_.Ma[r] = Ma_terms_[r].empty() ? ex(0) : ex(add(Ma_terms_[r]));
        eq_.F.resize(nq);
        for (std::size_t r = 0; r < nq; ++r) {
            exvector all = F_terms[r];
            all.insert(all.end(), load_terms[r].begin(), load_terms[r].end());
            eq_.F[r] = all.empty() ? ex(0) : ex(add(all));
        }
        outputs();
        eq_.constraints = derive_constraints(m_, sym_, frames_);
        eq_.model_name = m_.name;
        eq_.title = m_.title;
        return std::move(eq_);
    }

private:
    /// M (upper triangle), F and M a from the bodies' terms, with the grouping
    /// into composite bodies that costs the fewest operations for this model.
    void project(const std::vector<FrameState>& relative, const std::vector<BodyTerms>& terms,
                 std::vector<exvector>& F_terms) {
        const std::size_t nq = m_.dofs.size();
        std::optional<double> best;
        Matrix best_M;
        exvector best_F;
        std::vector<Grouping> groupings{Grouping::all};
        if (options_.grouping)
            groupings = {*options_.grouping};
        else if (options_.cost)
            groupings = {Grouping::none, Grouping::flexible, Grouping::all};
        for (Grouping grouping : groupings) {
            Projection projection(m_, frames_, relative, terms, grouping);
            Matrix M(nq, Row(nq, 0));
            exvector F, all;
            // M: O(DOFs²) entries, by far the largest cost of large models;
            // skipped in the tangent form, which needs only M a.
            for (std::size_t r = 0; mass_matrix_ && r < nq; ++r)
                for (std::size_t s = r; s < nq; ++s) {
                    M[r][s] = projection.mass(static_cast<int>(r), static_cast<int>(s));
                    all.push_back(M[r][s]);
                }
            for (std::size_t r = 0; r < nq; ++r) {
                F.push_back(projection.force(static_cast<int>(r)));
                all.push_back(F.back());
            }
            // The first of equal costs: a grouping only where it saves.
            const double cost = groupings.size() > 1 ? options_.cost(eq_, all) : 0.0;
            if (best && cost >= *best) continue;
            best = cost;
            best_M = std::move(M);
            best_F = std::move(F);
        }
        for (std::size_t r = 0; mass_matrix_ && r < nq; ++r)
            for (std::size_t s = r; s < nq; ++s) eq_.M[r][s] = best_M[r][s];
        for (std::size_t r = 0; r < nq; ++r) F_terms[r].push_back(best_F[r]);
        add_mass_times(frames_, terms, eq_.a, Ma_terms_);
    }

    /// Each body's frame in its parent's: its joint steps from the identity.
    std::vector<FrameState> relative_frames() {
        std::vector<FrameState> out;
        for (std::size_t b = 0; b < m_.bodies.size(); ++b) {
            const model::Body& body = m_.bodies[b];
            if (body.parent < 0) {
                out.push_back(frames_[b]);
                continue;
            }
            FrameState f = FrameState::ground();
            const model::Body& parent = m_.bodies[static_cast<std::size_t>(body.parent)];
            for (const auto& step : body.steps) f = apply_step(f, step, sym_, &parent);
            out.push_back(std::move(f));
        }
        return out;
    }

    /// Applied forces and moments about the body origin (eq. 7, 9, 19).
    static void add_applied_loads(const FrameState& f, const Wrench& w,
                                  std::vector<exvector>& load_terms) {
        for (const auto& [r, jv] : f.Jv)
            load_terms[static_cast<std::size_t>(r)].push_back(dot(jv, w.force));
        for (const auto& [r, jw] : f.Jw)
            load_terms[static_cast<std::size_t>(r)].push_back(dot(jw, w.moment));
    }

    std::vector<Wrench> applied_wrenches() {
        std::vector<Wrench> w(m_.bodies.size());
        for (const auto& f : m_.forces) {
            auto b = static_cast<std::size_t>(f.body);
            Vec3 value = change_axes(to_ginac(f.value, sym_), f.frame, f.body, frames_);
            Vec3 at = to_ginac(f.at, sym_);
            w[b].force = w[b].force + value;
            w[b].moment = w[b].moment + cross(at, value);
        }
        for (const auto& t : m_.torques) {
            auto b = static_cast<std::size_t>(t.body);
            w[b].moment =
                w[b].moment + change_axes(to_ginac(t.value, sym_), t.frame, t.body, frames_);
        }
        return w;
    }

    void generalized_loads(std::vector<exvector>& load_terms) {
        const auto& dofs = sym_.dofs();
        for (const auto& s : m_.springs) {
            auto r = static_cast<std::size_t>(s.dof);
            if (s.stiffness) load_terms[r].push_back(-to_ginac(*s.stiffness, sym_) * dofs[r].q);
            if (s.damping) load_terms[r].push_back(-to_ginac(*s.damping, sym_) * dofs[r].qd);
        }
        for (const auto& g : m_.genforces)
            load_terms[static_cast<std::size_t>(g.dof)].push_back(to_ginac(g.value, sym_));
    }

    /// Loads may use q'' (e.g. added mass): their q'' part belongs to M. They must be
    /// linear in q''.
    bool move_accelerations_into_mass(std::vector<exvector>& load_terms) {
        const auto& dofs = sym_.dofs();
        std::vector<symbol> qdd;
        for (const auto& d : dofs) qdd.push_back(d.qdd);
        DependsOn uses_qdd(qdd);
        exmap zero;
        for (const auto& d : dofs) zero[d.qdd] = 0;
        Substituter drop_qdd(zero);
        bool ok = true;
        for (std::size_t r = 0; r < load_terms.size(); ++r) {
            ex G = load_terms[r].empty() ? ex(0) : ex(add(load_terms[r]));
            if (!uses_qdd(G)) continue;
            for (std::size_t s = 0; s < dofs.size(); ++s) {
                ex coeff = sym_.diff(G, dofs[s].qdd);
                if (coeff.is_zero()) continue;
                if (uses_qdd(coeff)) {
                    diags_.error(diag::Kind::InvalidValue, m_.dofs[r].loc,
                                 "the loads on DOF '" + m_.dofs[r].name +
                                     "' are nonlinear in accelerations (q'')");
                    ok = false;
                    continue;
                }
                eq_.M[r][s] -= coeff;
                Ma_terms_[r].push_back(-coeff * eq_.a[s]);
            }
            load_terms[r] = {drop_qdd(G)};
        }
        return ok;
    }

    // ---- outputs ------------------------------------------------------------------------
    /// The frame of SID node `node` of flexible body `body`: where a joint on it
    /// starts (elastic rotation `exact`, about x, then y, then z).
    const FrameState& node_frame(int body, int node) {
        auto it = node_frames_.find({body, node});
        if (it != node_frames_.end()) return it->second;
        model::Step step;
        step.kind = model::Step::Kind::node;
        step.node = node;
        step.exact_rotation = true;
        const auto b = static_cast<std::size_t>(body);
        FrameState f = apply_step(frames_[b], step, sym_, &m_.bodies[b]);
        return node_frames_.emplace(std::make_pair(body, node), std::move(f)).first->second;
    }

    Vec3 kinematic(const std::string& fn, const model::Expr& target_expr, int frame_body,
                   int frame_node) {
        const std::string& target = target_expr.text;
        // The axes (and, for positions, the origin) of the output's frame: a body's
        // or one of its nodes' (`in tower.node(10)`); null for ground.
        const FrameState* k = frame_body < 0    ? nullptr
                              : frame_node >= 0 ? &node_frame(frame_body, frame_node)
                                                : &frames_[static_cast<std::size_t>(frame_body)];
        if (model::is_reaction_function(fn)) {
            if (!reactions_) reactions_.emplace(m_, frames_, sym_, applied_wrenches());
            const int body = m_.body_index(target);
            const Wrench& w = target_expr.kind == model::Expr::Kind::section
                                  ? reactions_->section(body, target_expr.primes,
                                                        node_frame(body, target_expr.primes))
                                  : reactions_->of(body);
            const Vec3& g = fn == "reaction_force" ? w.force : w.moment;
            return k ? transpose_times(k->R, g) : g;
        }
        Vec3 r, v, w;
        int body = m_.body_index(target);
        if (target == "ground") {
            // All zeros: ground does not move.
        } else if (body >= 0) {
            const FrameState& f = frames_[static_cast<std::size_t>(body)];
            r = f.r;
            v = f.R * f.v;
            w = f.R * f.w;
        } else {
            const model::Point& p = m_.points[static_cast<std::size_t>(m_.point_index(target))];
            const FrameState& f = frames_[static_cast<std::size_t>(p.body)];
            Vec3 at = to_ginac(p.at, sym_);
            r = f.r + f.R * at;
            v = f.R * (f.v + cross(f.w, at));
        }
        if (fn == "position") return k ? transpose_times(k->R, r - k->r) : r;
        const Vec3& g = fn == "velocity" ? v : w;
        return k ? transpose_times(k->R, g) : g;
    }

    void outputs() {
        std::vector<symbol> qdd;
        for (const auto& d : sym_.dofs()) qdd.push_back(d.qdd);
        DependsOn uses_qdd(qdd);
        for (const auto& o : m_.outputs) {
            KinematicsHook hook = [&](const std::string& fn, const model::Expr& target) {
                return kinematic(fn, target, o.frame, o.frame_node);
            };
            Output y{o.name, o.doc, to_ginac(o.value, sym_, hook), {}};
            // Reactions and q'' read the accelerations: the linear model needs ∂y/∂q''.
            if (uses_qdd(y.value))
                for (const auto& d : sym_.dofs()) y.dqdd.push_back(sym_.diff(y.value, d.qdd));
            eq_.outputs.push_back(std::move(y));
        }
    }

    const model::Model& m_;
    diag::Diagnostics& diags_;
    Symbols sym_;
    bool mass_matrix_;
    const DeriveOptions& options_;
    std::vector<FrameState> frames_;
    std::vector<exvector> Ma_terms_;                        // terms of (M a)_r
    std::optional<Reactions> reactions_;                    // built when an output asks for one
    std::map<std::pair<int, int>, FrameState> node_frames_; // (body, node): cut sections
    Equations eq_;
};

} // namespace

std::optional<Equations> derive(const model::Model& m, diag::Diagnostics& diags,
                                const DeriveOptions& options) {
    return Kane(m, diags, options).run();
}

} // namespace yamsc::symbolic
