#include "codegen/printer.hpp"

#include "diag/diagnostics.hpp"

#include <cmath>

namespace yamsc::codegen {
namespace {

// C precedence levels, loosest first.
constexpr int additive = 1;
constexpr int multiplicative = 2;
constexpr int unary = 3;
constexpr int atom = 4;

std::string join(const std::vector<std::string>& parts, const char* separator) {
    std::string out;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        if (i > 0) out += separator;
        out += parts[i];
    }
    return out;
}

} // namespace

OperationCount& OperationCount::operator+=(const OperationCount& o) {
    adds += o.adds;
    muls += o.muls;
    divs += o.divs;
    calls += o.calls;
    return *this;
}

OperationCount ldlt_factor_count(int n) {
    OperationCount c;
    for (int j = 0; j < n; ++j) {
        c.adds += j;
        c.muls += 2L * j;
        for (int i = j + 1; i < n; ++i) {
            c.adds += j;
            c.muls += 2L * j;
            c.divs += 1;
        }
    }
    return c;
}

OperationCount ldlt_solve_count(int n, int columns) {
    OperationCount c;
    const long triangle = static_cast<long>(n) * (n - 1) / 2; // forward, then backward
    c.adds = columns * 2 * triangle;
    c.muls = columns * 2 * triangle;
    c.divs = static_cast<long>(columns) * n;
    return c;
}

ExprPrinter::ExprPrinter(const Routine& routine, const ModelInfo& model, const Syntax& syntax)
    : routine_(routine), model_(model), syntax_(syntax) {
    for (int k = 0; k < routine.temporary_count; ++k) names_.push_back(temporary_name(k));
}

std::string ExprPrinter::temporary_name(int number) {
    return "t" + std::to_string(number);
}

std::string ExprPrinter::reference(int expr) {
    const Expr& e = routine_.exprs[static_cast<std::size_t>(expr)];
    if (e.temporary >= 0) return names_[e.temporary];
    return inline_text(expr).text;
}

std::string ExprPrinter::definition(int expr) {
    return inline_text(expr).text;
}

std::string ExprPrinter::operand(int expr, int min_precedence) {
    const Expr& e = routine_.exprs[static_cast<std::size_t>(expr)];
    if (e.temporary >= 0) return names_[e.temporary];
    Text t = inline_text(expr);
    if (t.precedence < min_precedence) return "(" + t.text + ")";
    return t.text;
}

// The sum s when `e` is an inline -1 * s with s an inline sum (how the graph
// keeps a sum's first term positive), so that it prints as `-a + b`, not -(a - b).
const Expr* ExprPrinter::negated_sum(const Expr& e) const {
    if (e.kind != ExprKind::mul || e.temporary >= 0 || e.value != -1.0 || e.operands.size() != 1 ||
        e.operands[0].weight != 1.0)
        return nullptr;
    const Expr& sum = routine_.exprs[static_cast<std::size_t>(e.operands[0].expr)];
    return sum.kind == ExprKind::add && sum.temporary < 0 ? &sum : nullptr;
}

ExprPrinter::Text ExprPrinter::inline_text(int expr) {
    const Expr& e = routine_.exprs[static_cast<std::size_t>(expr)];
    if (const Expr* sum = negated_sum(e)) {
        Expr negated = *sum;
        for (ExprOperand& op : negated.operands) op.weight = -op.weight;
        negated.value = -negated.value;
        return this->sum(negated);
    }
    switch (e.kind) {
    case ExprKind::number:
        return {format_literal(e.value, syntax_), e.value < 0.0 ? unary : atom};
    case ExprKind::load:
        return {e.array + "[" + std::to_string(e.index) + "]", atom};
    case ExprKind::param:
        return {syntax_.param_access + model_.params.at(static_cast<std::size_t>(e.index)).name,
                atom};
    case ExprKind::time:
        return {"t", atom};
    case ExprKind::add:
        return sum(e);
    case ExprKind::mul:
        return product(e.operands, e.value);
    case ExprKind::call:
        return call(e);
    }
    throw diag::InternalError("code generation: unknown expression kind");
}

ExprPrinter::Text ExprPrinter::call(const Expr& e) {
    ++count_.calls;
    std::vector<std::string> args;
    for (const ExprOperand& op : e.operands) args.push_back(operand(op.expr, 0));
    return {syntax_.functions[static_cast<std::size_t>(e.function)] + "(" + join(args, ", ") + ")",
            atom};
}

// coefficient * factors, numerator first: `c*a*b*b/(d*e)`; `-` leads a negative one.
ExprPrinter::Text ExprPrinter::product(const std::vector<ExprOperand>& factors,
                                       double coefficient) {
    std::vector<std::string> numerator;
    std::vector<std::string> denominator;
    const double magnitude = std::fabs(coefficient);
    if (magnitude != 1.0) numerator.push_back(format_literal(magnitude, syntax_));
    for (const ExprOperand& f : factors) {
        const std::string text = operand(f.expr, unary);
        const long repeat = std::lround(std::fabs(f.weight));
        for (long k = 0; k < repeat; ++k) (f.weight > 0 ? numerator : denominator).push_back(text);
    }
    if (numerator.size() > 1) count_.muls += static_cast<long>(numerator.size()) - 1;
    if (denominator.size() > 1) count_.muls += static_cast<long>(denominator.size()) - 1;
    std::string text = numerator.empty() ? format_literal(1.0, syntax_) : join(numerator, "*");
    if (!denominator.empty()) {
        ++count_.divs;
        text += "/";
        text += denominator.size() == 1 ? denominator[0] : "(" + join(denominator, "*") + ")";
    }
    if (coefficient < 0.0) text = "-" + text;
    return {text, multiplicative};
}

// The terms of a sum, with the terms of single-use sums of weight +-1 spliced
// in (so that `a + (b - c)` prints as `a + b - c`), and its constants.
void ExprPrinter::flatten(const Expr& e, double scale, std::vector<ExprOperand>& terms,
                          std::vector<double>& constants) const {
    for (const ExprOperand& op : e.operands) {
        const Expr& child = routine_.exprs[static_cast<std::size_t>(op.expr)];
        const double weight = scale * op.weight;
        if (child.kind == ExprKind::add && child.temporary < 0 && std::fabs(weight) == 1.0)
            flatten(child, weight, terms, constants);
        else if (const Expr* sum = negated_sum(child); sum && std::fabs(weight) == 1.0)
            flatten(*sum, -weight, terms, constants);
        else
            terms.push_back({op.expr, weight});
    }
    if (e.value != 0.0) constants.push_back(scale * e.value);
}

// Terms with a positive weight first, then `- term` for the negative ones; the
// constants last. A single-use product carries its coefficient's sign into the
// term: `a - 2.0*b*c`.
ExprPrinter::Text ExprPrinter::sum(const Expr& e) {
    std::vector<ExprOperand> terms;
    std::vector<double> constants;
    flatten(e, 1.0, terms, constants);
    auto inline_product = [this](const ExprOperand& op) -> const Expr* {
        const Expr& child = routine_.exprs[static_cast<std::size_t>(op.expr)];
        return child.kind == ExprKind::mul && child.temporary < 0 ? &child : nullptr;
    };
    auto sign_of = [&](const ExprOperand& op) {
        const Expr* product = inline_product(op);
        return product ? op.weight * product->value : op.weight;
    };
    auto magnitude_text = [&](const ExprOperand& op) {
        if (const Expr* product = inline_product(op))
            return this->product(product->operands, std::fabs(op.weight * product->value)).text;
        const double magnitude = std::fabs(op.weight);
        if (magnitude == 1.0) return operand(op.expr, multiplicative);
        ++count_.muls;
        return format_literal(magnitude, syntax_) + "*" + operand(op.expr, unary);
    };
    std::vector<std::pair<bool, std::string>> printed; // (negative, magnitude's text)
    for (const bool negative : {false, true})
        for (const ExprOperand& op : terms)
            if ((sign_of(op) < 0.0) == negative) printed.emplace_back(negative, magnitude_text(op));
    for (const double c : constants)
        printed.emplace_back(c < 0.0, format_literal(std::fabs(c), syntax_));
    count_.adds += static_cast<long>(printed.size()) - 1;
    std::string text;
    for (std::size_t i = 0; i < printed.size(); ++i) {
        const auto& [negative, t] = printed[i];
        if (i == 0)
            text = negative ? "-" + t : t;
        else
            text += (negative ? " - " : " + ") + t;
    }
    return {text, additive};
}

} // namespace yamsc::codegen
