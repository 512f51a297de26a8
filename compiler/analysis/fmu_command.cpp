// `yamsc fmu`: the model as an FMI unit (docs/packaging.md, "FMI units").
#include "analysis/commands.hpp"
#include "analysis/constrained_model.hpp"
#include "analysis/fmu_binary.hpp"
#include "analysis/fmu_blocks.hpp"
#include "analysis/fmu_description.hpp"
#include "analysis/jit_cache.hpp"
#include "analysis/load_blocks.hpp"
#include "analysis/loaded_model.hpp"
#include "analysis/zip_store.hpp"
#include "codegen/module.hpp"
#include "diag/errors.hpp"
#include "driver/files.hpp"
#include "driver/outputs.hpp"
#include "driver/pipeline.hpp"
#include "text/number.hpp"

#include <yamsc/atomic_file.hpp>

#include <algorithm>
#include <fstream>
#include <ostream>
#include <sstream>

namespace yamsc::analysis {

using driver::FmiVersion;
using driver::FmuOptions;
using driver::NamedFile;

namespace {

/// The folder of binaries/ the standard names for this machine.
std::string platform(FmiVersion version) {
#if defined(__x86_64__)
    return version == FmiVersion::fmi3 ? "x86_64-linux" : "linux64";
#elif defined(__aarch64__)
    if (version == FmiVersion::fmi2)
        throw diag::UsageError("FMI 2.0 names no platform for aarch64 Linux: use --fmi-version 3");
    return "aarch64-linux";
#else
#error "yamsc fmu: unknown platform"
#endif
}

/// A GUID-shaped token from the unit's content: a different model, parameter
/// start or setting gives another, the same ones the same.
std::string token_of(const std::string& content) {
    const std::string hex = driver::digest(content) + driver::digest("token\n" + content);
    return "{" + hex.substr(0, 8) + "-" + hex.substr(8, 4) + "-" + hex.substr(12, 4) + "-" +
           hex.substr(16, 4) + "-" + hex.substr(20, 12) + "}";
}

runtime::Method runtime_method(driver::SimMethod m) {
    return m == driver::SimMethod::cvode  ? runtime::Method::cvode
           : m == driver::SimMethod::abm4 ? runtime::Method::abm4
                                          : runtime::Method::rk4;
}

std::vector<std::string> docs_of(const std::vector<std::string>& names,
                                 const std::function<std::string(const std::string&)>& doc) {
    std::vector<std::string> out;
    for (const std::string& n : names) out.push_back(doc(n));
    return out;
}

template <class Items> std::string doc_in(const Items& items, const std::string& name) {
    for (const auto& item : items)
        if (item.name == name) return item.doc;
    return "";
}

/// documentation/index.html: what the unit is and what it exposes.
std::string documentation(const model::Model& m, const std::vector<fmi::Variable>& vars) {
    auto html = [](const std::string& s) {
        std::string out;
        for (char c : s)
            out += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
        return out;
    };
    std::string out = "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" +
                      html(m.name) + "</title></head><body>\n<h1>" + html(m.name) + "</h1>\n<p>" +
                      html(m.title) +
                      "</p>\n<p>An FMI unit written by yamsc fmu: model exchange and "
                      "co-simulation (the integrator and step of the co-simulation are the "
                      "parameters yamsc.method and yamsc.step).</p>\n<table>\n"
                      "<tr><th>value reference</th><th>name</th><th>description</th></tr>\n";
    for (const fmi::Variable& v : vars)
        out += "<tr><td>" + std::to_string(v.value_reference) + "</td><td>" + html(v.name) +
               "</td><td>" + html(v.description) + "</td></tr>\n";
    return out + "</table>\n</body></html>\n";
}

} // namespace

int fmu(const FmuOptions& o, std::ostream& out, std::ostream& err) {
    BlockOptions blocks;
    blocks.aero = o.aero;
    std::vector<NamedFile> inputs{{"the model", o.model}, {"--external", o.external}};
    for (const NamedFile& f : block_files(blocks)) inputs.push_back(f);
    const std::vector<NamedFile> outputs{{"-o", o.output}, {"--depfile", o.depfile}};
    driver::check_outputs(inputs, outputs);
    auto progress = [&](const std::string& s) {
        if (o.verbose) err << "yamsc: " << s << "\n";
    };

    // As `sim` loads it (the same cached library): the parameters bound, the
    // start of its `initial` block, the blocks closed as the unit closes them.
    codegen::RoutineSet routines{codegen::RoutineId::rhs, codegen::RoutineId::outputs};
    add_block_routines(blocks, false, routines);
    std::optional<Loaded> l = load(o.model, o.set, "", o.verbose, err, outputs, routines,
                                   o.external.empty() ? "" : o.external);
    if (!l) return 1;
    std::vector<double> q0, qd0;
    initial_state(*l, {}, q0, qd0);
    const runtime::ModelView view = with_load_blocks(*l, blocks);
    // On the constraints, as sim starts (its dependent coordinates and speeds
    // solved from the independent ones): the unit starts where sim does.
    if (view.nc > 0) {
        std::vector<double> x = q0;
        x.insert(x.end(), qd0.begin(), qd0.end());
        x.insert(x.end(), view.block_initial_states.begin(), view.block_initial_states.end());
        consistent_start(view, 0.0, x, std::vector<double>(static_cast<std::size_t>(view.nu), 0.0),
                         o.verbose, err);
        std::copy(x.begin(), x.begin() + static_cast<long>(q0.size()), q0.begin());
        std::copy(x.begin() + static_cast<long>(q0.size()),
                  x.begin() + static_cast<long>(2 * q0.size()), qd0.begin());
    }
    const model::Model& m = *l->front.model;

    // The unit's code: what its view calls (runtime::from_generated), with the
    // Jacobians and the output matrices its directional derivatives are made of;
    // not the linear model's routines, which the unit never calls.
    driver::FrontEnd full = l->front;
    diag::Diagnostics diags;
    driver::continue_front_end(full, o.model, driver::Until::jacobians, diags, progress);
    err << diags.render();
    if (diags.has_errors() || !full.system) return 1;
    // The parameters' start values (--set applied) become the generated
    // Params' defaults, which the unit starts from.
    const std::vector<std::string> param_names = l->library->param_names();
    for (ir::Parameter& p : full.system->params) {
        const auto at = std::find(param_names.begin(), param_names.end(), p.name);
        if (at != param_names.end())
            p.value = l->params[static_cast<std::size_t>(at - param_names.begin())];
    }
    codegen::Module module = codegen::build_module(*full.system);
    using codegen::RoutineId;
    codegen::RoutineSet kept{RoutineId::rhs,
                             RoutineId::rhs_jacobian,
                             RoutineId::mass_matrix,
                             RoutineId::forcing,
                             RoutineId::jacobians,
                             RoutineId::outputs,
                             RoutineId::outputs_from_qdd,
                             RoutineId::output_matrices};
    // A model with constraints runs constrained (runtime::constrain, as sim):
    // its rows and their derivatives; its Jacobian is the constrained view's.
    if (!full.system->constraints.empty()) {
        kept = kept.without(codegen::RoutineSet{RoutineId::rhs_jacobian});
        kept.insert(codegen::constraint_routines());
    }
    // Those the model has (none of the linear model's without DOFs or with constraints).
    codegen::RoutineSet present;
    for (const codegen::Routine& r : module.routines)
        if (!r.internal && r.id) present.insert(*r.id);
    codegen::keep_routines(module, kept.both(present));
    codegen::EmitOptions emit;
    emit.header_name = "model.hpp";
    emit.compiler_version = YAMSC_VERSION;
    emit.command_line = "yamsc fmu";

    fmi::UnitLayout layout = fmi::layout_of(view, param_names, l->params);
    std::copy(q0.begin(), q0.end(), layout.initial_state.begin());
    std::copy(qd0.begin(), qd0.end(), layout.initial_state.begin() + static_cast<long>(q0.size()));
    layout.method = runtime_method(o.method);
    // The unit's default internal step, as the runtime's UnitSettings has it.
    const double step = o.step > 0 ? o.step : 1e-3;
    layout.step = step;
    layout.dof_docs =
        docs_of(layout.dof_names, [&](const std::string& n) { return doc_in(m.dofs, n); });
    layout.input_docs =
        docs_of(layout.input_names, [&](const std::string& n) { return doc_in(m.inputs, n); });
    layout.param_docs =
        docs_of(layout.param_names, [&](const std::string& n) { return doc_in(m.params, n); });
    layout.output_docs =
        docs_of(layout.output_names, [&](const std::string& n) { return doc_in(m.outputs, n); });
    const std::vector<fmi::Variable> vars = fmi::variables(layout);

    UnitSettings settings;
    settings.model_namespace = m.name;
    settings.q0 = q0;
    settings.qd0 = qd0;
    settings.method = layout.method;
    settings.step = step;
    const UnitBlocks unit = unit_blocks(m, l->view, param_names, blocks);
    settings.blocks = unit.source;
    // The token: the model, the parameters' starts and the settings.
    std::string identity = l->digest + "\n" + YAMSC_VERSION + "\n" + glue_source(settings);
    for (double p : l->params) identity += text::shortest(p) + "\n";
    settings.token = token_of(identity);

    UnitSources sources;
    sources.model = codegen::emit_cpp(module, emit);
    sources.glue = glue_source(settings);
    sources.external = o.external;
    sources.external_prototypes = driver::external_prototypes(m);
    sources.blade_elements = unit.blade_elements;
    const std::string binary = build_unit_binary(sources, compiler_of(""), progress);

    DescriptionFacts facts;
    facts.version = o.version;
    facts.model_name = m.name;
    facts.description = m.title;
    facts.token = settings.token;
    facts.generation_tool = std::string("yamsc ") + YAMSC_VERSION;
    facts.step = step;
    facts.variables = vars;
    facts.block_states = static_cast<bool>(view.update_discrete);

    std::vector<ZipEntry> entries;
    entries.push_back({"modelDescription.xml", model_description(facts)});
    entries.push_back({"binaries/", ""});
    entries.push_back({"binaries/" + platform(o.version) + "/", ""});
    entries.push_back({"binaries/" + platform(o.version) + "/" + m.name + ".so", binary, true});
    entries.push_back({"documentation/", ""});
    entries.push_back({"documentation/index.html", documentation(m, vars)});
    entries.push_back({"resources/", ""});
    std::vector<std::string> folders{"resources/"};
    for (std::size_t k = 0; k < unit.files.size(); ++k) {
        const std::string name = "resources/" + unit.names[k];
        // Each folder's entry before its first file, as a zip tool writes them.
        for (auto slash = name.find('/', 10); slash != std::string::npos;
             slash = name.find('/', slash + 1))
            if (std::find(folders.begin(), folders.end(), name.substr(0, slash + 1)) ==
                folders.end()) {
                folders.push_back(name.substr(0, slash + 1));
                entries.push_back({folders.back(), ""});
            }
        entries.push_back({name, file_bytes(unit.files[k])});
    }
    const std::string archive = zip_stored(entries);
    std::vector<std::pair<std::string, std::string>> files{{o.output, archive}};
    if (!o.depfile.empty()) {
        std::vector<std::string> read{o.model};
        read.insert(read.end(), m.files_read.begin(), m.files_read.end());
        for (const NamedFile& f : inputs)
            if (!f.path.empty() && f.path != o.model) read.push_back(f.path);
        // The AeroDyn files the primary file names, carried too.
        for (const std::string& f : unit.files)
            if (std::find(read.begin(), read.end(), f) == read.end()) read.push_back(f);
        files.emplace_back(o.depfile, driver::make_rule({o.output}, read));
    }
    runtime::write_files_atomically(files);
    out << "wrote " << o.output << " (FMI " << (o.version == FmiVersion::fmi3 ? "3.0" : "2.0")
        << ", " << vars.size() << " variables, " << archive.size() << " bytes)\n";
    return 0;
}

} // namespace yamsc::analysis
