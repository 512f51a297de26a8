#include "driver/pipeline.hpp"

#include "data/file_source.hpp"
#include "driver/files.hpp"
#include "lower/lower.hpp"
#include "parse/parser.hpp"
#include "passes/passes.hpp"
#include "symbolic/approx.hpp"
#include "symbolic/derive.hpp"
#include "symbolic/linearize.hpp"

#include <chrono>
#include <cstdio>

namespace yamsc::driver {

namespace {

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

} // namespace

FrontEnd run_front_end(const std::string& path, Until until, diag::Diagnostics& diags,
                       const std::function<void(const std::string&)>& progress,
                       Derivatives derivatives,
                       const std::function<void(const model::Model&)>& checked) {
    auto say = [&](const std::string& s) {
        if (progress) progress(s);
    };
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
    say(timed("parsed and checked", clock.seconds()));
    // Only the Jacobian stage can use the tangent form; `approx` needs M itself.
    const bool tangent =
        until == Until::jacobians && fe.model->approximations.empty() &&
        (derivatives == Derivatives::tangent ||
         (derivatives == Derivatives::automatic && fe.model->dofs.size() >= tangent_form_min_dofs));
    fe.equations = symbolic::derive(*fe.model, diags, !tangent);
    if (!fe.equations || diags.has_errors()) return fe;
    fe.equations->source_path = path;
    // The digest covers the data files too: generated code changes when they do.
    std::string all = fe.source->text();
    for (const auto& f : fe.model->files_read) {
        diag::Diagnostics ignored;
        if (auto data = read_source(f, ignored)) all += "\n" + data->text();
    }
    fe.equations->source_digest = digest(all);
    say(timed("derived the equations of motion", clock.seconds()));
    if (!fe.model->approximations.empty()) {
        if (!symbolic::approximate(*fe.model, *fe.equations, diags)) return fe;
        say(timed("approximated (approx)", clock.seconds()));
    }
    if (until != Until::jacobians) return fe;
    fe.system = lower::lower(*fe.equations, symbolic::operating_point(*fe.model, *fe.equations));
    say(timed("imported the equations into the IR", clock.seconds()));
    if (tangent) {
        passes::derive_tangent(*fe.system);
        say(timed("derived the tangent (directional derivatives)", clock.seconds()));
    } else {
        passes::derive_jacobians(*fe.system);
        passes::output_jacobians(*fe.system);
        say(timed("derived the Jacobians", clock.seconds()));
    }
    return fe;
}

} // namespace yamsc::driver
