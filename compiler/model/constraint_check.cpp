#include "model/constraint_check.hpp"

#include "model/declaration_check.hpp"
#include <algorithm>
#include <map>

namespace yamsc::model {

using diag::Kind;
using K = Expr::Kind;

namespace {

std::string quoted(const std::string& s) {
    return "'" + s + "'";
}

std::string at(const Loc& l) {
    return std::to_string(l.line) + ":" + std::to_string(l.col);
}

/// The highest power of the rates q' in `e`: 0, 1, or 2 for anything not linear.
int rate_degree(const Expr& e, const SymbolTable& names) {
    switch (e.kind) {
    case K::number:
        return 0;
    case K::name: {
        const auto it = names.find(e.text);
        const bool dof = it != names.end() && it->second.kind == NameKind::dof;
        return dof && e.primes == 1 ? 1 : 0;
    }
    case K::neg:
        return rate_degree(e.args[0], names);
    case K::add:
    case K::sub:
        return std::max(rate_degree(e.args[0], names), rate_degree(e.args[1], names));
    case K::mul:
        return std::min(2, rate_degree(e.args[0], names) + rate_degree(e.args[1], names));
    case K::div:
        return rate_degree(e.args[1], names) > 0 ? 2 : rate_degree(e.args[0], names);
    default:
        for (const Expr& a : e.args)
            if (rate_degree(a, names) > 0) return 2;
        return 0;
    }
}

class ConstraintChecker {
public:
    ConstraintChecker(const Model& model, const SymbolTable& names, ExprChecker& exprs,
                      diag::Diagnostics& diags)
        : model_(model), names_(names), exprs_(exprs), diags_(diags) {
        for (const Dof& d : model.dofs) dof_names_.push_back(d.name);
    }

    void check(const ast::Constraint& decl, std::vector<Constraint>& out) {
        const ConstraintKindInfo* info = kind_of(decl.kind);
        bool ok = check_name(decl);
        if (!info) return;
        Constraint c;
        c.kind = info->kind;
        c.name = decl.id.name;
        c.loc = decl.loc;
        c.end = decl.end;
        std::map<ConstraintRole, Loc> written;
        for (const ast::Property& p : decl.roles) {
            const auto role =
                std::find_if(info->roles.begin(), info->roles.end(),
                             [&](const ConstraintRoleInfo& r) { return r.name == p.key; });
            if (role == info->roles.end()) {
                std::vector<std::string> roles;
                for (const ConstraintRoleInfo& r : info->roles) roles.push_back(r.name);
                diags_.error(Kind::UnknownProperty, p.loc,
                             "constraint kind " + quoted(info->name) + " has no role " +
                                 quoted(p.key) + diag::did_you_mean(p.key, roles));
                ok = false;
                continue;
            }
            const auto [it, fresh] = written.emplace(role->role, p.loc);
            if (!fresh) {
                diags_.error(Kind::DuplicateName, p.loc,
                             "role " + quoted(p.key) + " is already given at " + at(it->second));
                ok = false;
                continue;
            }
            ok = bind(c, *role, p) && ok;
        }
        for (const ConstraintRoleInfo& r : info->roles)
            if (r.required && !written.count(r.role) && decl.id.loc.line) {
                diags_.error(Kind::MissingProperty, decl.id.loc,
                             "constraint " + quoted(c.name) + " has no role " + quoted(r.name) +
                                 " (" + r.what + ")");
                ok = false;
            }
        if (ok) ok = check_joint(c, written);
        if (!ok) return;
        c.rows = constraint_rows(c);
        out.push_back(std::move(c));
    }

private:
    const ConstraintKindInfo* kind_of(const ast::Named& kind) {
        return find_kind(constraint_kinds(), kind, "constraint kind", diags_);
    }

    bool check_name(const ast::Constraint& decl) {
        return !decl.id.name.empty() &&
               fresh_declaration_name(decl.id, "constraint", seen_, diags_);
    }

    bool bind(Constraint& c, const ConstraintRoleInfo& role, const ast::Property& p) {
        const ast::Value& v = p.value;
        if (v.kind != ast::Value::Kind::expr) {
            diags_.error(Kind::InvalidValue, v.loc,
                         "role " + quoted(p.key) + " takes " + role.what);
            return false;
        }
        const Expr& e = v.expr;
        switch (role.role) {
        case ConstraintRole::a:
            return frame(e, p.key, c.a);
        case ConstraintRole::b:
            return frame(e, p.key, c.b);
        case ConstraintRole::joint: {
            const int w = word(e, role, p.key);
            if (w < 0) return false;
            static const LoopJoint joints[] = {LoopJoint::point, LoopJoint::point,
                                               LoopJoint::revolute, LoopJoint::prismatic,
                                               LoopJoint::weld};
            c.joint = joints[w];
            return true;
        }
        case ConstraintRole::axis:
            return axis(e, p.key, c.axis);
        case ConstraintRole::axle:
            return axis(e, p.key, c.axle);
        case ConstraintRole::normal:
            return axis(e, p.key, c.normal);
        case ConstraintRole::components:
            return components(e, p.key, c.components);
        case ConstraintRole::contact: {
            const int w = word(e, role, p.key);
            if (w < 0) return false;
            c.contact = w == 0 ? RollingContact::kept : RollingContact::by_tree;
            return true;
        }
        case ConstraintRole::value:
            c.value = e;
            return value(c, e);
        case ConstraintRole::coordinate:
            c.coordinate = dof(e, "the prescribed coordinate");
            if (c.coordinate < 0) return false;
            if (const auto [it, fresh] = prescribed_.emplace(c.coordinate, e.loc); !fresh) {
                diags_.error(Kind::InvalidValue, e.loc,
                             "coordinate " + quoted(e.text) + " is already prescribed at " +
                                 at(it->second));
                return false;
            }
            return true;
        case ConstraintRole::wheel:
            return body(e, p.key, c.wheel);
        case ConstraintRole::radius: {
            c.radius = e;
            ExprContext ctx{"the radius of constraint " + quoted(c.name)};
            return exprs_.scalar(e, ctx);
        }
        case ConstraintRole::dependent:
            return dependent(e, c.dependent);
        }
        return false;
    }

    /// A body, a point, ground, `body.tip` or `body.node(k)`.
    bool frame(const Expr& e, const std::string& role, FrameRef& out) {
        out.loc = e.loc;
        out.text = ast::to_string(e);
        if (e.kind == K::name && e.primes == 0) {
            if (e.text == "ground") return true;
            const auto it = names_.find(e.text);
            if (it != names_.end() && it->second.kind == NameKind::body) {
                out.body = model_.body_index(e.text);
                return out.body >= 0; // otherwise reported with the body tree
            }
            if (it != names_.end() && it->second.kind == NameKind::point) {
                const int p = model_.point_index(e.text);
                if (p < 0) return false; // reported with the point
                out.body = model_.points[static_cast<std::size_t>(p)].body;
                out.at = model_.points[static_cast<std::size_t>(p)].at;
                return true;
            }
            std::vector<std::string> candidates{"ground"};
            for (const auto& [name, info] : names_)
                if (info.kind == NameKind::body || info.kind == NameKind::point)
                    candidates.push_back(name);
            diags_.error(it == names_.end() ? Kind::UnknownName : Kind::WrongKind, e.loc,
                         "role " + quoted(role) + " takes a body, a point or a flexible body's " +
                             "node; " + quoted(e.text) +
                             (it == names_.end() ? " is not declared" : " is neither") +
                             diag::did_you_mean(e.text, candidates));
            return false;
        }
        if (e.kind == K::section) return section(e, role, out);
        diags_.error(Kind::InvalidValue, e.loc,
                     "role " + quoted(role) +
                         " takes a body, a point, ground, `body.tip` or `body.node(k)`");
        return false;
    }

    bool section(const Expr& e, const std::string& role, FrameRef& out) {
        const Expr& name = e.args[0];
        const int b = name.kind == K::name ? model_.body_index(name.text) : -1;
        if (b < 0 || !model_.bodies[static_cast<std::size_t>(b)].flex) {
            diags_.error(b < 0 ? Kind::UnknownName : Kind::WrongKind, name.loc,
                         "role " + quoted(role) + ": a section `." + e.text +
                             "` needs the name of a flexible body before it");
            return false;
        }
        const auto& nodes = model_.bodies[static_cast<std::size_t>(b)].flex->sid->nodes;
        if (nodes.empty()) {
            diags_.error(Kind::InvalidValue, e.loc,
                         "flexible body " + quoted(name.text) + " has no nodes in its SID");
            return false;
        }
        out.body = b;
        if (e.args.size() < 2) {
            out.node = static_cast<int>(nodes.size()) - 1;
            return true;
        }
        std::string why;
        const auto k = evaluate_constant(e.args[1], why);
        if (!k) {
            diags_.error(Kind::NotConstant, e.args[1].loc, "the node number " + why);
            return false;
        }
        for (std::size_t i = 0; i < nodes.size(); ++i)
            if (nodes[i].id == *k) {
                out.node = static_cast<int>(i);
                return true;
            }
        diags_.error(Kind::InvalidValue, e.args[1].loc,
                     "flexible body " + quoted(name.text) + " has no node " +
                         ast::to_string(e.args[1]));
        return false;
    }

    bool body(const Expr& e, const std::string& role, int& out) {
        if (e.kind == K::name && e.primes == 0) {
            out = model_.body_index(e.text);
            if (out >= 0) return true;
        }
        std::vector<std::string> bodies;
        for (const Body& b : model_.bodies) bodies.push_back(b.name);
        diags_.error(
            e.kind == K::name && !names_.count(e.text) ? Kind::UnknownName : Kind::WrongKind, e.loc,
            "role " + quoted(role) + " takes a body" +
                (e.kind == K::name ? diag::did_you_mean(e.text, bodies) : ""));
        return false;
    }

    int word(const Expr& e, const ConstraintRoleInfo& role, const std::string& key) {
        if (e.kind == K::name && e.primes == 0) {
            const auto w = std::find(role.words.begin(), role.words.end(), e.text);
            if (w != role.words.end()) return static_cast<int>(w - role.words.begin());
        }
        std::string list;
        for (const std::string& w : role.words) list += (list.empty() ? "" : ", ") + w;
        diags_.error(Kind::InvalidValue, e.loc,
                     "role " + quoted(key) + " takes one of " + list +
                         (e.kind == K::name ? diag::did_you_mean(e.text, role.words) : ""));
        return -1;
    }

    static int axis_letter(const Expr& e) {
        if (e.kind == K::name && e.primes == 0 && e.text.size() == 1 && e.text[0] >= 'x' &&
            e.text[0] <= 'z')
            return e.text[0] - 'x';
        return -1;
    }

    bool axis(const Expr& e, const std::string& key, int& out) {
        const Expr& inner = e.kind == K::neg ? e.args[0] : e;
        out = axis_letter(inner);
        if (out >= 0) return true;
        diags_.error(Kind::InvalidValue, e.loc,
                     "role " + quoted(key) + " takes an axis: x, y or z");
        return false;
    }

    bool components(const Expr& e, const std::string& key, std::array<bool, 3>& out) {
        std::vector<const Expr*> items;
        if (e.kind == K::vector)
            for (const Expr& a : e.args) items.push_back(&a);
        else
            items.push_back(&e);
        out = {{false, false, false}};
        for (const Expr* item : items) {
            const int k = axis_letter(*item);
            if (k < 0 || out[static_cast<std::size_t>(k)]) {
                diags_.error(Kind::InvalidValue, item->loc,
                             "role " + quoted(key) +
                                 " takes a list of distinct components x, y, z: `(x, y)`");
                return false;
            }
            out[static_cast<std::size_t>(k)] = true;
        }
        return true;
    }

    int dof(const Expr& e, const std::string& what) {
        const auto it = e.kind == K::name && e.primes == 0 ? names_.find(e.text) : names_.end();
        if (it != names_.end() && it->second.kind == NameKind::dof) return it->second.index;
        const bool unknown = e.kind == K::name && it == names_.end();
        diags_.error(unknown ? Kind::UnknownName : Kind::WrongKind, e.loc,
                     what + " needs a DOF, " +
                         (e.kind == K::name
                              ? quoted(e.text) + " is " + (unknown ? "not declared" : "not a DOF")
                              : std::string("not an expression")) +
                         (e.kind == K::name ? diag::did_you_mean(e.text, dof_names_) : ""));
        return -1;
    }

    bool dependent(const Expr& e, std::vector<int>& out) {
        std::vector<const Expr*> items;
        if (e.kind == K::vector)
            for (const Expr& a : e.args) items.push_back(&a);
        else
            items.push_back(&e);
        bool ok = true;
        for (const Expr* item : items) {
            const int d = dof(*item, "`dependent`");
            if (d < 0) {
                ok = false;
                continue;
            }
            if (const auto [it, fresh] = dependent_.emplace(d, item->loc); !fresh) {
                diags_.error(Kind::InvalidValue, item->loc,
                             "DOF " + quoted(item->text) + " is already named dependent at " +
                                 at(it->second));
                ok = false;
                continue;
            }
            out.push_back(d);
        }
        return ok;
    }

    /// What the expression of a relation, speed or prescribed value may use.
    bool value(const Constraint& c, const Expr& e) {
        ExprContext ctx{"constraint " + quoted(c.name)};
        ctx.time = true;
        ctx.inputs = true;
        // Rows are differentiated once (speed) or twice (holonomic) in time.
        ctx.input_extra_order = c.kind == ConstraintKind::speed ? 1 : 2;
        ctx.dofs = c.kind != ConstraintKind::prescribed;
        ctx.dof_primes = c.kind == ConstraintKind::speed ? 1 : 0;
        if (!exprs_.scalar(e, ctx)) return false;
        if (c.kind != ConstraintKind::speed) return true;
        const int degree = rate_degree(e, names_);
        if (degree == 1) return true;
        diags_.error(Kind::InvalidValue, e.loc,
                     "the value of speed constraint " + quoted(c.name) +
                         (degree == 0 ? " reads no rate q' (write a `relation` of coordinates)"
                                      : " is not linear in the rates q'"));
        return false;
    }

    /// Roles that only some joints take.
    bool check_joint(const Constraint& c, const std::map<ConstraintRole, Loc>& written) {
        if (c.kind != ConstraintKind::loop) return true;
        const auto axis = written.find(ConstraintRole::axis);
        const bool needs_axis = c.joint == LoopJoint::revolute || c.joint == LoopJoint::prismatic;
        if (needs_axis && axis == written.end()) {
            diags_.error(Kind::MissingProperty, c.loc,
                         "constraint " + quoted(c.name) +
                             ": a revolute or prismatic joint needs its `axis` (x, y or z)");
            return false;
        }
        if (!needs_axis && axis != written.end()) {
            diags_.error(Kind::InvalidValue, axis->second,
                         "constraint " + quoted(c.name) +
                             ": only revolute and prismatic joints take an `axis`");
            return false;
        }
        if (c.a.body == c.b.body && c.a.node == c.b.node) {
            diags_.error(Kind::InvalidValue, c.b.loc,
                         "constraint " + quoted(c.name) + " joins a frame of " +
                             quoted(c.a.body < 0
                                        ? "ground"
                                        : model_.bodies[static_cast<std::size_t>(c.a.body)].name) +
                             " to itself");
            return false;
        }
        return true;
    }

    const Model& model_;
    const SymbolTable& names_;
    ExprChecker& exprs_;
    diag::Diagnostics& diags_;
    std::vector<std::string> dof_names_;
    std::map<std::string, Loc> seen_;
    std::map<int, Loc> dependent_, prescribed_;
};

const char* const axis_names[] = {"x", "y", "z"};

} // namespace

std::vector<ConstraintRow> constraint_rows(const Constraint& c) {
    std::vector<ConstraintRow> rows;
    auto row = [&](const std::string& suffix, bool holonomic) {
        rows.push_back({suffix.empty() ? c.name : c.name + "." + suffix, holonomic});
    };
    switch (c.kind) {
    case ConstraintKind::loop:
        for (int i = 0; i < 3; ++i) {
            const bool along = c.joint == LoopJoint::prismatic && i == c.axis;
            if (c.components[static_cast<std::size_t>(i)] && !along) row(axis_names[i], true);
        }
        if (c.joint == LoopJoint::revolute) {
            for (int i = 0; i < 3; ++i)
                if (i != c.axis) row(std::string("r") + axis_names[i], true);
        } else if (c.joint != LoopJoint::point) {
            for (int i = 0; i < 3; ++i) row(std::string("r") + axis_names[i], true);
        }
        break;
    case ConstraintKind::relation:
    case ConstraintKind::prescribed:
        row("", true);
        break;
    case ConstraintKind::speed:
        row("", false);
        break;
    case ConstraintKind::rolling:
        if (c.contact == RollingContact::kept) row("height", true);
        for (int i = 0; i < 3; ++i)
            if (i != c.normal) row(axis_names[i], false);
        break;
    }
    return rows;
}

std::string constraint_source(const Model& model, const Constraint& c) {
    const std::string file = model.source ? model.source->path() : std::string("model");
    return file + ":" + at(c.loc);
}

std::vector<Constraint> check_constraints(const ast::ModelFile& file, const Model& model,
                                          const SymbolTable& names, ExprChecker& exprs,
                                          diag::Diagnostics& diags) {
    ConstraintChecker checker(model, names, exprs, diags);
    std::vector<Constraint> out;
    for (const ast::Constraint& decl : file.constraints) checker.check(decl, out);
    return out;
}

} // namespace yamsc::model
