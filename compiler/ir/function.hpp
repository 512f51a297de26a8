#pragma once
// The elementary functions of the intermediate representation, defined once
// for every stage: the import from GiNaC names them, the derivative passes
// know their rules, the evaluator their values and the printers their
// spellings (codegen/syntax.cpp, indexed by this enum).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace yamsc::ir {

/// `sqrt` and `pow` come from non-integer powers; the rest from the model's own
/// functions (in the order of the model language's function table).
enum class Function : std::uint8_t {
    sin,
    cos,
    tan,
    asin,
    acos,
    atan,
    atan2,
    sinh,
    cosh,
    tanh,
    asinh,
    acosh,
    atanh,
    exp,
    log,
    abs,
    sqrt,
    pow,
};
inline constexpr int function_count = 18;

struct FunctionInfo {
    std::string_view name; // as GiNaC and the C library spell it (fabs aside)
    std::size_t arity;
};

const FunctionInfo& info(Function f);

/// The function a model's expression calls by `name` with `arity` arguments;
/// nullopt for anything else (sqrt and pow included: those are powers).
std::optional<Function> model_function(std::string_view name, std::size_t arity);

/// f(x), or f(x, y) for atan2 and pow, as generated code computes it.
double evaluate(Function f, double x, double y = 0.0);

} // namespace yamsc::ir
