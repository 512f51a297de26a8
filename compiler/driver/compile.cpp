// `yamsc MODEL -o FILE`: the whole pipeline, ending in generated files.
#include "ast/ast.hpp"
#include "codegen/emit.hpp"
#include "codegen/module.hpp"
#include "driver/commands.hpp"
#include "driver/files.hpp"
#include "driver/outputs.hpp"

#include "codegen/linear_routines.hpp"
#include "driver/pipeline.hpp"
#include "driver/targets.hpp"
#include "model/names.hpp"
#include <yamsc/atomic_file.hpp>

#include <optional>
#include <ostream>

namespace yamsc::driver {

namespace {

std::string basename(const std::string& path) {
    auto slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

bool is_identifier(const std::string& s) {
    if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
    for (char c : s)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
    return true;
}

void check_namespace(const std::string& ns, const Target& target) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (true) {
        auto pos = ns.find("::", start);
        parts.push_back(ns.substr(start, pos - start));
        if (pos == std::string::npos) break;
        start = pos + 2;
    }
    if (!target.nested_namespaces && parts.size() > 1)
        throw UsageError("--namespace for C output is a single identifier (the function prefix)");
    for (const auto& p : parts) {
        if (!is_identifier(p))
            throw UsageError("--namespace '" + ns + "' is not a valid identifier");
        std::string why = model::reserved_reason(p);
        if (!why.empty()) throw UsageError("--namespace '" + p + "' " + why);
    }
}

/// Make-style dependency file: the outputs depend on the model file and on every
/// data file it read (SID, ElastoDyn).
std::string depfile_text(const CompileOptions& o, const std::vector<std::string>& data_files) {
    std::vector<std::string> targets{o.output};
    if (!o.header.empty()) targets.push_back(o.header);
    std::vector<std::string> deps{o.model};
    deps.insert(deps.end(), data_files.begin(), data_files.end());
    return make_rule(targets, deps);
}

std::string join(const std::vector<std::string>& items) {
    std::string s;
    for (const std::string& item : items) s += (s.empty() ? "" : ",") + item;
    return s;
}

codegen::EmitOptions::Real real_type(const CompileOptions& o) {
    return o.real == Real::single_precision ? codegen::EmitOptions::Real::single_precision
                                            : codegen::EmitOptions::Real::double_precision;
}

const char* derivatives_name(Derivatives d) {
    return d == Derivatives::unrolled ? "unrolled" : d == Derivatives::tangent ? "tangent" : "auto";
}

/// The module options from the command line (--sensitivities: their
/// parameter derivatives are passes of the front end).
codegen::Options module_options(const CompileOptions& o) {
    codegen::Options options;
    options.sensitivity_params = o.sensitivities;
    return options;
}

/// --jacobians; sensitivities are formed from the unrolled Jacobians (the CLI
/// refuses them with --jacobians tangent). A target that prints the System, not
/// the code module (LaTeX), prints M and the unrolled Jacobians, whatever the size.
Derivatives derivatives_of(const CompileOptions& o, const Target& target) {
    if (!o.sensitivities.empty() || !target.prints_module) return Derivatives::unrolled;
    return o.jacobians.value_or(Derivatives::automatic);
}

} // namespace

int compile(const CompileOptions& o, std::ostream& out, std::ostream& err) {
    const Target& target = driver::target(o.dump == Dump::none ? o.lang : Language::cpp);
    if (!o.name_space.empty()) check_namespace(o.name_space, target);
    // --dump prints and writes no file.
    const std::vector<NamedFile> output_files =
        o.dump == Dump::none ? std::vector<NamedFile>{{"-o", o.output},
                                                      {"--header", o.header},
                                                      {"--depfile", o.depfile}}
                             : std::vector<NamedFile>{};
    check_outputs({{"the model", o.model}}, output_files);

    diag::Diagnostics diags;
    auto progress = [&](const std::string& s) {
        if (o.verbose) err << "yamsc: " << s << "\n";
    };
    Until until = o.dump == Dump::ast     ? Until::ast
                  : o.dump == Dump::model ? Until::model
                                          : Until::jacobians;
    FrontEnd fe = run_front_end(
        o.model, until, diags, progress,
        DerivativeRequest(derivatives_of(o, target), o.sensitivities), [&](const model::Model& m) {
            check_outputs(data_files_of(m), output_files);
            if (!o.sensitivities.empty() && !m.externals.empty())
                throw UsageError("--sensitivities: the model declares external "
                                 "functions, whose parameter derivatives are not "
                                 "supported yet");
        });
    err << diags.render();
    if (diags.has_errors()) return 1;
    if (o.jacobians == Derivatives::tangent && fe.model && fe.model->dofs.empty())
        throw UsageError("--jacobians tangent does not apply to a model without DOFs: it has no "
                         "Jacobian to form");
    if (o.jacobians == Derivatives::tangent && fe.system && !fe.system->tangent_form)
        throw UsageError("--jacobians tangent does not apply to a model with `approx` or with "
                         "outputs that read accelerations (reaction loads, q''): both work on M "
                         "itself");
    if (o.dump == Dump::ast) {
        out << ast::dump(*fe.ast);
        return 0;
    }
    if (o.dump == Dump::model) {
        out << model::dump(*fe.model);
        return 0;
    }
    if (!o.header.empty() && !target.header)
        throw UsageError(std::string("--header does not apply to --lang ") + target.name);
    std::optional<codegen::Module> module;
    if (target.prints_module) {
        module = codegen::build_module(*fe.system, module_options(o));
        codegen::add_operating_point(*module, *fe.system);
        progress("built the code module (common subexpressions shared)");
        if (o.dump == Dump::module) {
            out << codegen::dump(*module);
            return 0;
        }
    }
    codegen::EmitOptions emit;
    emit.namespace_name = o.name_space;
    emit.header_name = o.header.empty() ? "" : basename(o.header);
    emit.compiler_version = YAMSC_VERSION;
    emit.real = real_type(o);
    // Only the options that shape the output are recorded, so identical inputs give
    // identical bytes wherever the files are written.
    emit.command_line =
        std::string("--lang ") + target.name +
        (o.name_space.empty() ? "" : " --namespace " + o.name_space) +
        (o.header.empty() ? "" : " --header " + emit.header_name) +
        (!o.real                             ? ""
         : *o.real == Real::single_precision ? " --real float"
                                             : " --real double") +
        (!o.jacobians ? "" : std::string(" --jacobians ") + derivatives_name(*o.jacobians)) +
        (o.sensitivities.empty() ? "" : " --sensitivities " + join(o.sensitivities));
    const codegen::EmittedFiles files =
        target.emit(TargetInput{o, fe, module ? &*module : nullptr, emit});
    // Both written before either is replaced, the header renamed first: a source
    // is never left referring to a missing or stale header.
    std::vector<std::pair<std::string, std::string>> outputs;
    if (!o.header.empty()) outputs.emplace_back(o.header, files.header);
    outputs.emplace_back(o.output, files.source);
    runtime::write_files_atomically(outputs);
    if (!o.depfile.empty())
        runtime::write_file_atomically(o.depfile, depfile_text(o, fe.model->files_read));
    progress("wrote " + o.output + (o.header.empty() ? "" : " and " + o.header) + " (" +
             std::to_string(files.source.size() + files.header.size()) + " bytes)");
    return 0;
}

} // namespace yamsc::driver
