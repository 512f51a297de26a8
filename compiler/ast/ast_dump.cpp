// ast::to_string (expressions back to source text) and ast::dump (the whole tree, one line per
// declaration, for `yamsc --dump=ast` and golden tests).
#include "ast/ast.hpp"

#include <string>

namespace yamsc::ast {
namespace {

// Binding strength of each form, loosest first; it mirrors the grammar in
// grammar/model_grammar.hpp so that printed text parses back to the same tree.
enum Level { sum = 1, product, unary, degree, power, postfix, atom };

Level level_of(const Expr& e) {
    switch (e.kind) {
    case Expr::Kind::add:
    case Expr::Kind::sub:
        return sum;
    case Expr::Kind::mul:
    case Expr::Kind::div:
        return product;
    case Expr::Kind::neg:
        return unary;
    case Expr::Kind::deg:
        return degree;
    case Expr::Kind::pow:
        return power;
    case Expr::Kind::component:
    case Expr::Kind::section:
        return postfix;
    case Expr::Kind::number:
    case Expr::Kind::name:
    case Expr::Kind::call:
    case Expr::Kind::vector:
        return atom;
    }
    return atom;
}

std::string print(const Expr& e, Level at_least);

/// Argument `i`, printed at `at_least`; a malformed tree prints a marker instead of failing.
std::string arg(const Expr& e, std::size_t i, Level at_least) {
    return i < e.args.size() ? print(e.args[i], at_least) : std::string("<missing>");
}

/// An exponent: the grammar allows unary minus there without parentheses (`x^-2`).
std::string exponent(const Expr& e) {
    if (e.kind == Expr::Kind::neg && !e.args.empty()) return "-" + exponent(e.args[0]);
    return print(e, power);
}

std::string list(const std::vector<Expr>& items) {
    std::string out;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (i > 0) out += ", ";
        out += print(items[i], sum);
    }
    return out;
}

std::string bare(const Expr& e) {
    switch (e.kind) {
    case Expr::Kind::number:
        return e.text;
    case Expr::Kind::name:
        return e.text + std::string(static_cast<std::size_t>(e.primes), '\'');
    case Expr::Kind::neg:
        return "-" + arg(e, 0, unary);
    case Expr::Kind::add:
        return arg(e, 0, sum) + " + " + arg(e, 1, product);
    case Expr::Kind::sub:
        return arg(e, 0, sum) + " - " + arg(e, 1, product);
    case Expr::Kind::mul:
        return arg(e, 0, product) + " * " + arg(e, 1, unary);
    case Expr::Kind::div:
        return arg(e, 0, product) + " / " + arg(e, 1, unary);
    case Expr::Kind::pow:
        return arg(e, 0, postfix) + "^" +
               (e.args.size() > 1 ? exponent(e.args[1]) : std::string("<missing>"));
    case Expr::Kind::deg:
        return arg(e, 0, power) + " deg";
    case Expr::Kind::call:
        return e.text + "(" + list(e.args) + ")";
    case Expr::Kind::vector:
        return "(" + list(e.args) + ")";
    case Expr::Kind::component:
        return arg(e, 0, postfix) + "." + e.text;
    case Expr::Kind::section:
        if (e.args.size() == 1 && e.args[0].kind == Expr::Kind::number) // checked
            return e.text + ".node(" + e.args[0].text + ")";
        return arg(e, 0, postfix) + "." + e.text +
               (e.args.size() > 1 ? "(" + print(e.args[1], Level{}) + ")" : "");
    }
    return "<?>";
}

std::string print(const Expr& e, Level at_least) {
    std::string s = bare(e);
    return level_of(e) < at_least ? "(" + s + ")" : s;
}

// ---------------------------------------------------------------- dump

std::string quote(const std::string& s) {
    std::string out = "\"";
    for (const char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

std::string at(const Loc& loc) {
    if (loc.line == 0) return "";
    return " @" + std::to_string(loc.line) + ":" + std::to_string(loc.col);
}

std::string doc(const Named& n) {
    return n.doc.empty() ? "" : "  # " + n.doc;
}

std::string modes(const std::vector<ModeEntry>& entries) {
    std::string out = "(";
    for (std::size_t i = 0; i < entries.size(); ++i) {
        if (i > 0) out += ", ";
        if (!entries[i].mode.empty()) out += entries[i].mode + " -> ";
        out += entries[i].dof;
    }
    return out + ")";
}

std::string value(const Value& v) {
    switch (v.kind) {
    case Value::Kind::expr:
        return to_string(v.expr);
    case Value::Kind::string:
        return quote(v.str);
    case Value::Kind::modes:
        return modes(v.modes);
    case Value::Kind::table: {
        std::string out = "(";
        for (std::size_t i = 0; i < v.table.size(); ++i) {
            if (i > 0) out += ", ";
            out += to_string(v.table[i].station) + ": " + to_string(v.table[i].value);
        }
        return out + ")";
    }
    }
    return "<?>";
}

std::string property(const Property& p) {
    return p.key + " = " + value(p.value) + at(p.loc) + "\n";
}

std::string axis(const Axis& a) {
    if (a.vector) return to_string(*a.vector);
    return std::string(a.sign < 0 ? "-" : "") + static_cast<char>('x' + a.index);
}

std::string point_ref(const PointRef& p) {
    switch (p.kind) {
    case PointRef::Kind::origin:
        return p.body;
    case PointRef::Kind::tip:
        return p.body + ".tip";
    case PointRef::Kind::node:
        return p.body + ".node(" + (p.node ? to_string(*p.node) : "") + ")";
    }
    return p.body;
}

std::string step(const JointStep& s) {
    switch (s.kind) {
    case JointStep::Kind::at:
        return "at " + to_string(s.vector);
    case JointStep::Kind::translate:
        return "translate " + axis(s.axis) + " " + to_string(s.arg);
    case JointStep::Kind::rotate:
        return "rotate " + axis(s.axis) + " " + to_string(s.arg);
    case JointStep::Kind::free:
        return "free " + modes(s.dofs);
    case JointStep::Kind::option:
        return s.option.key + " = " + value(s.option.value);
    }
    return "<?>";
}

std::string frame(const std::optional<Named>& f) {
    return f ? " in " + f->name : "";
}

} // namespace

std::string to_string(const Expr& e) {
    return print(e, sum);
}

std::string dump(const ModelFile& file) {
    std::string out;
    if (file.model) {
        out += "model " + file.model->name;
        if (!file.title.empty()) out += " " + quote(file.title);
        out += at(file.model->loc) + "\n";
    }
    for (const Param& p : file.params) {
        out += "param " + p.id.name + (p.value ? " = " + to_string(*p.value) : "") + at(p.id.loc) +
               doc(p.id) + "\n";
    }
    for (const Input& i : file.inputs) {
        out += "input " + i.id.name + " order " + std::to_string(i.order) + at(i.id.loc) +
               doc(i.id) + "\n";
    }
    for (const Named& d : file.dofs) out += "dof " + d.name + at(d.loc) + doc(d) + "\n";
    if (file.gravity) out += "gravity " + to_string(*file.gravity) + at(file.gravity_loc) + "\n";
    for (const RigidBody& b : file.rigid_bodies) {
        out += "rigid " + b.name + at(b.loc) + "\n";
        for (const Property& p : b.properties) out += "  " + property(p);
    }
    for (const FlexibleBody& b : file.flexible_bodies) {
        out += "flexible " + b.name + (b.symbolic ? " symbolic" : "") + at(b.loc) + "\n";
        for (const Property& p : b.properties) out += "  " + property(p);
        if (b.beam) {
            out += "  beam";
            if (b.beam->file) out += " " + quote(*b.beam->file);
            if (!b.beam->format.empty()) out += " " + b.beam->format;
            out += at(b.beam->loc) + "\n";
            for (const Property& p : b.beam->properties) out += "    " + property(p);
            for (const ModeShape& m : b.beam->mode_shapes) {
                out += "    mode " + m.name + " " + m.direction + " = " + to_string(m.shape) +
                       at(m.loc) + "\n";
            }
        }
    }
    for (const Joint& j : file.joints) {
        out += "joint " + point_ref(j.parent) + " -> " + j.child + at(j.loc) + "\n";
        for (const JointStep& s : j.steps) out += "  " + step(s) + at(s.loc) + "\n";
    }
    for (const Point& p : file.points) {
        out += "point " + p.id.name + " on " + p.body + " at " + to_string(p.at) + at(p.id.loc) +
               doc(p.id) + "\n";
    }
    for (const Force& f : file.forces) {
        out += "force on " + f.body + (f.at ? " at " + to_string(*f.at) : "") + frame(f.frame) +
               " = " + to_string(f.value) + at(f.loc) + "\n";
    }
    for (const Torque& t : file.torques) {
        out +=
            "torque on " + t.body + frame(t.frame) + " = " + to_string(t.value) + at(t.loc) + "\n";
    }
    for (const Spring& s : file.springs) {
        out += "spring " + s.dof.name +
               (s.stiffness ? " stiffness " + to_string(*s.stiffness) : "") +
               (s.damping ? " damping " + to_string(*s.damping) : "") + at(s.loc) + "\n";
    }
    for (const GenForce& g : file.genforces) {
        out += "genforce " + g.dof.name + " = " + to_string(g.value) + at(g.loc) + "\n";
    }
    for (const Approx& a : file.approximations) {
        out += "approx ";
        for (std::size_t i = 0; i < a.symbols.size(); ++i) {
            out += (i > 0 ? ", " : "") + a.symbols[i].name;
        }
        out += " order " + std::to_string(a.order) + at(a.loc) + "\n";
    }
    if (file.linearize) {
        out += "linearize" + at(file.linearize->loc) + "\n";
        for (const Assignment& a : file.linearize->point) {
            out += "  " + a.name + std::string(static_cast<std::size_t>(a.primes), '\'') + " = " +
                   to_string(a.value) + at(a.loc) + "\n";
        }
    }
    if (file.initial) {
        out += "initial" + at(file.initial->loc) + "\n";
        for (const Assignment& a : file.initial->state) {
            out += "  " + a.name + std::string(static_cast<std::size_t>(a.primes), '\'') + " = " +
                   to_string(a.value) + at(a.loc) + "\n";
        }
    }
    for (const Output& o : file.outputs) {
        std::string point;
        if (o.frame_point.kind == PointRef::Kind::tip) point = ".tip";
        if (o.frame_point.kind == PointRef::Kind::node && o.frame_point.node)
            point = ".node(" + to_string(*o.frame_point.node) + ")";
        out += "output " + o.id.name + " = " + to_string(o.value) + frame(o.frame) + point +
               at(o.loc) + doc(o.id) + "\n";
    }
    for (const External& e : file.externals) {
        out += "external ";
        if (e.kind == External::Kind::genforce) {
            out += "genforce (";
            for (std::size_t i = 0; i < e.dofs.size(); ++i)
                out += (i > 0 ? ", " : "") + e.dofs[i].name;
            out += ")";
        } else {
            out += std::string(e.kind == External::Kind::force ? "force" : "torque") + " on " +
                   e.body + (e.at ? " at " + to_string(*e.at) : "") + frame(e.frame);
        }
        out += " = " + e.function.name + "(";
        for (std::size_t i = 0; i < e.args.size(); ++i)
            out += (i > 0 ? ", " : "") + to_string(e.args[i].value) + frame(e.args[i].frame);
        out += ")" + std::string(e.without_jacobian ? " without jacobian" : "") + at(e.loc) + "\n";
    }
    for (const Load& l : file.loads) {
        out += "load " + l.kind.name + " " + l.id.name + at(l.loc) + "\n";
        for (const Property& p : l.roles) out += "  " + property(p);
    }
    for (const Constraint& c : file.constraints) {
        out += "constraint " + c.kind.name + " " + c.id.name + at(c.loc) + "\n";
        for (const Property& p : c.roles) out += "  " + property(p);
    }
    return out;
}

} // namespace yamsc::ast
