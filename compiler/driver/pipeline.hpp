#pragma once
// The compiler's stages chained: source -> AST -> checked model -> equations
// (GiNaC) -> ir::System with its derivatives (the passes).
// Each stage reports into one Diagnostics; the chain stops after the first stage
// that reported an error.
#include "ast/ast.hpp"
#include "ir/system.hpp"
#include "model/model.hpp"
#include "symbolic/equations.hpp"

#include <functional>

namespace yamsc::driver {

struct FrontEnd {
    std::shared_ptr<const diag::SourceFile> source;
    std::optional<ast::ModelFile> ast;
    std::optional<model::Model> model;
    std::optional<symbolic::Equations> equations;
    std::optional<ir::System> system; // Until::jacobians: the equations in the IR, derived
};

enum class Until { ast, model, equations, jacobians };

/// How the derivatives are formed (docs/benchmarks.md): `unrolled`, M and
/// every Jacobian entry as its own expression (fastest code for small models);
/// `tangent`, M a and one directional derivative, evaluated column by column
/// in generated loops (code and compile time O(n²) instead of O(n³) for an
/// n-body chain); `automatic`: tangent from `tangent_form_min_dofs` DOFs on,
/// unless the model has `approx` (which works on M itself).
enum class Derivatives { automatic, unrolled, tangent };
inline constexpr std::size_t tangent_form_min_dofs = 25;

/// Runs the stages up to `until`. `progress` (may be empty) receives a line per stage.
FrontEnd run_front_end(const std::string& path, Until until, diag::Diagnostics& diags,
                       const std::function<void(const std::string&)>& progress = {},
                       Derivatives derivatives = Derivatives::automatic);

} // namespace yamsc::driver
