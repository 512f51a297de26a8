#include "ir/function.hpp"

#include <array>
#include <cmath>

namespace yamsc::ir {
namespace {

constexpr std::array<FunctionInfo, function_count> table{{
    {"sin", 1},
    {"cos", 1},
    {"tan", 1},
    {"asin", 1},
    {"acos", 1},
    {"atan", 1},
    {"atan2", 2},
    {"sinh", 1},
    {"cosh", 1},
    {"tanh", 1},
    {"asinh", 1},
    {"acosh", 1},
    {"atanh", 1},
    {"exp", 1},
    {"log", 1},
    {"abs", 1},
    {"sqrt", 1},
    {"pow", 2},
}};

} // namespace

const FunctionInfo& info(Function f) {
    return table[static_cast<std::size_t>(f)];
}

std::optional<Function> model_function(std::string_view name, std::size_t arity) {
    for (int i = 0; i < function_count; ++i) {
        const auto f = static_cast<Function>(i);
        if (f == Function::sqrt || f == Function::pow) continue;
        if (table[static_cast<std::size_t>(i)].name == name &&
            table[static_cast<std::size_t>(i)].arity == arity)
            return f;
    }
    return std::nullopt;
}

double evaluate(Function f, double x, double y) {
    switch (f) {
    case Function::sin:
        return std::sin(x);
    case Function::cos:
        return std::cos(x);
    case Function::tan:
        return std::tan(x);
    case Function::asin:
        return std::asin(x);
    case Function::acos:
        return std::acos(x);
    case Function::atan:
        return std::atan(x);
    case Function::atan2:
        return std::atan2(x, y);
    case Function::sinh:
        return std::sinh(x);
    case Function::cosh:
        return std::cosh(x);
    case Function::tanh:
        return std::tanh(x);
    case Function::asinh:
        return std::asinh(x);
    case Function::acosh:
        return std::acosh(x);
    case Function::atanh:
        return std::atanh(x);
    case Function::exp:
        return std::exp(x);
    case Function::log:
        return std::log(x);
    case Function::abs:
        return std::fabs(x);
    case Function::sqrt:
        return std::sqrt(x);
    case Function::pow:
        return std::pow(x, y);
    }
    return std::nan("");
}

} // namespace yamsc::ir
