#pragma once
// The language-neutral module: everything the generated code computes, routine
// by routine, with the shared work made explicit (named temporaries computed
// once, local arrays, the factorisation of M and the solves with it). Emitters
// only print a Module; `yamsc --dump=module` prints it with dump().
#include "codegen/routines.hpp"
#include "codegen/sparse_ldlt.hpp"
#include "ir/graph.hpp"
#include "ir/system.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace yamsc::codegen {

// Code generation reads the IR; these are its names here.
using ir::Function;
using ir::function_count;
using ir::Graph;
using ir::Node;
using ir::NodeId;
using ir::NodeKind;
using ir::Operand;
using ir::OperandSpan;
using ir::symbol_kind_count;
using ir::SymbolKind;
using ir::SymbolRef;

struct Options {
    /// The largest integer exponent written as repeated multiplication (x*x*x);
    /// other exponents call pow (sqrt for 1/2).
    int max_multiplied_power = 4;
    /// A single-use expression nested deeper than this still gets a temporary,
    /// so that printed expressions (and compilers) never nest without bound.
    int max_inline_depth = 32;
    /// Emit the linear model's routines (linear, state_space, output_matrices).
    /// A model compiled only to be simulated can leave them out: they about
    /// double what the C++ compiler has to digest.
    bool linear_model = true;
    /// Parameters (by name) whose derivatives d(M0, C0, K0)/dp the routine
    /// `linear_sensitivities` computes; empty: no such routine.
    std::vector<std::string> sensitivity_params;
};

enum class ExprKind : std::uint8_t {
    number, // a literal
    load,   // array[index]: an argument, a local array or an output already written
    param,  // a parameter, by index
    time,   // t
    add,    // value + sum(weight * operand)
    mul,    // value * prod(operand ^ weight), integer weights
    call,   // function(operands...)
};

struct ExprOperand {
    int expr = 0; // index into Routine::exprs, always lower than the user's
    double weight = 1.0;
};

/// One node of a routine's expression DAG. Every node that is not a leaf is
/// printed exactly once: as the definition of its temporary, or inline in its
/// only user.
struct Expr {
    ExprKind kind = ExprKind::number;
    double value = 0.0;                // number: the value; add: constant; mul: coefficient
    std::string array;                 // load
    int index = 0;                     // load: element; param: parameter index
    Function function = Function::sin; // call
    std::vector<ExprOperand> operands;
    int temporary = -1; // >= 0: computed once into the temporary t<temporary>
};

bool is_leaf(const Expr& e);

/// array[index] = exprs[expr]
struct Assignment {
    std::string array;
    int index = 0;
    int expr = 0;
};

enum class StepKind {
    evaluate, // define `temporaries` (in order), then perform `assignments`
    factor,   // LDL^T-factorise the n x n local `matrix` (M) in place (lower triangle read)
    solve,    // target + offset, an n x columns row-major block, := matrix^-1 * itself
    sweep,    // a loop calling an internal routine once per unit direction (Sweep)
    call,     // one call of an internal routine (Call), e.g. the prologue of sweeps
};

/// callee(arguments...): the caller's spelling of every argument, outputs included.
struct Call {
    std::string callee;
    std::vector<std::string> arguments;
};

/// Column k < count of a matrix from an internal routine (the tangent form,
/// docs/benchmarks.md): the callee is called with the unit direction
/// e_(first + k) (of seed_size values) as its argument `seed_argument` and a
/// scratch array of result_size values as its last argument (its only output);
/// then target[offset + i * stride + k] = scale * result[result_first + i]
/// for i < rows.
struct Sweep {
    std::string callee;
    /// The caller's spelling of each callee argument but the last (the entry at
    /// seed_argument is ignored): "t", "x + 2", "p", "0.0".
    std::vector<std::string> arguments;
    int seed_argument = 0;
    int seed_size = 0, first = 0, count = 0;
    int result_size = 0, result_first = 0, rows = 0;
    std::string target;
    int offset = 0, stride = 0;
    double scale = 1.0;
};

struct Step {
    StepKind kind = StepKind::evaluate;
    std::vector<int> temporaries;
    std::vector<Assignment> assignments;
    std::string matrix;
    int n = 0;
    std::string target;
    int offset = 0;
    int columns = 0;
    Sweep sweep; // StepKind::sweep
    Call call;   // StepKind::call
};

enum class ArgumentKind { scalar, input_array, params, output_array };

struct Argument {
    std::string name;
    ArgumentKind kind = ArgumentKind::scalar;
    bool used = false; // unused arguments are cast to void in the generated code
};

struct LocalArray {
    std::string name;
    int size = 0;
};

struct Routine {
    std::string name; // mass_matrix, forcing, jacobians, outputs, rhs, rhs_jacobian, linear, ...
    /// Which function of the API it is (routines.hpp); none for internal helpers.
    std::optional<RoutineId> id;
    std::string summary;
    /// A helper of the tangent form, called by sweeps: file-local in the
    /// generated code, defined before its callers, not part of the API.
    bool internal = false;
    std::vector<Argument> arguments;
    std::vector<LocalArray> locals;
    std::vector<Expr> exprs;
    std::vector<Step> steps;
    int temporary_count = 0;

    const Argument* argument(std::string_view name) const;
};

struct NamedDoc {
    std::string name;
    std::string doc;
};

struct ParamInfo {
    std::string name;
    std::string doc;
    std::optional<double> default_value; // none: must be set at run time
};

/// One row of the model's constraints (ir::ConstraintRow without its expressions).
struct ConstraintInfo {
    std::string name;
    bool holonomic = true;
    int dependent = -1;
    std::string source;
};

struct ModelInfo {
    std::string name;
    std::string title;
    std::string source_path;
    std::string source_digest;
    std::vector<NamedDoc> dofs;
    std::vector<NamedDoc> inputs; // name as written (theta_p''), doc
    std::vector<ParamInfo> params;
    std::vector<NamedDoc> outputs;
    std::vector<ConstraintInfo> constraints; // the nh holonomic rows first

    int nq() const { return static_cast<int>(dofs.size()); }
    int nc() const { return static_cast<int>(constraints.size()); }
    int nh() const {
        int n = 0;
        for (const ConstraintInfo& c : constraints) n += c.holonomic ? 1 : 0;
        return n;
    }
    int nu() const { return static_cast<int>(inputs.size()); }
    int np() const { return static_cast<int>(params.size()); }
    int ny() const { return static_cast<int>(outputs.size()); }
};

/// An external function (ir::External): what the emitters need to call it.
struct ExternalInfo {
    std::string name, what, location;
    int first_input = 0; // its first result's channel in the routines' u
    int results = 0;
    int args = 0;
    bool user_jacobian = true;
};

struct Module {
    ModelInfo model; // with externals: the declared inputs only
    /// With externals, the routines read u of channels() entries, the declared
    /// ones then every external's results; the emitters wrap them
    /// (codegen/external_wrappers.hpp) into the API, whose u is the declared one.
    std::vector<ExternalInfo> externals;
    int channels() const {
        int n = model.nu();
        for (const ExternalInfo& e : externals) n += e.results;
        return n;
    }
    Options options;
    /// M depends on q and the parameters only: `mass_matrix(q, p, M)` exists
    /// besides the full `mass_matrix(t, q, u, p, M)`.
    bool mass_matrix_short_form = false;
    /// The symbolic LDL^T of M (codegen/sparse_ldlt.hpp) that the factor and
    /// solve steps of its size print; n = 0: none, every step calls the loops.
    LdltPlan mass_ldlt;
    std::vector<Routine> routines;

    /// The routine of that name; throws diag::InternalError if there is none.
    const Routine& routine(std::string_view name) const;
    /// The public routine `id`; throws diag::InternalError if there is none.
    const Routine& routine(RoutineId id) const;
};

/// Lowers the System `s` to a module: mass_matrix, forcing, jacobians,
/// outputs_from_qdd, outputs (codegen/output_routines.hpp), rhs, rhs_jacobian
/// and the linear model's linear, state_space and output_matrices
/// (codegen/linear_routines.hpp; add_operating_point adds operating_point).
/// The passes each routine reads (its row of routines.hpp) must have run, as
/// the System records them: passes::derive_jacobians and output_jacobians (or
/// derive_tangent), and parameter_derivatives for options.sensitivity_params.
/// Linear in the size of the System's graph. Throws diag::InternalError when the
/// System is malformed (wrong shapes, missing derivatives) or holds something
/// generated code cannot express.
Module build_module(const ir::System& s, const Options& options = {});

/// Keeps the public routines of `wanted` (in the module's order) and the
/// internal routines they call; drops every other. For a module compiled for
/// one use only (the JIT): the C emitter's rk4_step needs rhs. Throws
/// diag::InternalError for a routine the module does not have.
void keep_routines(Module& module, RoutineSet wanted);

/// A readable, deterministic listing of the module (for `yamsc --dump=module`).
std::string dump(const Module& module);

} // namespace yamsc::codegen
