#include "model/checker.hpp"

#include "model/constraint_check.hpp"

#include "model/expr_check.hpp"
#include "model/flexible.hpp"
#include "model/load_check.hpp"
#include "model/mesh_channels.hpp"

#include <algorithm>
#include <functional>
#include <map>
#include <set>

namespace yamsc::model {

using diag::Kind;

int Model::body_index(const std::string& name) const {
    for (std::size_t i = 0; i < bodies.size(); ++i)
        if (bodies[i].name == name) return static_cast<int>(i);
    return -1;
}

int Model::point_index(const std::string& name) const {
    for (std::size_t i = 0; i < points.size(); ++i)
        if (points[i].name == name) return static_cast<int>(i);
    return -1;
}

namespace {

Expr number(const std::string& text, const Loc& loc) {
    return Expr{Expr::Kind::number, loc, text, 0, {}};
}

Vec zero_vec(const Loc& loc) {
    return {number("0", loc), number("0", loc), number("0", loc)};
}

class Checker {
public:
    Checker(const ast::ModelFile& file, DataSource& data, diag::Diagnostics& diags)
        : file_(file), data_(data), diags_(diags), exprs_(names_, model_.inputs, diags) {}

    std::optional<Model> run() {
        model_.source = file_.source;
        declare_model();
        declare_names();
        check_params();
        build_bodies();
        check_loads();
        check_outputs();
        model_.loads = check_load_blocks(file_, model_, names_, diags_);
        model_.constraints = check_constraints(file_, model_, names_, exprs_, diags_);
        if (!diags_.has_errors()) add_mesh_channels(model_);
        check_externals();
        check_dof_usage();
        check_linearize();
        check_initial_state();
        check_approximations();
        if (diags_.has_errors()) return std::nullopt;
        return std::move(model_);
    }

private:
    // ---- declarations -------------------------------------------------------------
    void declare_model() {
        if (!file_.model) {
            diag::Location loc{file_.source, 1, 1};
            diags_.error(Kind::MissingModel, loc,
                         "the file has no model declaration (start it with `model NAME`)");
            return;
        }
        model_.name = file_.model->name;
        model_.title = file_.title;
        std::string why = reserved_reason(model_.name);
        if (!why.empty())
            diags_.error(Kind::ReservedName, file_.model->loc,
                         "model name '" + model_.name + "' " + why);
    }

    bool declare(const std::string& name, NameKind kind, int index, const Loc& loc) {
        std::string why = reserved_reason(name);
        if (!why.empty()) {
            diags_.error(Kind::ReservedName, loc, "'" + name + "' " + why);
            return false;
        }
        auto [it, fresh] = names_.emplace(name, NameInfo{kind, index, loc});
        if (!fresh) {
            diags_.error(Kind::DuplicateName, loc, "'" + name + "' is already declared");
            diags_.note(it->second.loc, "'" + name + "' was declared here");
            return false;
        }
        return true;
    }

    void declare_names() {
        for (const auto& p : file_.params) {
            declare(p.id.name, NameKind::param, static_cast<int>(model_.params.size()), p.id.loc);
            model_.params.push_back({p.id.name, p.id.doc, std::nullopt, p.id.loc});
        }
        for (const auto& in : file_.inputs) {
            declare(in.id.name, NameKind::input, static_cast<int>(model_.inputs.size()), in.id.loc);
            if (in.order < 0 || in.order > 2)
                diags_.error(Kind::InvalidValue, in.id.loc,
                             "input order must be 0, 1 or 2, not " + std::to_string(in.order));
            model_.inputs.push_back({in.id.name, in.id.doc, in.order, in.id.loc});
        }
        for (const auto& d : file_.dofs) {
            declare(d.name, NameKind::dof, static_cast<int>(model_.dofs.size()), d.loc);
            model_.dofs.push_back({d.name, d.doc, d.loc});
        }
        int body = 0;
        for (const auto& b : file_.rigid_bodies) declare(b.name, NameKind::body, body++, b.loc);
        for (const auto& b : file_.flexible_bodies) declare(b.name, NameKind::body, body++, b.loc);
        int point = 0;
        for (const auto& p : file_.points) declare(p.id.name, NameKind::point, point++, p.id.loc);
    }

    void check_params() {
        for (std::size_t i = 0; i < file_.params.size(); ++i) {
            const auto& p = file_.params[i];
            if (!p.value) continue;
            ExprContext ctx{"the default of parameter '" + p.id.name + "'"};
            if (!exprs_.scalar(*p.value, ctx)) continue;
            std::string why;
            auto v = evaluate_constant(*p.value, why);
            if (!v)
                diags_.error(Kind::NotConstant, p.value->loc,
                             "the default of parameter '" + p.id.name +
                                 "' must be a constant number: it " + why);
            else
                model_.params[i].value = *v;
        }
        if (file_.gravity) {
            ExprContext ctx{"gravity"};
            if (auto v = exprs_.vector(*file_.gravity, ctx)) model_.gravity = *v;
        } else {
            model_.gravity = zero_vec(file_.source ? Loc{file_.source, 1, 1} : Loc{});
        }
    }

    // ---- bodies and joints ----------------------------------------------------------
    static ExprContext constant_ctx(std::string what) { return ExprContext{std::move(what)}; }

    ExprContext step_ctx(const std::string& body) const {
        ExprContext ctx{"a joint step of body '" + body + "'"};
        ctx.dofs = true;
        ctx.inputs = true;
        ctx.input_extra_order = 2;
        ctx.time = true;
        return ctx;
    }

    std::optional<Body> rigid_body(const ast::RigidBody& rb) {
        Body b;
        b.name = rb.name;
        b.kind = Body::Kind::rigid;
        b.loc = rb.loc;
        b.com = zero_vec(rb.loc);
        for (auto& e : b.inertia) e = number("0", rb.loc);
        bool has_mass = false;
        std::set<std::string> seen;
        for (const auto& prop : rb.properties) {
            if (!seen.insert(prop.key).second) {
                diags_.error(Kind::DuplicateName, prop.loc,
                             "property '" + prop.key + "' is given twice");
                continue;
            }
            if (prop.value.kind != ast::Value::Kind::expr) {
                diags_.error(Kind::InvalidValue, prop.value.loc,
                             "property '" + prop.key + "' of a rigid body takes an expression");
                continue;
            }
            const Expr& v = prop.value.expr;
            std::string what = "the " + prop.key + " of body '" + rb.name + "'";
            if (prop.key == "mass") {
                has_mass = exprs_.scalar(v, constant_ctx(what));
                if (has_mass) b.mass = v;
            } else if (prop.key == "com") {
                if (auto c = exprs_.vector(v, constant_ctx(what))) b.com = *c;
            } else if (prop.key == "inertia") {
                if (v.kind != Expr::Kind::vector || (v.args.size() != 3 && v.args.size() != 6)) {
                    diags_.error(Kind::InvalidValue, v.loc,
                                 "inertia takes 3 entries (Jxx, Jyy, Jzz) or 6 (Ixx, Iyy, Izz, "
                                 "Ixy, Iyz, Ixz)");
                    continue;
                }
                bool ok = true;
                for (const Expr& a : v.args) ok = exprs_.scalar(a, constant_ctx(what)) && ok;
                if (!ok) continue;
                for (std::size_t i = 0; i < v.args.size(); ++i) b.inertia[i] = v.args[i];
            } else {
                diags_.error(Kind::UnknownProperty, prop.loc,
                             "rigid bodies have no property '" + prop.key + "'" +
                                 diag::did_you_mean(prop.key, {"mass", "com", "inertia"}));
            }
        }
        if (!has_mass && !seen.count("mass")) {
            diags_.error(Kind::MissingProperty, rb.loc,
                         "rigid body '" + rb.name + "' has no mass (add `mass = ...`)");
        }
        if (!has_mass) return std::nullopt;
        return b;
    }

    std::optional<Body> flexible_body(const ast::FlexibleBody& fb) {
        NameValues values;
        for (const auto& p : model_.params)
            if (p.value) values[p.name] = *p.value;
        FlexibleInputs in{names_, values, data_, diags_};
        auto checked = check_flexible(fb, in);
        if (!checked) return std::nullopt;
        if (checked->beam) beams_.emplace(fb.name, std::move(*checked->beam));
        Body b;
        b.name = fb.name;
        b.kind = Body::Kind::flexible;
        b.loc = fb.loc;
        b.mass = number("0", fb.loc);
        b.com = zero_vec(fb.loc);
        for (auto& e : b.inertia) e = number("0", fb.loc);
        b.flex = std::move(checked->flex);
        if (b.flex->symbolic) {
            for (const auto& sp : shape_parameters(b.name, *b.flex)) {
                if (!declare(sp.name, NameKind::param, static_cast<int>(model_.params.size()),
                             fb.loc))
                    return std::nullopt;
                model_.params.push_back(
                    {sp.name, "shape integral of flexible body " + b.name, sp.value, fb.loc});
            }
        }
        return b;
    }

    /// A joint on `parent.tip` or `parent.node(k)` starts at that node of the parent.
    bool node_step(const ast::Joint& j, const Body* parent, Body& b) {
        if (j.parent.kind == ast::PointRef::Kind::origin) return true;
        if (!parent || !parent->flex) return false; // reported with the joint
        const auto& nodes = parent->flex->sid->nodes;
        Step st;
        st.kind = Step::Kind::node;
        st.exact_rotation = true; // `elastic_rotation = exact` unless the joint says otherwise
        st.loc = j.parent.loc;
        if (j.parent.kind == ast::PointRef::Kind::tip) {
            if (nodes.empty()) {
                diags_.error(Kind::InvalidValue, j.parent.loc,
                             "flexible body '" + parent->name + "' has no nodes in its SID");
                return false;
            }
            st.node = static_cast<int>(nodes.size()) - 1;
        } else {
            std::string why;
            auto k = evaluate_constant(*j.parent.node, why);
            for (std::size_t i = 0; k && i < nodes.size(); ++i)
                if (nodes[i].id == *k) st.node = static_cast<int>(i);
            if (st.node < 0) {
                std::string ids;
                for (const auto& n : nodes) ids += (ids.empty() ? "" : ", ") + std::to_string(n.id);
                diags_.error(Kind::InvalidValue, j.parent.node->loc,
                             "flexible body '" + parent->name + "' has no node " +
                                 (k ? std::to_string(static_cast<long long>(*k)) : "like that") +
                                 " (its nodes: " + (ids.empty() ? "none" : ids) + ")");
                return false;
            }
        }
        b.steps.push_back(st);
        return true;
    }

    void elastic_rotation(const ast::JointStep& s, Body& b) {
        if (b.steps.empty() || b.steps.front().kind != Step::Kind::node) {
            diags_.error(Kind::InvalidValue, s.loc,
                         "elastic_rotation applies to joints on a node of a flexible body "
                         "(`joint tower.tip -> " +
                             b.name + "`)");
            return;
        }
        const ast::Value& v = s.option.value;
        std::string word =
            v.kind == ast::Value::Kind::expr && v.expr.kind == Expr::Kind::name ? v.expr.text : "";
        // `exact` keeps its original meaning, about x, then y, then z; `exact_yxz`
        // etc. name another order (the paper's 3-DOF land model turns about y first).
        static const std::vector<std::string> words = {"small",     "exact",     "exact_xyz",
                                                       "exact_xzy", "exact_yxz", "exact_yzx",
                                                       "exact_zxy", "exact_zyx"};
        if (std::find(words.begin(), words.end(), word) == words.end()) {
            diags_.error(Kind::InvalidValue, v.loc,
                         "elastic_rotation is `small`, `exact` (= `exact_xyz`) or `exact_` "
                         "followed by an order of the axes x, y, z, such as `exact_yxz`" +
                             diag::did_you_mean(word, words));
            return;
        }
        Step& node = b.steps.front();
        node.exact_rotation = word != "small";
        if (word.size() == 9) // exact_abc
            for (std::size_t i = 0; i < 3; ++i) node.rotation_order[i] = word[6 + i] - 'x';
    }

    bool axis_of(const ast::Axis& axis, Step& step, const std::string& body) {
        if (axis.vector) {
            auto v =
                exprs_.vector(*axis.vector, constant_ctx("the axis of a joint of '" + body + "'"));
            if (!v) return false;
            std::string why;
            double n2 = 0;
            bool constant = true;
            for (const Expr& c : *v) {
                auto x = evaluate_constant(c, why);
                if (!x)
                    constant = false;
                else
                    n2 += *x * *x;
            }
            if (constant && n2 == 0.0) {
                diags_.error(Kind::InvalidValue, axis.vector->loc, "a joint axis cannot be zero");
                return false;
            }
            step.vector = *v;
            step.axis_index = -1;
            return true;
        }
        if (axis.index < 0 || axis.index > 2) {
            diags_.error(Kind::InvalidValue, axis.loc, "unknown axis");
            return false;
        }
        step.axis_index = axis.index;
        step.axis_sign = axis.sign;
        step.vector = zero_vec(axis.loc);
        step.vector[static_cast<std::size_t>(axis.index)] =
            number(axis.sign > 0 ? "1" : "-1", axis.loc);
        return true;
    }

    void joint_steps(const ast::Joint& j, Body& b) {
        for (const auto& s : j.steps) {
            switch (s.kind) {
            case ast::JointStep::Kind::at: {
                Step st;
                st.kind = Step::Kind::offset;
                st.loc = s.loc;
                if (auto v =
                        exprs_.vector(s.vector, constant_ctx("an `at` offset of the joint of '" +
                                                             b.name + "'"))) {
                    st.vector = *v;
                    b.steps.push_back(st);
                }
                break;
            }
            case ast::JointStep::Kind::translate:
            case ast::JointStep::Kind::rotate: {
                Step st;
                st.kind = s.kind == ast::JointStep::Kind::rotate ? Step::Kind::rotate
                                                                 : Step::Kind::translate;
                st.loc = s.loc;
                bool ok = axis_of(s.axis, st, b.name);
                ok = exprs_.scalar(s.arg, step_ctx(b.name)) && ok;
                if (!ok) break;
                st.arg = s.arg;
                b.steps.push_back(st);
                break;
            }
            case ast::JointStep::Kind::free: {
                if (s.dofs.size() != 6) {
                    diags_.error(Kind::InvalidValue, s.loc,
                                 "free takes six DOFs: three translations and three rotations "
                                 "(x, y, z order), not " +
                                     std::to_string(s.dofs.size()));
                    break;
                }
                for (std::size_t i = 0; i < 6; ++i) {
                    const auto& entry = s.dofs[i];
                    auto it = names_.find(entry.dof);
                    if (it == names_.end() || it->second.kind != NameKind::dof) {
                        std::vector<std::string> dofs;
                        for (const auto& d : model_.dofs) dofs.push_back(d.name);
                        diags_.error(it == names_.end() ? Kind::UnknownName : Kind::WrongKind,
                                     entry.loc,
                                     "free needs DOFs, '" + entry.dof + "' is " +
                                         (it == names_.end() ? "not declared" : "not a DOF") +
                                         diag::did_you_mean(entry.dof, dofs));
                        continue;
                    }
                    Step st;
                    st.kind = i < 3 ? Step::Kind::translate : Step::Kind::rotate;
                    st.loc = entry.loc;
                    ast::Axis axis;
                    axis.index = static_cast<int>(i % 3);
                    axis.loc = entry.loc;
                    axis_of(axis, st, b.name);
                    Expr arg;
                    arg.kind = Expr::Kind::name;
                    arg.text = entry.dof;
                    arg.loc = entry.loc;
                    st.arg = arg;
                    b.steps.push_back(st);
                }
                break;
            }
            case ast::JointStep::Kind::option:
                if (s.option.key == "elastic_rotation") {
                    elastic_rotation(s, b);
                } else {
                    diags_.error(Kind::UnknownProperty, s.loc,
                                 "joints have no option '" + s.option.key + "'" +
                                     diag::did_you_mean(s.option.key, {"elastic_rotation"}));
                }
                break;
            }
        }
    }

    void build_bodies() {
        // Bodies in declaration order; flexible ones are reported as unsupported.
        std::vector<std::optional<Body>> declared;
        std::vector<std::string> body_names;
        for (const auto& rb : file_.rigid_bodies) {
            declared.push_back(rigid_body(rb));
            body_names.push_back(rb.name);
        }
        for (const auto& fb : file_.flexible_bodies) {
            declared.push_back(flexible_body(fb));
            body_names.push_back(fb.name);
        }
        auto index_of = [&](const std::string& name) {
            auto it = std::find(body_names.begin(), body_names.end(), name);
            return it == body_names.end() ? -1 : static_cast<int>(it - body_names.begin());
        };
        std::vector<int> parent(declared.size(), -2); // -2: no joint yet
        std::vector<const ast::Joint*> joint_of(declared.size(), nullptr);
        for (const auto& j : file_.joints) {
            int child = index_of(j.child);
            if (j.child == "ground") {
                diags_.error(Kind::BodyTree, j.child_loc, "ground cannot be the child of a joint");
                continue;
            }
            if (child < 0) {
                diags_.error(Kind::UnknownName, j.child_loc,
                             "unknown body '" + j.child + "'" +
                                 diag::did_you_mean(j.child, body_names));
                continue;
            }
            int par = -1;
            if (j.parent.body != "ground") {
                par = index_of(j.parent.body);
                if (par < 0) {
                    auto names = body_names;
                    names.push_back("ground");
                    diags_.error(Kind::UnknownName, j.parent.loc,
                                 "unknown body '" + j.parent.body + "'" +
                                     diag::did_you_mean(j.parent.body, names));
                    continue;
                }
            } else if (j.parent.kind != ast::PointRef::Kind::origin) {
                diags_.error(Kind::InvalidValue, j.parent.loc, "ground has no tip or nodes");
                continue;
            }
            if (j.parent.kind != ast::PointRef::Kind::origin && par >= 0) {
                bool flexible = static_cast<std::size_t>(par) >= file_.rigid_bodies.size();
                if (!flexible) {
                    diags_.error(Kind::InvalidValue, j.parent.loc,
                                 "rigid body '" + j.parent.body +
                                     "' has no tip or nodes (they belong to flexible bodies)");
                    continue;
                }
            }
            if (par == child) {
                diags_.error(Kind::BodyTree, j.loc, "body '" + j.child + "' is joined to itself");
                continue;
            }
            if (joint_of[static_cast<std::size_t>(child)]) {
                diags_.error(Kind::BodyTree, j.loc,
                             "body '" + j.child +
                                 "' already has a joint: a body hangs from exactly one parent");
                diags_.note(joint_of[static_cast<std::size_t>(child)]->loc,
                            "the first joint is here");
                continue;
            }
            joint_of[static_cast<std::size_t>(child)] = &j;
            parent[static_cast<std::size_t>(child)] = par;
        }
        for (std::size_t i = 0; i < declared.size(); ++i) {
            if (!joint_of[i]) {
                const Loc& loc = i < file_.rigid_bodies.size()
                                     ? file_.rigid_bodies[i].loc
                                     : file_.flexible_bodies[i - file_.rigid_bodies.size()].loc;
                diags_.error(Kind::BodyTree, loc,
                             "body '" + body_names[i] + "' has no joint (add `joint PARENT -> " +
                                 body_names[i] + "`)");
            }
        }
        // Order parents before children; bodies on a cycle never reach ground.
        std::vector<int> order;
        std::vector<int> state(declared.size(), 0); // 0 new, 1 visiting, 2 done, 3 cyclic
        std::function<bool(int)> visit = [&](int i) -> bool {
            auto ui = static_cast<std::size_t>(i);
            if (state[ui] == 2) return true;
            if (state[ui] == 1 || state[ui] == 3) return false;
            state[ui] = 1;
            bool ok = parent[ui] < 0 || visit(parent[ui]);
            state[ui] = ok ? 2 : 3;
            if (ok) order.push_back(i);
            return ok;
        };
        for (std::size_t i = 0; i < declared.size(); ++i) {
            if (!joint_of[i]) continue;
            if (!visit(static_cast<int>(i)) && state[i] == 3 && parent[i] >= -1) {
                diags_.error(Kind::BodyTree, joint_of[i]->loc,
                             "body '" + body_names[i] +
                                 "' is on a cycle of joints that never reaches ground");
                state[i] = 4;
            }
        }
        std::vector<int> new_index(declared.size(), -1);
        for (int i : order) {
            auto ui = static_cast<std::size_t>(i);
            if (!declared[ui] || !joint_of[ui]) continue; // no joint: reported above
            int par = parent[ui];
            if (par >= 0 && new_index[static_cast<std::size_t>(par)] < 0) continue;
            Body b = *declared[ui];
            b.parent = par < 0 ? -1 : new_index[static_cast<std::size_t>(par)];
            if (!node_step(*joint_of[ui],
                           par < 0 ? nullptr : &*declared[static_cast<std::size_t>(par)], b))
                continue;
            joint_steps(*joint_of[ui], b);
            new_index[ui] = static_cast<int>(model_.bodies.size());
            model_.bodies.push_back(std::move(b));
        }
        for (const auto& p : file_.points) {
            Point pt;
            pt.name = p.id.name;
            pt.loc = p.id.loc;
            pt.body = body_ref(p.body, p.body_loc, "a point");
            if (auto v =
                    exprs_.vector(p.at, constant_ctx("the position of point '" + p.id.name + "'")))
                pt.at = *v;
            model_.points.push_back(pt);
        }
    }

    /// Index of a body named in a load/point (-1 for ground when allowed, -2 on error).
    int body_ref(const std::string& name, const Loc& loc, const std::string& what,
                 bool ground_ok = false) {
        if (name == "ground") {
            if (ground_ok) return -1;
            diags_.error(Kind::InvalidValue, loc, what + " cannot be on ground");
            return -2;
        }
        int i = model_.body_index(name);
        if (i >= 0) return i;
        auto it = names_.find(name);
        if (it != names_.end() && it->second.kind == NameKind::body) return -2; // reported already
        std::vector<std::string> bodies;
        for (const auto& b : file_.rigid_bodies) bodies.push_back(b.name);
        if (ground_ok) bodies.push_back("ground");
        diags_.error(Kind::UnknownName, loc,
                     "unknown body '" + name + "'" + diag::did_you_mean(name, bodies));
        return -2;
    }

    int frame_ref(const std::optional<ast::Named>& frame, int default_frame) {
        if (!frame) return default_frame;
        return body_ref(frame->name, frame->loc, "a frame", true);
    }

    // ---- loads and outputs ------------------------------------------------------------
    ExprContext load_ctx(std::string what) const {
        ExprContext ctx{std::move(what)};
        ctx.dofs = true;
        ctx.dof_primes = 2;
        ctx.inputs = true;
        ctx.time = true;
        return ctx;
    }

    int dof_ref(const ast::Named& d, const std::string& what) {
        auto it = names_.find(d.name);
        if (it == names_.end() || it->second.kind != NameKind::dof) {
            std::vector<std::string> dofs;
            for (const auto& x : model_.dofs) dofs.push_back(x.name);
            diags_.error(it == names_.end() ? Kind::UnknownName : Kind::WrongKind, d.loc,
                         what + " needs a DOF, '" + d.name + "' is " +
                             (it == names_.end() ? "not declared" : "not a DOF") +
                             diag::did_you_mean(d.name, dofs));
            return -1;
        }
        return it->second.index;
    }

    void check_loads() {
        for (const auto& f : file_.forces) {
            Force out;
            out.loc = f.loc;
            out.body = body_ref(f.body, f.body_loc, "a force");
            out.frame = frame_ref(f.frame, out.body);
            out.at = zero_vec(f.loc);
            if (f.at) {
                if (auto v =
                        exprs_.vector(*f.at, constant_ctx("the point of application of a force")))
                    out.at = *v;
            }
            auto v = exprs_.vector(f.value, load_ctx("a force"));
            if (out.body >= 0 && out.frame >= -1 && v) {
                out.value = *v;
                model_.forces.push_back(out);
            }
        }
        for (const auto& tq : file_.torques) {
            Torque out;
            out.loc = tq.loc;
            out.body = body_ref(tq.body, tq.body_loc, "a torque");
            out.frame = frame_ref(tq.frame, out.body);
            auto v = exprs_.vector(tq.value, load_ctx("a torque"));
            if (out.body >= 0 && out.frame >= -1 && v) {
                out.value = *v;
                model_.torques.push_back(out);
            }
        }
        for (const auto& s : file_.springs) {
            Spring out;
            out.loc = s.loc;
            out.dof = dof_ref(s.dof, "a spring");
            ExprContext ctx = load_ctx("a spring coefficient");
            ctx.dofs = false;
            bool ok = out.dof >= 0;
            if (s.stiffness) ok = exprs_.scalar(*s.stiffness, ctx) && ok;
            if (s.damping) ok = exprs_.scalar(*s.damping, ctx) && ok;
            out.stiffness = s.stiffness;
            out.damping = s.damping;
            if (ok) model_.springs.push_back(out);
        }
        for (const auto& g : file_.genforces) {
            GenForce out;
            out.loc = g.loc;
            out.dof = dof_ref(g.dof, "genforce");
            bool ok = exprs_.scalar(g.value, load_ctx("a generalized force")) && out.dof >= 0;
            out.value = g.value;
            if (ok) model_.genforces.push_back(out);
        }
    }

    void check_outputs() {
        std::set<std::string> seen;
        for (const auto& o : file_.outputs) {
            Output out;
            out.name = o.id.name;
            out.doc = o.id.doc;
            out.loc = o.id.loc;
            std::string why = reserved_reason(o.id.name);
            if (!why.empty())
                diags_.error(Kind::ReservedName, o.id.loc, "'" + o.id.name + "' " + why);
            if (!seen.insert(o.id.name).second)
                diags_.error(Kind::DuplicateName, o.id.loc,
                             "output '" + o.id.name + "' is already declared");
            ExprContext ctx{"output '" + o.id.name + "'"};
            ctx.dofs = true;
            ctx.dof_primes = 2; // q'': the accelerations M^-1 F, solved in `outputs`
            ctx.inputs = true;
            ctx.time = true;
            ctx.kinematics = true;
            out.frame = frame_ref(o.frame, -1);
            out.frame_node = frame_node(o, out.frame);
            bool ok = exprs_.scalar(o.value, ctx) && out.frame >= -1 && out.frame_node >= -1;
            out.value = o.value;
            ok = ok && resolve_sections(out.value);
            if (ok) model_.outputs.push_back(out);
        }
    }

    /// The index of SID node `number` (null: the tip, the last node) of flexible
    /// `body`, or -1 after reporting.
    int section_node(const Body& body, const Expr* number, const Loc& loc) {
        const auto& nodes = body.flex->sid->nodes;
        if (nodes.empty()) {
            diags_.error(Kind::InvalidValue, loc,
                         "flexible body '" + body.name + "' has no nodes in its SID");
            return -1;
        }
        if (!number) return static_cast<int>(nodes.size()) - 1;
        std::string why;
        auto k = evaluate_constant(*number, why);
        for (std::size_t i = 0; k && i < nodes.size(); ++i)
            if (nodes[i].id == *k) return static_cast<int>(i);
        std::string ids;
        for (const auto& n : nodes) ids += (ids.empty() ? "" : ", ") + std::to_string(n.id);
        if (nodes.size() > 3 &&
            nodes.back().id - nodes.front().id + 1 == static_cast<int>(nodes.size()))
            ids = std::to_string(nodes.front().id) + " to " + std::to_string(nodes.back().id);
        diags_.error(Kind::InvalidValue, number->loc,
                     "flexible body '" + body.name + "' has no node " +
                         (k ? std::to_string(static_cast<long long>(*k)) : "like that: " + why) +
                         " (its nodes: " + ids + ")");
        return -1;
    }

    /// `in tower.node(10)`: the node's index; -1 for a plain frame, -2 after reporting.
    int frame_node(const ast::Output& o, int frame) {
        if (o.frame_point.kind == ast::PointRef::Kind::origin) return -1;
        if (frame == -1)
            diags_.error(Kind::InvalidValue, o.frame_point.loc, "ground has no tip or nodes");
        if (frame < 0) return -2; // else reported with the frame
        const Body& body = model_.bodies[static_cast<std::size_t>(frame)];
        if (!body.flex) {
            diags_.error(Kind::WrongKind, o.frame_point.loc,
                         "'" + body.name + "' is a rigid body: only flexible bodies have nodes");
            return -2;
        }
        const int node = section_node(
            body, o.frame_point.kind == ast::PointRef::Kind::tip ? nullptr : &*o.frame_point.node,
            o.frame_point.loc);
        return node < 0 ? -2 : node;
    }

    /// Each `body.node(k)` / `body.tip` in a checked output becomes the body's name and
    /// its SID node's index, and the body gets the inertia integrals of the part
    /// beyond that node (asked of the data stage once per node).
    bool resolve_sections(Expr& e) {
        bool ok = true;
        for (Expr& a : e.args) ok = resolve_sections(a) && ok;
        if (e.kind != Expr::Kind::section || !ok) return ok;
        const std::string name = e.args[0].text;
        const int b = model_.body_index(name);
        if (b < 0) return false; // reported with the body
        Body& body = model_.bodies[static_cast<std::size_t>(b)];
        if (!body.flex) {
            diags_.error(Kind::WrongKind, e.loc,
                         "'" + name + "' is a rigid body: a section cuts a flexible one; its " +
                             "joint's load is reaction_moment(" + name + ")");
            return false;
        }
        Flexible& flex = *body.flex;
        const auto beam = beams_.find(name);
        if (beam == beams_.end() || flex.symbolic) {
            diags_.error(Kind::NotSupported, e.loc,
                         "flexible body '" + name + "' cannot be cut at a section: its " +
                             (flex.symbolic ? "shape integrals are symbolic parameters"
                                            : "SID holds integrals over the whole body only") +
                             "; the loads through a section need the mass distribution of a " +
                             "`beam` block (docs/language.md)");
            return false;
        }
        const int node = section_node(body, e.text == "tip" ? nullptr : &e.args[1], e.loc);
        if (node < 0) return false;
        if (!flex.sections.count(node)) {
            auto part = data_.section_sid(beam->second, node, e.loc, diags_);
            if (!part) return false;
            flex.sections.emplace(node, std::make_shared<const sid::Sid>(std::move(*part)));
        }
        Expr resolved;
        resolved.kind = Expr::Kind::section;
        resolved.loc = e.loc;
        resolved.text = name;
        resolved.primes = node;
        // For dumps: the node's number in the SID.
        resolved.args.push_back(
            number(std::to_string(flex.sid->nodes[static_cast<std::size_t>(node)].id), e.loc));
        e = std::move(resolved);
        return true;
    }

    // An external function: its name is a C symbol of the user's library, its
    // arguments are what an output may read except q'' and reaction loads (they
    // would need the accelerations the function's own result changes).
    void check_externals() {
        std::map<std::string, Loc> seen;
        for (const auto& e : file_.externals) {
            External out;
            out.name = e.function.name;
            out.loc = e.function.loc;
            bool ok = true;
            std::string why = reserved_reason(out.name);
            // Global C symbols beside the model's namespace and the optional derivatives.
            if (why.empty() && (out.name.rfind("yamsc", 0) == 0 || out.name == model_.name))
                why = "is reserved for the generated code's own symbols (the model's name, "
                      "yamsc*)";
            for (const auto& other : file_.externals)
                if (why.empty() && out.name == other.function.name + "_jacobian")
                    why = "is the derivative of external function '" + other.function.name + "'";
            if (!why.empty()) {
                diags_.error(Kind::ReservedName, e.function.loc,
                             "external function '" + out.name + "' " + why);
                ok = false;
            }
            auto [it, inserted] = seen.emplace(out.name, e.function.loc);
            if (!inserted) {
                diags_.error(Kind::DuplicateName, e.function.loc,
                             "external function '" + out.name + "' is already declared at " +
                                 std::to_string(it->second.line) + ":" +
                                 std::to_string(it->second.col));
                ok = false;
            }
            const std::string what = "an argument of external function '" + out.name + "'";
            switch (e.kind) {
            case ast::External::Kind::force:
            case ast::External::Kind::torque: {
                const bool force = e.kind == ast::External::Kind::force;
                out.kind = force ? External::Kind::force : External::Kind::torque;
                out.body = body_ref(e.body, e.body_loc, force ? "a force" : "a torque");
                out.frame = frame_ref(e.frame, out.body);
                out.at = zero_vec(e.loc);
                if (e.at) {
                    if (auto v = exprs_.vector(*e.at,
                                               constant_ctx("the point of application of a force")))
                        out.at = *v;
                    else
                        ok = false;
                }
                ok = ok && out.body >= 0 && out.frame >= -1;
                break;
            }
            case ast::External::Kind::genforce: {
                out.kind = External::Kind::genforce;
                std::set<int> dofs;
                for (const ast::Named& d : e.dofs) {
                    const int i = dof_ref(d, "an external genforce");
                    if (i >= 0 && !dofs.insert(i).second) {
                        diags_.error(Kind::DuplicateName, d.loc,
                                     "DOF '" + d.name + "' is listed twice");
                        ok = false;
                    }
                    ok = ok && i >= 0;
                    out.dofs.push_back(i);
                }
                break;
            }
            }
            for (const auto& a : e.args) {
                ExprContext ctx{what};
                ctx.dofs = true;
                ctx.dof_primes = 1; // not q'': the result changes the accelerations
                ctx.inputs = true;
                ctx.time = true;
                ctx.kinematics = true;
                ctx.reactions = false;
                const int frame = frame_ref(a.frame, -1);
                ok = exprs_.scalar(a.value, ctx) && frame >= -1 && ok;
                out.args.push_back(a.value);
                out.arg_frames.push_back(frame);
            }
            out.without_jacobian = e.without_jacobian;
            if (ok) model_.externals.push_back(out);
        }
    }

    // Every DOF must drive a mode of one flexible body, or one step in each joint it
    // moves: several joints may share a DOF (a gear: the generator turns at
    // `GBRatio * psi` while the rotor turns at `psi`), one joint may not use it twice.
    void check_dof_usage() {
        struct Use {
            Loc loc;
            std::size_t body;
            bool mode;
        };
        std::vector<std::vector<Use>> uses(model_.dofs.size());
        for (std::size_t bi = 0; bi < model_.bodies.size(); ++bi) {
            const auto& b = model_.bodies[bi];
            if (b.flex)
                for (int d : b.flex->dofs)
                    uses[static_cast<std::size_t>(d)].push_back({b.loc, bi, true});
            for (const auto& s : b.steps) {
                if (s.kind == Step::Kind::offset || s.kind == Step::Kind::node) continue;
                std::vector<const Expr*> names;
                collect_names(s.arg, names);
                std::set<int> in_step;
                for (const Expr* n : names) {
                    auto it = names_.find(n->text);
                    if (it != names_.end() && it->second.kind == NameKind::dof &&
                        in_step.insert(it->second.index).second)
                        uses[static_cast<std::size_t>(it->second.index)].push_back(
                            {n->loc, bi, false});
                }
            }
        }
        if (diags_.has_errors()) return; // bodies may be missing: usage would mislead
        for (std::size_t i = 0; i < model_.dofs.size(); ++i) {
            const Dof& d = model_.dofs[i];
            if (uses[i].empty()) {
                diags_.error(Kind::DofUsage, d.loc,
                             "DOF '" + d.name +
                                 "' moves nothing: use it in a joint step "
                                 "(rotate/translate/free)");
            } else {
                for (std::size_t a = 1; a < uses[i].size(); ++a) {
                    const Use& first = uses[i][a - 1];
                    const Use& u = uses[i][a];
                    if (u.body != first.body && !u.mode && !first.mode) continue;
                    diags_.error(Kind::DofUsage, u.loc,
                                 u.mode || first.mode
                                     ? "DOF '" + d.name +
                                           "' is a mode of a flexible body and drives another "
                                           "step or mode"
                                     : "DOF '" + d.name +
                                           "' is used by two steps of one joint; a joint's DOF "
                                           "drives one step");
                    diags_.note(first.loc, "first used here");
                    break;
                }
            }
        }
    }

    // ---- linearization and approximations ----------------------------------------------
    /// `linearize { ... }`: one value per DOF, rate and input channel, 0 unless written.
    void check_linearize() {
        if (!file_.linearize) return;
        const Loc& loc = file_.linearize->loc;
        OperatingPoint op;
        op.loc = loc;
        op.q.assign(model_.dofs.size(), number("0", loc));
        op.qd.assign(model_.dofs.size(), number("0", loc));
        std::vector<std::size_t> first_channel;
        for (const Input& in : model_.inputs) {
            first_channel.push_back(op.u.size());
            for (int k = 0; k <= in.order; ++k) op.u.push_back(number("0", loc));
        }
        std::set<std::pair<std::string, int>> seen;
        bool ok = true;
        for (const ast::Assignment& a : file_.linearize->point) {
            const std::string written =
                a.name + std::string(static_cast<std::size_t>(a.primes), '\'');
            Expr* slot = operating_point_slot(a, written, op, first_channel);
            if (!slot) {
                ok = false;
                continue;
            }
            if (!seen.insert({a.name, a.primes}).second) {
                diags_.error(Kind::DuplicateName, a.loc,
                             "'" + written + "' is given twice in the linearize block");
                ok = false;
                continue;
            }
            // The point is a function of the parameters only: the linear model is then
            // LPV, exact at every parameter set.
            ExprContext ctx{"the operating point value of '" + written + "'"};
            if (!exprs_.scalar(a.value, ctx)) {
                ok = false;
                continue;
            }
            *slot = a.value;
        }
        if (ok) model_.operating_point = std::move(op);
    }

    /// `initial { ... }`: a value per DOF and rate, 0 unless written; parameters only, so
    /// that `--set` moves the initial state with the parameters.
    void check_initial_state() {
        if (!file_.initial) return;
        const Loc& loc = file_.initial->loc;
        InitialState init;
        init.loc = loc;
        init.q.assign(model_.dofs.size(), number("0", loc));
        init.qd.assign(model_.dofs.size(), number("0", loc));
        std::set<std::pair<std::string, int>> seen;
        bool ok = true;
        for (const ast::Assignment& a : file_.initial->state) {
            const std::string written =
                a.name + std::string(static_cast<std::size_t>(a.primes), '\'');
            auto it = names_.find(a.name);
            if (it == names_.end() || it->second.kind != NameKind::dof) {
                std::vector<std::string> candidates;
                for (const Dof& d : model_.dofs) candidates.push_back(d.name);
                diags_.error(it == names_.end() ? Kind::UnknownName : Kind::WrongKind, a.loc,
                             (it == names_.end() ? "unknown DOF '" + a.name + "'"
                                                 : "'" + a.name + "' is not a DOF") +
                                 " in the initial block: it sets DOFs and their rates" +
                                 (it == names_.end() ? diag::did_you_mean(a.name, candidates)
                                                     : std::string()));
                ok = false;
                continue;
            }
            if (a.primes > 1) {
                diags_.error(Kind::InvalidValue, a.loc,
                             "the initial block sets DOFs and rates, not '" + written +
                                 "': accelerations follow from M q'' = F");
                ok = false;
                continue;
            }
            if (!seen.insert({a.name, a.primes}).second) {
                diags_.error(Kind::DuplicateName, a.loc,
                             "'" + written + "' is given twice in the initial block");
                ok = false;
                continue;
            }
            ExprContext ctx{"the initial value of '" + written + "'"};
            if (!exprs_.scalar(a.value, ctx)) {
                ok = false;
                continue;
            }
            const auto index = static_cast<std::size_t>(it->second.index);
            (a.primes == 0 ? init.q : init.qd)[index] = a.value;
        }
        if (ok) model_.initial_state = std::move(init);
    }

    /// Where the value of `name''...` goes in the operating point, or null (reported).
    Expr* operating_point_slot(const ast::Assignment& a, const std::string& written,
                               OperatingPoint& op, const std::vector<std::size_t>& first_channel) {
        auto it = names_.find(a.name);
        if (it == names_.end()) {
            std::vector<std::string> candidates;
            for (const Dof& d : model_.dofs) candidates.push_back(d.name);
            for (const Input& in : model_.inputs) candidates.push_back(in.name);
            diags_.error(Kind::UnknownName, a.loc,
                         "unknown DOF or input '" + a.name + "' in the linearize block" +
                             diag::did_you_mean(a.name, candidates));
            return nullptr;
        }
        const auto index = static_cast<std::size_t>(it->second.index);
        if (it->second.kind == NameKind::dof) {
            if (a.primes > 1) {
                diags_.error(Kind::InvalidValue, a.loc,
                             "the operating point sets DOFs and rates, not '" + written +
                                 "': accelerations follow from M q'' = F");
                return nullptr;
            }
            return a.primes == 0 ? &op.q[index] : &op.qd[index];
        }
        if (it->second.kind == NameKind::input) {
            const Input& in = model_.inputs[index];
            if (a.primes > in.order) {
                diags_.error(Kind::InvalidValue, a.loc,
                             "input '" + in.name + "' is declared with order " +
                                 std::to_string(in.order) + ": '" + written +
                                 "' is not one of its channels");
                return nullptr;
            }
            return &op.u[first_channel[index] + static_cast<std::size_t>(a.primes)];
        }
        diags_.error(Kind::WrongKind, a.loc,
                     "the linearize block sets DOFs, their rates and inputs; '" + a.name +
                         "' is not one of them");
        return nullptr;
    }

    /// `approx a, b order N`: parameters, DOFs or inputs, each in one group only.
    void check_approximations() {
        std::map<std::string, Loc> grouped;
        for (const ast::Approx& a : file_.approximations) {
            Approximation group;
            group.order = a.order;
            group.loc = a.loc;
            if (a.order < 1 || a.order > max_approx_order) {
                diags_.error(Kind::InvalidValue, a.loc,
                             "approx order must be between 1 and " +
                                 std::to_string(max_approx_order) + ", not " +
                                 std::to_string(a.order));
                continue;
            }
            bool ok = true;
            for (const ast::Named& n : a.symbols) {
                auto it = names_.find(n.name);
                if (it == names_.end()) {
                    std::vector<std::string> candidates;
                    for (const auto& [name, info] : names_)
                        if (info.kind == NameKind::param || info.kind == NameKind::dof ||
                            info.kind == NameKind::input)
                            candidates.push_back(name);
                    diags_.error(Kind::UnknownName, n.loc,
                                 "unknown name '" + n.name + "' in approx" +
                                     diag::did_you_mean(n.name, candidates));
                    ok = false;
                    continue;
                }
                const NameKind kind = it->second.kind;
                if (kind != NameKind::param && kind != NameKind::dof && kind != NameKind::input) {
                    diags_.error(Kind::WrongKind, n.loc,
                                 "approx expands in parameters, DOFs or inputs; '" + n.name +
                                     "' is none of them");
                    ok = false;
                    continue;
                }
                auto [prev, fresh] = grouped.emplace(n.name, n.loc);
                if (!fresh) {
                    diags_.error(Kind::DuplicateName, n.loc,
                                 "'" + n.name + "' is already approximated");
                    diags_.note(prev->second, "first approximated here");
                    ok = false;
                    continue;
                }
                group.symbols.push_back({n.name, kind, it->second.index, n.loc});
            }
            if (ok) model_.approximations.push_back(std::move(group));
        }
    }

    /// Orders above this are never useful for small angles and grow as (n+N)!/(n! N!).
    static constexpr int max_approx_order = 8;

    const ast::ModelFile& file_;
    DataSource& data_;
    diag::Diagnostics& diags_;
    Model model_;
    /// The beams the SIDs of beam blocks were made of, by body: what sections cut.
    std::map<std::string, beam::Beam> beams_;
    SymbolTable names_;
    ExprChecker exprs_;
};

} // namespace

std::optional<Model> check(const ast::ModelFile& file, DataSource& data, diag::Diagnostics& diags) {
    return Checker(file, data, diags).run();
}

} // namespace yamsc::model
