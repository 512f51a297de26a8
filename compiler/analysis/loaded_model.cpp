#include "analysis/loaded_model.hpp"

#include "analysis/constrained_model.hpp"

#include "analysis/external_library.hpp"
#include "analysis/jit.hpp"
#include "diag/diagnostics.hpp"
#include "driver/bindings.hpp"
#include "driver/sid_values.hpp"
#include "model/expr_check.hpp"
#include "model/scene_channels.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <ostream>

namespace yamsc::analysis {

using diag::UserError;
using driver::Assignment;
using driver::bind_named;
using driver::bind_state;
using driver::check_outputs;
using driver::content_digest;
using driver::continue_front_end;
using driver::data_files_of;
using driver::Derivatives;
using driver::FrontEnd;
using driver::NamedFile;
using driver::run_front_end;
using driver::sid_parameter_values;
using driver::Until;

namespace {

/// Values of parameter expressions (the `initial` and `linearize` blocks) at
/// the bound parameters; `names[i]` names values[i] in messages.
std::vector<double> evaluate_at(const Loaded& l, const std::vector<double>& params,
                                const std::vector<model::Expr>& values,
                                const std::vector<std::string>& names, const char* block) {
    model::NameValues bound;
    const std::vector<std::string>& param_names = l.library->param_names();
    for (std::size_t i = 0; i < param_names.size() && i < params.size(); ++i)
        bound[param_names[i]] = params[i];
    std::vector<double> out;
    for (std::size_t i = 0; i < values.size(); ++i) {
        std::string why;
        const std::optional<double> x = model::evaluate_with(values[i], bound, why);
        if (!x)
            throw UserError(std::string("the ") + block + " value of '" +
                            (i < names.size() ? names[i] : "?") + "' cannot be evaluated: " + why);
        out.push_back(*x);
    }
    return out;
}

std::vector<std::string> primed(const std::vector<std::string>& names) {
    std::vector<std::string> out;
    for (const std::string& n : names) out.push_back(n + "'");
    return out;
}

} // namespace

std::optional<Loaded> load(const std::string& path, const std::vector<Assignment>& set,
                           const std::string& sid_spec, bool verbose, std::ostream& err,
                           const std::vector<NamedFile>& outputs, codegen::RoutineSet routines,
                           const std::string& external, ModelChannels channels) {
    std::optional<Loaded> l =
        load_unbound(path, sid_spec, verbose, err, outputs, routines, external, channels);
    if (l) bind_parameters(*l, set);
    return l;
}

std::optional<Loaded> load_unbound(const std::string& path, const std::string& sid_spec,
                                   bool verbose, std::ostream& err,
                                   const std::vector<NamedFile>& outputs,
                                   codegen::RoutineSet routines, const std::string& external,
                                   ModelChannels channels) {
    // One model at a time per process: the derivation (GiNaC) shares global
    // state, and the JIT names its temporary files by process id. Python
    // threads (yamsc.load, a Dask worker's batch tasks) can load at once.
    static std::mutex loading;
    std::lock_guard<std::mutex> lock(loading);
    diag::Diagnostics diags;
    auto progress = [&](const std::string& s) {
        if (verbose) err << "yamsc: " << s << "\n";
    };
    FrontEnd fe =
        run_front_end(path, Until::model, diags, progress, Derivatives::automatic,
                      [&](const model::Model& m) { check_outputs(data_files_of(m), outputs); });
    err << diags.render();
    if (diags.has_errors()) return std::nullopt;
    if (channels == ModelChannels::scene) model::add_scene_channels(*fe.model);
    JitOptions jit;
    jit.progress = progress;
    jit.notice = [&](const std::string& s) { err << "yamsc: " << s << std::endl; };
    // The external functions first: the model's library binds to them when it loads.
    diag::Diagnostics missing;
    const std::optional<ExternalLibrary> externals =
        load_external_library(*fe.model, external, jit, missing);
    err << missing.render();
    if (!externals) return std::nullopt;
    for (const std::string& note : externals->notes)
        if (verbose || note.find("central differences") != std::string::npos)
            err << "yamsc: note: " << note << "\n";
    const ModelIdentity id{fe.model->name, content_digest(*fe.source, *fe.model), routines,
                           channels};
    // Reported as located diagnostics (exit 1), like the checker's errors.
    struct NotDerived {};
    auto derive = [&]() {
        diag::Diagnostics derivation;
        FrontEnd full = fe;
        continue_front_end(full, path, Until::jacobians, derivation, progress);
        err << derivation.render();
        if (derivation.has_errors() || !full.system) throw NotDerived{};
        return std::move(*full.system);
    };
    Loaded l;
    try {
        l.library = load_compiled_model(id, derive, jit);
    } catch (const NotDerived&) {
        return std::nullopt;
    }
    // --sid values first, so that --set still overrides them.
    if (!sid_spec.empty()) l.sid_values = sid_parameter_values(*fe.model, sid_spec);
    l.digest = id.content_digest;
    l.front = std::move(fe);
    return l;
}

void bind_parameters(Loaded& l, const std::vector<Assignment>& set) {
    std::vector<std::optional<double>> defaults;
    for (double v : l.library->default_params())
        defaults.push_back(std::isnan(v) ? std::nullopt : std::optional<double>(v));
    std::vector<Assignment> all = l.sid_values;
    all.insert(all.end(), set.begin(), set.end());
    l.params = bind_named(l.library->param_names(), defaults, all, "parameter");
    // A model with constraints moves with them in every command (constrained_model.hpp).
    l.view = constrained_view(l.library->view(l.params));
}

Loaded load_library(const std::string& path, const std::vector<Assignment>& set) {
    Loaded l;
    l.library = std::make_unique<runtime::SharedModel>(path);
    bind_parameters(l, set);
    return l;
}

codegen::RoutineSet linear_model_routines() {
    using codegen::RoutineId;
    return {RoutineId::rhs, RoutineId::rhs_jacobian, RoutineId::mass_matrix, RoutineId::forcing,
            RoutineId::jacobians};
}

bool refuse_without_dofs(const Loaded& l, const std::string& command, const std::string& verb,
                         std::ostream& err) {
    if (l.view.nq > 0) return false;
    const std::string message = "`yamsc " + command +
                                "`: the model has no DOF (its motion is all prescribed), there "
                                "is nothing to " +
                                verb + " (`yamsc sim` and `yamsc eval` evaluate its outputs)";
    if (!l.front.ast || !l.front.ast->model) throw UserError(message);
    diag::Diagnostics diags;
    diags.error(diag::Kind::DofUsage, l.front.ast->model->loc, message);
    err << diags.render();
    return true;
}

std::vector<double> inputs_of(const runtime::ModelView& v, const std::vector<Assignment>& u) {
    return bind_named(v.input_names, std::vector<std::optional<double>>(v.input_names.size(), 0.0),
                      u, "input");
}

void operating_point(const Loaded& l, const std::vector<double>& params,
                     const std::vector<Assignment>& at, const std::vector<Assignment>& u_given,
                     std::vector<double>& q, std::vector<double>& qd, std::vector<double>& u) {
    const runtime::ModelView& v = l.view;
    q.assign(static_cast<std::size_t>(v.nq), 0.0);
    qd.assign(static_cast<std::size_t>(v.nq), 0.0);
    u.assign(static_cast<std::size_t>(v.nu), 0.0);
    if (l.front.model && l.front.model->operating_point) {
        const auto& op = *l.front.model->operating_point;
        q = evaluate_at(l, params, op.q, v.dof_names, "linearize");
        qd = evaluate_at(l, params, op.qd, primed(v.dof_names), "linearize");
        u = evaluate_at(l, params, op.u, v.input_names, "linearize");
    }
    for (const Assignment& a : at) {
        const std::string channel = a.name + std::string(static_cast<std::size_t>(a.primes), '\'');
        auto dof = std::find(v.dof_names.begin(), v.dof_names.end(), a.name);
        auto input = std::find(v.input_names.begin(), v.input_names.end(), channel);
        if (dof != v.dof_names.end() && a.primes <= 1)
            (a.primes == 0 ? q : qd)[static_cast<std::size_t>(dof - v.dof_names.begin())] = a.value;
        else if (input != v.input_names.end())
            u[static_cast<std::size_t>(input - v.input_names.begin())] = a.value;
        else {
            std::vector<std::string> names = v.dof_names;
            names.insert(names.end(), v.input_names.begin(), v.input_names.end());
            throw UserError("--at: unknown DOF or input '" + channel + "'" +
                            diag::did_you_mean(a.name, names));
        }
    }
    std::vector<std::optional<double>> from_point(u.begin(), u.end());
    u = bind_named(v.input_names, from_point, u_given, "input");
}

void initial_state(const Loaded& l, const std::vector<Assignment>& ic, std::vector<double>& q,
                   std::vector<double>& qd) {
    const runtime::ModelView& v = l.view;
    q.assign(static_cast<std::size_t>(v.nq), 0.0);
    qd.assign(static_cast<std::size_t>(v.nq), 0.0);
    if (l.front.model && l.front.model->initial_state) {
        const auto& init = l.front.model->initial_state;
        q = evaluate_at(l, l.params, init->q, v.dof_names, "initial");
        qd = evaluate_at(l, l.params, init->qd, primed(v.dof_names), "initial");
    }
    std::vector<double> given_q, given_qd;
    bind_state(v.dof_names, ic, given_q, given_qd, "--ic");
    for (const Assignment& a : ic) {
        const auto i = static_cast<std::size_t>(
            std::find(v.dof_names.begin(), v.dof_names.end(), a.name) - v.dof_names.begin());
        (a.primes == 0 ? q : qd)[i] = (a.primes == 0 ? given_q : given_qd)[i];
    }
}
} // namespace yamsc::analysis
