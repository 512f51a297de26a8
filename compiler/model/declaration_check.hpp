#pragma once
// What `load` and `constraint` declarations share: a kind looked up in its
// table, a name of its own.
#include "diag/diagnostics.hpp"
#include "model/names.hpp"

#include <map>
#include <string>
#include <vector>

namespace yamsc::model {

/// The row of `kinds` named `kind`, or null after reporting an unknown one (with a
/// suggestion; `what`: "load block kind").
template <class Info>
const Info* find_kind(const std::vector<Info>& kinds, const ast::Named& kind,
                      const std::string& what, diag::Diagnostics& diags) {
    std::vector<std::string> names;
    for (const Info& k : kinds) {
        if (k.name == kind.name) return &k;
        names.push_back(k.name);
    }
    if (!kind.name.empty())
        diags.error(diag::Kind::UnknownName, kind.loc,
                    "unknown " + what + " '" + kind.name + "'" +
                        diag::did_you_mean(kind.name, names));
    return nullptr;
}

/// A declaration's name is not reserved and not one of `seen` (then added); false
/// after reporting (`what`: "load block").
inline bool fresh_declaration_name(const ast::Named& id, const std::string& what,
                                   std::map<std::string, diag::Location>& seen,
                                   diag::Diagnostics& diags) {
    const std::string why = reserved_reason(id.name);
    if (!why.empty()) {
        diags.error(diag::Kind::ReservedName, id.loc, "'" + id.name + "' " + why);
        return false;
    }
    const auto [it, fresh] = seen.emplace(id.name, id.loc);
    if (!fresh) {
        diags.error(diag::Kind::DuplicateName, id.loc,
                    what + " '" + id.name + "' is already declared at " +
                        std::to_string(it->second.line) + ":" + std::to_string(it->second.col));
        return false;
    }
    return true;
}

} // namespace yamsc::model
