#include "driver/pipeline.hpp"

#include "codegen/external_wrappers.hpp"
#include "data/file_source.hpp"
#include "diag/errors.hpp"
#include "driver/derivation_loader.hpp"
#include "driver/files.hpp"
#include "ir/param_index.hpp"
#include "model/load_check.hpp"
#include "model/names.hpp"
#include "parse/parser.hpp"
#include "passes/pipeline.hpp"
#include "passes/taylor.hpp"

#include <chrono>
#include <cstdio>

namespace yamsc::driver {

namespace {

/// Whether an expression reads the accelerations: a reaction load or a DOF's q''.
bool reads_accelerations(const model::Model& m, const ast::Expr& e) {
    if (e.kind == ast::Expr::Kind::call && model::is_reaction_function(e.text)) return true;
    if (e.kind == ast::Expr::Kind::name && e.primes == 2)
        for (const auto& d : m.dofs)
            if (d.name == e.text) return true;
    for (const ast::Expr& a : e.args)
        if (reads_accelerations(m, a)) return true;
    return false;
}

/// Outputs that read q'' need M, which the tangent form does not derive.
bool outputs_read_accelerations(const model::Model& m) {
    for (const auto& o : m.outputs)
        if (reads_accelerations(m, o.value)) return true;
    return false;
}

class Stopwatch {
public:
    double seconds() const {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }

private:
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

std::string timed(const char* what, double s) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%s: %.3f s", what, s);
    return buf;
}

/// The model's `approx` groups, in order, as the passes' symbol groups.
std::vector<passes::PassPlan::Approximation> approximations(const model::Model& m) {
    // The first channel of each input (its derivatives are channels of their own).
    std::vector<int> first_channel;
    int channel = 0;
    for (const model::Input& in : m.inputs) {
        first_channel.push_back(channel);
        channel += in.order + 1;
    }
    std::vector<passes::PassPlan::Approximation> out;
    for (const model::Approximation& group : m.approximations) {
        passes::PassPlan::Approximation a;
        a.order = group.order;
        for (const auto& sym : group.symbols) {
            if (sym.kind == model::NameKind::param)
                a.group.push_back({ir::SymbolKind::param, sym.index});
            else if (sym.kind == model::NameKind::dof)
                a.group.push_back({ir::SymbolKind::q, sym.index});
            else
                a.group.push_back(
                    {ir::SymbolKind::input, first_channel.at(static_cast<std::size_t>(sym.index))});
        }
        out.push_back(std::move(a));
    }
    return out;
}

/// Reports what an `approx` group cannot expand at the group's line.
void report(const model::Approximation& group, const passes::NotExpandable& x,
            diag::Diagnostics& diags) {
    std::string names;
    for (const auto& sym : group.symbols) names += (names.empty() ? "" : ", ") + sym.name;
    diags.error(x.not_supported ? diag::Kind::NotSupported : diag::Kind::InvalidValue, group.loc,
                "approx: cannot expand the equations in " + names + " to order " +
                    std::to_string(group.order) + ": they contain " + x.what());
}

/// --sensitivities: the parameters' indices in the System; a misspelt name is an
/// error, not a silent no-op.
std::vector<std::size_t> parameter_indices(const ir::System& s,
                                           const std::vector<std::string>& names) {
    std::vector<std::size_t> indices;
    for (const std::string& name : names) {
        const std::optional<std::size_t> i = ir::param_index(s, name);
        if (!i)
            throw diag::UsageError("--sensitivities: '" + name +
                                   "' is not a parameter of the model");
        indices.push_back(*i);
    }
    return indices;
}

/// The externals as the IR keeps them: their input channels follow every
/// declared one; `args` holds placeholders until passes::separate_externals.
std::vector<ir::External> system_externals(const model::Model& m) {
    int channel = 0;
    for (const model::Input& in : m.inputs) channel += in.order + 1;
    std::vector<ir::External> out;
    for (const model::External& e : m.externals) {
        ir::External x;
        x.name = e.name;
        x.what = e.kind == model::External::Kind::force    ? "force on " + m.bodies[e.body].name
                 : e.kind == model::External::Kind::torque ? "torque on " + m.bodies[e.body].name
                                                           : "generalized forces";
        // The file's name only: compiled models are cached by content, whatever
        // the folder they were compiled from (analysis/jit_cache.hpp).
        std::string file = e.loc.file ? e.loc.file->path() : std::string("?");
        if (const auto slash = file.find_last_of('/'); slash != std::string::npos)
            file = file.substr(slash + 1);
        x.location = file + ":" + std::to_string(e.loc.line) + ":" + std::to_string(e.loc.col);
        x.first_input = channel;
        x.results = e.results();
        channel += x.results;
        x.args.assign(e.args.size(), 0);
        x.user_jacobian = !e.without_jacobian;
        out.push_back(std::move(x));
    }
    return out;
}

} // namespace

std::string external_prototypes(const model::Model& m) {
    codegen::Module module;
    for (const ir::External& e : system_externals(m))
        module.externals.push_back({e.name, e.what, e.location, e.first_input, e.results,
                                    static_cast<int>(e.args.size()), e.user_jacobian});
    return codegen::external_prototypes(module);
}

std::string content_digest(const diag::SourceFile& source, const model::Model& m) {
    std::string all = model::without_load_statements(source.text(), m);
    for (const auto& f : m.files_read) {
        diag::Diagnostics ignored;
        if (auto data = read_source(f, ignored)) all += "\n" + data->text();
    }
    return digest(all);
}

FrontEnd run_front_end(const std::string& path, Until until, diag::Diagnostics& diags,
                       const std::function<void(const std::string&)>& progress,
                       const DerivativeRequest& derivatives,
                       const std::function<void(const model::Model&)>& checked) {
    FrontEnd fe;
    fe.source = read_source(path, diags);
    if (!fe.source) return fe;
    Stopwatch clock;
    fe.ast = parse::parse_model(fe.source, diags);
    if (!fe.ast || diags.has_errors() || until == Until::ast) return fe;
    fe.model = data::check_model(*fe.ast, diags);
    if (!fe.model || diags.has_errors()) return fe;
    if (checked) checked(*fe.model);
    if (until == Until::model) return fe;
    if (progress) progress(timed("parsed and checked", clock.seconds()));
    continue_front_end(fe, path, until, diags, progress, derivatives);
    return fe;
}

bool uses_tangent_form(const model::Model& m, Until until, Derivatives derivatives) {
    // Only the Jacobian stage can use the tangent form; `approx` and outputs that
    // read q'' (reaction loads) need M itself.
    const bool accelerations = outputs_read_accelerations(m);
    // The externals' chain rule is written for the unrolled Jacobians.
    const bool externals = !m.externals.empty();
    if (externals && derivatives == Derivatives::tangent && until == Until::jacobians)
        throw diag::UsageError("--jacobians tangent: the model declares external functions, "
                               "whose chain rule needs the unrolled Jacobians (use auto or "
                               "unrolled)");
    // The constrained rhs (Schur complement of B M^-1 B^T) needs M itself.
    const bool constraints = !m.constraints.empty();
    if (constraints && derivatives == Derivatives::tangent && until == Until::jacobians)
        throw diag::UsageError("--jacobians tangent: the model declares constraints, whose "
                               "rows need the unrolled form (use auto or unrolled)");
    // Without DOFs there are no Jacobians to form column by column.
    return until == Until::jacobians && !m.dofs.empty() && m.approximations.empty() &&
           !accelerations && !externals && !constraints &&
           (derivatives == Derivatives::tangent ||
            (derivatives == Derivatives::automatic && m.dofs.size() >= tangent_form_min_dofs));
}

void continue_front_end(FrontEnd& fe, const std::string& path, Until until,
                        diag::Diagnostics& diags,
                        const std::function<void(const std::string&)>& progress,
                        const DerivativeRequest& derivatives) {
    if (!fe.model || !fe.source)
        throw diag::InternalError("continue_front_end needs a checked model");
    Stopwatch clock;
    const bool tangent = uses_tangent_form(*fe.model, until, derivatives.form);
    const model::Model derived = model::with_external_channels(*fe.model);
    derivation::DerivationRequest request;
    request.model = &derived;
    request.mass_matrix = !tangent;
    request.source_path = path;
    // The digest covers the data files too: generated code changes when they do.
    request.source_digest = content_digest(*fe.source, *fe.model);
    derivation::DerivationResult derived_system;
    derive_through_module(request, diags, derived_system);
    if (!derived_system.system || diags.has_errors()) return;
    fe.system = std::move(derived_system.system);
    if (progress) {
        // The stage times as before the module: since this function started.
        const double before =
            clock.seconds() - derived_system.derive_seconds - derived_system.lower_seconds;
        progress(timed("derived the equations of motion", before + derived_system.derive_seconds));
        progress(timed("imported the equations into the IR", clock.seconds()));
    }
    finish_front_end(fe, until, tangent, diags, progress, clock.seconds(),
                     derivatives.sensitivities);
}

void finish_front_end(FrontEnd& fe, Until until, bool tangent, diag::Diagnostics& diags,
                      const std::function<void(const std::string&)>& progress,
                      double seconds_so_far, const std::vector<std::string>& sensitivities) {
    if (!fe.model || !fe.system)
        throw diag::InternalError("finish_front_end needs a checked model and its System");
    Stopwatch clock;
    auto say = [&](const char* what) {
        if (progress) progress(timed(what, seconds_so_far + clock.seconds()));
    };
    passes::PassPlan plan;
    plan.externals = !fe.model->externals.empty();
    if (plan.externals) fe.system->externals = system_externals(*fe.model);
    plan.approximations = approximations(*fe.model);
    if (until == Until::jacobians) {
        using D = passes::PassPlan::Derivatives;
        plan.derivatives = tangent ? D::tangent : D::unrolled;
        plan.sensitivity_params = parameter_indices(*fe.system, sensitivities);
    }
    // The progress lines name stages, each ending with one of these passes.
    const ir::Pass jacobians_done =
        plan.externals ? ir::Pass::external_jacobians : ir::Pass::output_jacobians;
    std::size_t approximated = 0;
    auto after = [&](ir::Pass p) {
        if (p == ir::Pass::approximate && ++approximated == plan.approximations.size())
            say("approximated (approx)");
        if (p == ir::Pass::derive_tangent) say("derived the tangent (directional derivatives)");
        if (p == jacobians_done) say("derived the Jacobians");
    };
    try {
        passes::run_pipeline(*fe.system, plan, after);
    } catch (const passes::NotExpandable& x) {
        report(fe.model->approximations.at(x.group), x, diags);
    }
}

} // namespace yamsc::driver
