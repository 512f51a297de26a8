#pragma once
// The compiler's stages chained: source -> AST -> checked model -> equations
// (GiNaC, in the derivation module: derivation/derivation.hpp) -> ir::System
// with its derivatives (the passes).
// Each stage reports into one Diagnostics; the chain stops after the first stage
// that reported an error.
#include "ast/ast.hpp"
#include "driver/commands.hpp"
#include "ir/system.hpp"
#include "model/model.hpp"

#include <functional>

namespace yamsc::driver {

struct FrontEnd {
    std::shared_ptr<const diag::SourceFile> source;
    std::optional<ast::ModelFile> ast;
    std::optional<model::Model> model;
    // Until::system: the equations in the IR, approximated (`approx`);
    // Until::jacobians: with their derivatives (the passes) as well.
    std::optional<ir::System> system;
};

enum class Until { ast, model, system, jacobians };

/// What the passes derive at Until::jacobians: the form of the Jacobians, and
/// the parameters (by name) whose derivatives of the linear model are derived
/// too (--sensitivities).
struct DerivativeRequest {
    DerivativeRequest(Derivatives f = Derivatives::automatic, std::vector<std::string> p = {})
        : form(f), sensitivities(std::move(p)) {}
    Derivatives form;
    std::vector<std::string> sensitivities;
};

/// Runs the stages up to `until`. `progress` (may be empty) receives a line per stage.
/// `checked` (may be empty) sees the checked model before the equations are
/// derived: the data files it read are known there, and an exception from it
/// stops the run before the expensive stages.
FrontEnd run_front_end(const std::string& path, Until until, diag::Diagnostics& diags,
                       const std::function<void(const std::string&)>& progress = {},
                       const DerivativeRequest& derivatives = {},
                       const std::function<void(const model::Model&)>& checked = {});

/// Runs the stages after the checker up to `until` on a FrontEnd that stopped at
/// Until::model (the JIT checks its cache in between: a hit derives nothing).
void continue_front_end(FrontEnd& fe, const std::string& path, Until until,
                        diag::Diagnostics& diags,
                        const std::function<void(const std::string&)>& progress = {},
                        const DerivativeRequest& derivatives = {});

/// Whether the derivatives of `m` up to `until` take the tangent form (no M is
/// derived then). Throws diag::UsageError for a combination that cannot be.
bool uses_tangent_form(const model::Model& m, Until until, Derivatives derivatives);

/// The stages after the derivation: the externals' channels, `approx`, and up to
/// Until::jacobians the derivatives, on `fe.system` (derived with M unless
/// `tangent`), and the derivatives of the linear model with respect to the
/// parameters named in `sensitivities` (passes/pipeline.hpp runs them all).
/// continue_front_end ends with it; tests that derive in-process (to keep the
/// GiNaC equations) call it too. `seconds_so_far` starts its clock. Throws
/// diag::UsageError for a name in `sensitivities` that is not a parameter.
void finish_front_end(FrontEnd& fe, Until until, bool tangent, diag::Diagnostics& diags,
                      const std::function<void(const std::string&)>& progress = {},
                      double seconds_so_far = 0.0,
                      const std::vector<std::string>& sensitivities = {});

/// The C prototypes of the model's external functions, as the generated code
/// declares them (codegen::external_prototypes); "" without any. The user's
/// source given as `--external file.c` is compiled against them.
std::string external_prototypes(const model::Model& m);

/// The digest of a model by content: its text and every data file it read, in
/// order (not their paths). Generated code records it; the JIT's cache keys on it.
std::string content_digest(const diag::SourceFile& source, const model::Model& m);

} // namespace yamsc::driver
