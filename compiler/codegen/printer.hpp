#pragma once
// The expression printer for C-like languages: prints a routine's expressions
// with minimal but correct parentheses, differences as `a - b`, small integer
// powers as multiplications, and counts the operations it writes.
#include "codegen/module.hpp"
#include "codegen/syntax.hpp"

#include <string>
#include <utility>
#include <vector>

namespace yamsc::codegen {

struct OperationCount {
    long adds = 0; // additions and subtractions
    long muls = 0;
    long divs = 0;
    long calls = 0; // elementary functions, sqrt and pow

    OperationCount& operator+=(const OperationCount& o);
};

/// The operations of the generic LDL^T loops for an n x n system
/// (helpers/ldlt.inc; the straight-line code counts its own, ldlt_text.hpp).
OperationCount ldlt_factor_count(int n);
OperationCount ldlt_solve_count(int n, int columns);

class ExprPrinter {
public:
    ExprPrinter(const Routine& routine, const ModelInfo& model, const Syntax& syntax);

    /// How temporaries are spelt, by number (default: t<k>).
    void set_temporary_names(std::vector<std::string> names) { names_ = std::move(names); }
    const std::string& temporary(int number) const { return names_[number]; }

    /// How a user reads the value of exprs[expr]: the temporary's name, a leaf, or
    /// (for a single-use expression) its inline text.
    std::string reference(int expr);
    /// The value of a temporary, to initialise it with.
    std::string definition(int expr);
    static std::string temporary_name(int number);

    /// The operations printed so far.
    const OperationCount& count() const { return count_; }

private:
    struct Text {
        std::string text;
        int precedence;
    };
    Text inline_text(int expr);
    std::string operand(int expr, int min_precedence);
    Text sum(const Expr& e);
    void flatten(const Expr& e, double scale, std::vector<ExprOperand>& terms,
                 std::vector<double>& constants) const;
    const Expr* negated_sum(const Expr& e) const;
    Text product(const std::vector<ExprOperand>& factors, double coefficient);
    Text call(const Expr& e);

    const Routine& routine_;
    const ModelInfo& model_;
    const Syntax& syntax_;
    std::vector<std::string> names_;
    OperationCount count_;
};

} // namespace yamsc::codegen
