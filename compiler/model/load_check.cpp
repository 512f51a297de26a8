#include "model/load_check.hpp"

#include "model/declaration_check.hpp"
#include "model/mesh_channels.hpp"

#include <algorithm>
#include <map>

namespace yamsc::model {

using diag::Kind;

namespace {

std::string quoted(const std::string& s) {
    return "'" + s + "'";
}

const char* target_noun(RoleTarget t) {
    switch (t) {
    case RoleTarget::input_read:
    case RoleTarget::load_input:
        return "input";
    case RoleTarget::output_read:
        return "output";
    case RoleTarget::parameter:
        return "parameter";
    case RoleTarget::body:
        return "body";
    }
    return "name";
}

const char* kind_noun(NameKind k) {
    switch (k) {
    case NameKind::param:
        return "a parameter";
    case NameKind::input:
        return "an input";
    case NameKind::dof:
        return "a DOF";
    case NameKind::body:
        return "a body";
    case NameKind::point:
        return "a point";
    case NameKind::time:
        return "the time";
    }
    return "a name";
}

class LoadChecker {
public:
    LoadChecker(const Model& model, const SymbolTable& names, diag::Diagnostics& diags)
        : names_(names), diags_(diags) {
        for (const Output& o : model.outputs) outputs_.push_back(o.name);
        for (const Input& i : model.inputs) inputs_.push_back(i.name);
        for (const Param& p : model.params) params_.push_back(p.name);
        for (const Body& b : model.bodies) bodies_.push_back(b.name);
    }

    void check(const ast::Load& decl, std::vector<LoadBlock>& out) {
        const LoadKindInfo* info = kind_of(decl.kind);
        const bool named = check_name(decl, info);
        if (!info) return;
        LoadBlock block;
        block.kind = info->kind;
        block.name = decl.id.name;
        block.loc = decl.loc;
        block.end = decl.end;
        block.bound.assign(info->roles.size(), "");
        std::vector<Loc> bound_at(info->roles.size());
        std::vector<bool> written(info->roles.size(), false); // reported when wrong
        bool ok = named;
        for (const ast::Property& p : decl.roles) {
            const auto role = std::find_if(info->roles.begin(), info->roles.end(),
                                           [&](const LoadRole& r) { return r.name == p.key; });
            if (role == info->roles.end()) {
                std::vector<std::string> roles;
                for (const LoadRole& r : info->roles) roles.push_back(r.name);
                diags_.error(Kind::UnknownProperty, p.loc,
                             "load block kind " + quoted(info->name) + " has no role " +
                                 quoted(p.key) + diag::did_you_mean(p.key, roles));
                ok = false;
                continue;
            }
            const auto r = static_cast<std::size_t>(role - info->roles.begin());
            if (written[r]) {
                diags_.error(Kind::DuplicateName, p.loc,
                             "role " + quoted(p.key) + " is already bound at " +
                                 std::to_string(bound_at[r].line) + ":" +
                                 std::to_string(bound_at[r].col));
                ok = false;
                continue;
            }
            written[r] = true;
            bound_at[r] = p.value.loc;
            const std::string name = bound_name(p, *role);
            if (name.empty()) {
                ok = false;
                continue;
            }
            block.bound[r] = name;
        }
        for (std::size_t r = 0; r < info->roles.size(); ++r)
            if (info->roles[r].required && !written[r] && decl.id.loc.line) {
                diags_.error(Kind::MissingProperty, decl.id.loc,
                             "load block " + quoted(block.name) + " has no role " +
                                 quoted(info->roles[r].name) + " (" + info->roles[r].what + ": `" +
                                 info->roles[r].name + " = " + target_noun(info->roles[r].target) +
                                 " name`)");
                ok = false;
            }
        ok = check_loads_apart(*info, block, bound_at) && ok;
        if (ok) out.push_back(std::move(block));
    }

private:
    const LoadKindInfo* kind_of(const ast::Named& kind) {
        return find_kind(load_kinds(), kind, "load block kind", diags_);
    }

    /// The block's name: an identifier of its own; its outputs NAME_<output>
    /// follow the model's and may not repeat one.
    bool check_name(const ast::Load& decl, const LoadKindInfo* info) {
        const std::string& name = decl.id.name;
        if (name.empty() || !fresh_declaration_name(decl.id, "load block", seen_, diags_))
            return false;
        if (!info) return true;
        for (const std::string& o : info->outputs) {
            const std::string full = info->output_name(name, o);
            if (std::find(outputs_.begin(), outputs_.end(), full) != outputs_.end()) {
                diags_.error(
                    Kind::DuplicateName, decl.id.loc,
                    "load block " + quoted(name) + " adds the output " + quoted(full) +
                        ", which the model declares already (" +
                        (info->prefixed_outputs ? "rename the block" : "rename the output") + ")");
                return false;
            }
        }
        return true;
    }

    /// The declared name a role is bound to, "" after reporting why not.
    std::string bound_name(const ast::Property& p, const LoadRole& role) {
        const char* noun = target_noun(role.target);
        const ast::Value& v = p.value;
        if (v.kind != ast::Value::Kind::expr || v.expr.kind != Expr::Kind::name ||
            v.expr.primes != 0) {
            const bool a = role.target == RoleTarget::parameter || role.target == RoleTarget::body;
            diags_.error(Kind::InvalidValue, v.loc,
                         "role " + quoted(p.key) + " takes the name of " + (a ? "a " : "an ") +
                             noun + " (" + role.what + ")");
            return "";
        }
        const std::string& name = v.expr.text;
        if (role.target == RoleTarget::output_read) {
            if (std::find(outputs_.begin(), outputs_.end(), name) != outputs_.end()) return name;
            const auto it = names_.find(name);
            if (it != names_.end())
                diags_.error(Kind::WrongKind, v.loc,
                             quoted(name) + " is " + kind_noun(it->second.kind) + "; role " +
                                 quoted(p.key) + " takes an output (" + role.what + ")");
            else
                diags_.error(Kind::UnknownName, v.loc,
                             "unknown output " + quoted(name) + diag::did_you_mean(name, outputs_));
            return "";
        }
        const NameKind want = role.target == RoleTarget::parameter ? NameKind::param
                              : role.target == RoleTarget::body    ? NameKind::body
                                                                   : NameKind::input;
        const auto it = names_.find(name);
        if (it == names_.end()) {
            const bool output = std::find(outputs_.begin(), outputs_.end(), name) != outputs_.end();
            if (output)
                diags_.error(Kind::WrongKind, v.loc,
                             quoted(name) + " is an output; role " + quoted(p.key) + " takes " +
                                 kind_noun(want) + " (" + role.what + ")");
            else
                diags_.error(Kind::UnknownName, v.loc,
                             std::string("unknown ") + noun + " " + quoted(name) +
                                 diag::did_you_mean(name, want == NameKind::param  ? params_
                                                          : want == NameKind::body ? bodies_
                                                                                   : inputs_));
            return "";
        }
        if (it->second.kind != want) {
            diags_.error(Kind::WrongKind, v.loc,
                         quoted(name) + " is " + kind_noun(it->second.kind) + "; role " +
                             quoted(p.key) + " takes " + kind_noun(want) + " (" + role.what + ")");
            return "";
        }
        return name;
    }

    /// An input a load is added to is bound to that role only: the block does
    /// not read its own load, and two loads do not share a channel.
    bool check_loads_apart(const LoadKindInfo& info, const LoadBlock& block,
                           const std::vector<Loc>& at) {
        bool ok = true;
        for (std::size_t r = 0; r < info.roles.size(); ++r) {
            if (info.roles[r].target != RoleTarget::load_input || block.bound[r].empty()) continue;
            for (std::size_t s = 0; s < info.roles.size(); ++s) {
                const RoleTarget t = info.roles[s].target;
                if (s == r || block.bound[s] != block.bound[r] ||
                    (t != RoleTarget::input_read && t != RoleTarget::load_input))
                    continue;
                if (t == RoleTarget::load_input && s < r) continue; // reported once
                diags_.error(Kind::InvalidValue, at[r],
                             "input " + quoted(block.bound[r]) + " is bound to role " +
                                 quoted(info.roles[r].name) + " and to role " +
                                 quoted(info.roles[s].name) +
                                 ": the input a load is added to is bound to that role only");
                ok = false;
            }
        }
        return ok;
    }

    const SymbolTable& names_;
    diag::Diagnostics& diags_;
    std::vector<std::string> outputs_, inputs_, params_, bodies_;
    std::map<std::string, Loc> seen_;
};

} // namespace

std::vector<LoadBlock> check_load_blocks(const ast::ModelFile& file, const Model& model,
                                         const SymbolTable& names, diag::Diagnostics& diags) {
    LoadChecker checker(model, names, diags);
    std::vector<LoadBlock> blocks;
    for (const ast::Load& decl : file.loads) checker.check(decl, blocks);
    return blocks;
}

std::string without_load_statements(const std::string& text, const Model& model) {
    if (model.loads.empty()) return text;
    std::vector<std::size_t> line_start{0};
    for (std::size_t i = 0; i < text.size(); ++i)
        if (text[i] == '\n') line_start.push_back(i + 1);
    auto offset = [&](const Loc& l) {
        const auto line = static_cast<std::size_t>(std::max(l.line, 1) - 1);
        if (line >= line_start.size()) return text.size();
        return std::min(text.size(), line_start[line] + static_cast<std::size_t>(l.col - 1));
    };
    std::string out;
    std::size_t from = 0;
    for (const LoadBlock& b : model.loads) {
        if (has_mesh(b)) continue; // its mesh channels are part of the equations
        const std::size_t start = offset(b.loc);
        std::size_t stop = text.find('\n', offset(b.end));
        stop = stop == std::string::npos ? text.size() : stop + 1;
        if (start < from || stop < start) continue; // not in file order: kept
        out.append(text, from, start - from);
        from = stop;
    }
    return out.append(text, from, std::string::npos);
}

} // namespace yamsc::model
