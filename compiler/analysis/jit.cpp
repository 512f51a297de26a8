#include "analysis/jit.hpp"

#include "analysis/compiler_invocation.hpp"
#include "analysis/jit_cache.hpp"
#include "codegen/emit.hpp"
#include "codegen/module.hpp"
#include "driver/files.hpp"

#include "embedded_abi.hpp"

#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <unistd.h>

namespace yamsc::analysis {

using driver::digest;

namespace {

// -march=native: the library is built for this machine's CPU (AVX; rhs of the
// 16-DOF turbine about 7 % faster, docs/benchmarks.md); the cache key holds the
// CPU (cpu_identity), so a cache shared between machines never loads a library
// built for another CPU. -ffp-contract=off: no fused multiply-adds, so the
// numbers stay those of a plain -O2 build to the last bit (the Python module,
// `eval` and the compiled libraries of the tests agree exactly; FMA would be
// another 5-8 %).
const std::vector<std::string> compile_flags{"-std=c++17",         "-O2",     "-march=native",
                                             "-ffp-contract=off",  "-shared", "-fPIC",
                                             "-fvisibility=hidden"};

/// rhs (the loader needs it) and the others; throws std::invalid_argument for
/// a routine the C ABI does not export.
codegen::RoutineSet normalised(codegen::RoutineSet routines) {
    if (const codegen::RoutineSet outside = routines.without(codegen::abi_routines());
        !outside.empty())
        throw std::invalid_argument("the model ABI has no routine '" +
                                    codegen::routine_names(outside) + "'");
    routines.insert(codegen::RoutineId::rhs);
    return routines;
}

std::string seconds_text(double s) {
    char buf[32];
    std::snprintf(buf, sizeof buf, s < 10 ? "%.1f s" : "%.0f s", s);
    return buf;
}

/// Compiles `source` into `library` (atomically: a temporary file renamed).
void compile(const std::string& compiler, const std::string& source, const std::string& library) {
    LibraryBuild build(library);
    std::vector<std::string> arguments = compile_flags;
    arguments.push_back(build.temporary(".cpp", source));
    try {
        build.compile(compiler, arguments);
    } catch (const CompilerFailed& e) {
        throw std::runtime_error("the C++ compiler failed on the generated model (" + compiler +
                                 "):\n" + e.messages);
    }
}

} // namespace

std::string shared_model_source(const ir::System& eq, codegen::RoutineSet routines) {
    codegen::RoutineSet wanted = normalised(routines);
    // A model with constraints is constrained in every command: its rows, M and F
    // always (the runtime's constrained view solves M q'' = F + B^T lambda, B q'' +
    // gamma = 0 and projects onto the rows with them); where a command asks for a
    // Jacobian, dF/d[q, q', u] and the rows' derivatives, from which that view
    // forms its exact rhs_jacobian; never the generated rhs_jacobian.
    if (eq.constraints.empty()) {
        wanted = wanted.without(codegen::constraint_routines());
    } else {
        using codegen::RoutineId;
        const codegen::RoutineSet derivatives{RoutineId::jacobians, RoutineId::constraint_jacobians,
                                              RoutineId::mass_action_jacobian};
        const bool jacobian = !wanted.both(codegen::RoutineSet{RoutineId::rhs_jacobian}).empty() ||
                              !wanted.both(derivatives).empty();
        wanted = wanted.without(codegen::RoutineSet{RoutineId::rhs_jacobian});
        wanted.insert(codegen::constraint_routines().without(derivatives));
        wanted.insert({RoutineId::mass_matrix, RoutineId::forcing});
        if (jacobian) wanted.insert(derivatives);
    }
    codegen::Options module_options;
    module_options.linear_model = false;
    codegen::Module module = codegen::build_module(eq, module_options);
    codegen::keep_routines(module, wanted);
    codegen::EmitOptions options;
    options.compiler_version = YAMSC_VERSION;
    options.command_line = "yamsc (compiled on the fly: " + codegen::routine_names(wanted) + ")";
    std::string source = codegen::emit_cpp(module, options).source;
    source += "\n// ---- C ABI for the runtime's loader ----\n" + std::string(abi_export_text) +
              "\nYAMSC_EXPORT_MODEL_INFO(" + eq.model_name + ")\n";
    wanted.for_each([&](codegen::RoutineId r) {
        source += std::string(codegen::routine_row(r).abi_macro) + "(" + eq.model_name + ")\n";
    });
    return source;
}

std::unique_ptr<runtime::SharedModel> load_compiled_model(const ModelIdentity& id,
                                                          const std::function<ir::System()>& derive,
                                                          const JitOptions& o) {
    auto tell = [](const std::function<void(const std::string&)>& to, const std::string& s) {
        if (to) to(s);
    };
    const codegen::RoutineSet routines = normalised(id.routines);
    const std::string names = codegen::routine_names(routines);
    const std::string compiler = compiler_of(o.compiler);
    const ModelCache cache(cache_folder(o.cache_dir));
    const std::string key =
        digest(id.content_digest + (id.channels == ModelChannels::scene ? "\nscene" : "") + "\n" +
               names + "\n" + joined_words(compile_flags) + "\n" + compiler_identity(compiler) +
               "\n" + cpu_identity() + "\n" + program_identity() + "\n" + abi_export_text);
    const std::string library = cache.library_path(id.model_name, key);
    if (::access(library.c_str(), R_OK) == 0) {
        try {
            auto model = std::make_unique<runtime::SharedModel>(library);
            tell(o.progress, "using the compiled model cached in " + library);
            return model;
        } catch (const runtime::SharedModelError& e) {
            // A damaged entry is rebuilt, not fatal.
            tell(o.progress,
                 std::string("recompiling a cached model that does not load: ") + e.what());
        }
    }
    const std::string source = shared_model_source(derive(), routines);
    const CompileEstimate estimate = cache.estimate(source.size());
    char size[32];
    std::snprintf(size, sizeof size, "%.2f MB", static_cast<double>(source.size()) / 1e6);
    tell(o.notice, "compiling model '" + id.model_name + "' (" + names + "; " + size +
                       " of C++) with " + compiler + "; this usually takes about " +
                       seconds_text(estimate.seconds) +
                       (estimate.measured_here ? " here" : " (no compile timed here yet)") +
                       "; later runs load it from " + cache.folder());
    const auto start = std::chrono::steady_clock::now();
    compile(compiler, source, library);
    const double took =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    cache.record_compile(source.size(), took);
    tell(o.progress, "compiled in " + seconds_text(took));
    return std::make_unique<runtime::SharedModel>(library);
}

std::unique_ptr<runtime::SharedModel> load_compiled_model(const ir::System& eq,
                                                          const JitOptions& options) {
    const codegen::RoutineSet all = codegen::abi_routines();
    const ModelIdentity id{eq.model_name, digest(shared_model_source(eq, all)), all};
    return load_compiled_model(
        id, [&]() { return eq; }, options);
}

} // namespace yamsc::analysis
