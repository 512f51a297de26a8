#include "model_handle.hpp"

#include "analysis/constrained_model.hpp"

#include "diag/errors.hpp"

#include <algorithm>
#include <cstring>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace yamsc::python {

namespace {

/// `routines=` as the ABI's routines; none given: every one (Python may call any).
codegen::RoutineSet routine_set(const std::vector<std::string>& names) {
    if (names.empty()) return codegen::abi_routines();
    codegen::RoutineSet set;
    for (const std::string& name : names) {
        const std::optional<codegen::RoutineId> id = codegen::routine_named(name);
        if (!id || !codegen::abi_routines().contains(*id))
            throw std::invalid_argument("the model ABI has no routine '" + name + "'");
        set.insert(*id);
    }
    return set;
}

/// `link length [m]` -> `m`: the bracket at the end of a doc comment.
std::string unit_of(const std::string& doc) {
    const std::size_t close = doc.find_last_not_of(" \t");
    if (close == std::string::npos || doc[close] != ']') return "";
    const std::size_t open = doc.rfind('[', close);
    return open == std::string::npos ? "" : doc.substr(open + 1, close - open - 1);
}

template <class Item> const Item* named(const std::vector<Item>& items, const std::string& name) {
    for (const Item& item : items)
        if (item.name == name) return &item;
    return nullptr;
}

} // namespace

ModelHandle ModelHandle::from_source(const std::string& path, const std::string& sid,
                                     const std::vector<driver::Assignment>& set,
                                     std::vector<std::string> routines, const std::string& external,
                                     const analysis::BlockOptions& blocks) {
    std::ostringstream err;
    ModelHandle h;
    h.blocks_ = blocks;
    try {
        codegen::RoutineSet wanted = routine_set(routines);
        analysis::add_block_routines(blocks, wanted.contains(codegen::RoutineId::rhs_jacobian),
                                     wanted);
        std::optional<analysis::Loaded> loaded =
            analysis::load(path, set, sid, false, err, {}, wanted, external);
        if (!loaded) throw LoadError(err.str());
        h.loaded_ = std::move(*loaded);
        h.loaded_.view = analysis::with_load_blocks(h.loaded_, blocks);
    } catch (const LoadError&) {
        throw;
    } catch (const std::exception& e) {
        // UserError (a --set name that does not exist, a block the model does
        // not declare), a failed compile, ...
        throw LoadError(err.str() + e.what());
    }
    return h;
}

ModelHandle ModelHandle::from_library(const std::string& path,
                                      const std::vector<driver::Assignment>& set) {
    ModelHandle h;
    try {
        h.loaded_ = analysis::load_library(path, set);
    } catch (const std::exception& e) {
        throw LoadError(e.what());
    }
    return h;
}

const runtime::ModelView& ModelHandle::view_at(const double* p) {
    if (!p) return loaded_.view;
    const std::size_t n = loaded_.params.size();
    if (n == 0 || std::equal(p, p + n, loaded_.params.begin())) return loaded_.view;
    if (other_params_.size() != n || !std::equal(p, p + n, other_params_.begin())) {
        const std::vector<double> params(p, p + n);
        other_view_ = analysis::with_load_blocks(
            loaded_, analysis::constrained_view(library().view(params)), params, blocks_);
        other_params_.assign(p, p + n);
    }
    return other_view_;
}

std::vector<double> ModelHandle::params_at(const double* p) const {
    return p ? std::vector<double>(p, p + loaded_.params.size()) : loaded_.params;
}

std::vector<Described> ModelHandle::described(const std::string& kind) const {
    const runtime::SharedModel& lib = library();
    const std::optional<model::Model>& m = loaded_.front.model;
    std::vector<Described> out;
    auto add = [&](const std::string& name, const std::string* doc) {
        out.push_back({name, doc ? *doc : "", doc ? unit_of(*doc) : ""});
    };
    if (kind == "dofs") {
        for (const std::string& n : lib.dof_names()) {
            const auto* d = m ? named(m->dofs, n) : nullptr;
            add(n, d ? &d->doc : nullptr);
        }
    } else if (kind == "inputs") {
        for (const std::string& n : lib.input_names()) {
            // u' and u'' are channels of the input u.
            const auto* d = m ? named(m->inputs, n.substr(0, n.find('\''))) : nullptr;
            add(n, d ? &d->doc : nullptr);
        }
    } else if (kind == "params") {
        for (const std::string& n : lib.param_names()) {
            const auto* d = m ? named(m->params, n) : nullptr;
            add(n, d ? &d->doc : nullptr);
        }
    } else if (kind == "outputs") {
        for (const std::string& n : lib.output_names()) {
            const auto* d = m ? named(m->outputs, n) : nullptr;
            add(n, d ? &d->doc : nullptr);
        }
    } else {
        throw std::invalid_argument("unknown kind '" + kind + "'");
    }
    return out;
}

} // namespace yamsc::python
