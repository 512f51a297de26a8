#pragma once
// The state the grammar actions fill while parsing one `.mbd` file: the AST being built, a stack
// of finished sub-expressions, the pieces of the statement in progress, and the bookkeeping for
// error messages (open brackets, nesting depth) and recovery.
#include "ast/ast.hpp"
#include "diag/diagnostics.hpp"

#include <tao/pegtl/parse_error.hpp>
#include <tao/pegtl/position.hpp>

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace yamsc::parse {

/// Limits that turn hostile or absurd input into a `Limit` diagnostic instead of exhausting the
/// stack or memory.
struct Limits {
    static constexpr std::size_t max_source_bytes = 16u << 20;
    static constexpr int max_lines = 1'000'000;
    static constexpr int max_nesting = 200;           // brackets, signs, powers inside each other
    static constexpr int max_expression_depth = 1000; // depth of one expression tree
    static constexpr std::size_t max_list_length = 10'000; // elements of one vector, call, table
    static constexpr std::size_t max_expression_nodes = 1'000'000; // in the whole file
    static constexpr int max_errors = 50;
};

/// A syntax or limit error at a position; thrown by the control and the actions, caught where
/// parsing can resume (a statement or a block item).
class syntax_error : public tao::pegtl::parse_error {
public:
    syntax_error(const std::string& message, const tao::pegtl::position& where,
                 diag::Kind kind = diag::Kind::Syntax, bool resume_here = false, bool fatal = false)
        : tao::pegtl::parse_error(message, where), kind(kind), resume_here(resume_here),
          fatal(fatal) {}

    diag::Kind kind;
    /// True if parsing should resume exactly at the error instead of skipping to the next line
    /// (a block that was not closed before the next statement).
    bool resume_here;
    /// True if parsing cannot usefully go on (a limit of the whole file was reached).
    bool fatal;
};

/// `"L:C"`, for messages that refer to another place in the file.
std::string line_col(const ast::Loc& loc);

class ParseState {
public:
    ParseState(std::shared_ptr<const diag::SourceFile> source, diag::Diagnostics& diags);

    ast::Loc loc(const tao::pegtl::position& where) const;

    // ---- expressions: a stack of finished sub-expressions with their tree depth
    void push_leaf(ast::Expr::Kind kind, std::string text, const tao::pegtl::position& where);
    /// Replaces the top with `kind(top)`, e.g. neg, deg, component (with `text`).
    void wrap_top(ast::Expr::Kind kind, const tao::pegtl::position& where, std::string text = {});
    /// Replaces the two top entries a, b with `kind(a, b)`.
    void combine_top(ast::Expr::Kind kind, const tao::pegtl::position& where);
    ast::Expr& top();
    ast::Expr pop();
    std::size_t stack_size() const { return exprs_.size(); }
    /// Starts a bracketed list (call arguments, vector elements) at the current stack height.
    void open_list();
    /// The elements pushed since the matching open_list(), in order.
    std::vector<ast::Expr> close_list(const tao::pegtl::position& where);
    /// Turns the elements of a `(...)` group into one expression: itself if single, else a vector.
    void finish_group(const tao::pegtl::position& where);
    /// Turns `name` and the arguments after it into a call.
    void finish_call(const tao::pegtl::position& where);

    // ---- pieces of the statement in progress
    std::string string_value;            // the last string literal, unescaped
    ast::Property property;              // the property being parsed
    std::vector<ast::ModeEntry> entries; // the last list of modes or `free` DOFs
    ast::Loc list_loc;                   // where that list started
    std::vector<ast::TablePoint> table;  // the last table
    ast::Axis axis;                      // the last joint axis
    /// Where `key = value` lines of the current block go (body or beam properties).
    std::vector<std::vector<ast::Property>*> property_sinks;
    /// Where `name = value` lines of the current `linearize` or `initial` block go.
    std::vector<ast::Assignment>* assignments = nullptr;

    /// Declarations of the current statement that a trailing `# comment` documents. Indices,
    /// not pointers: the vectors grow while the statement declares more names.
    enum class DocKind { param, input, dof, output, point };
    struct DocTarget {
        DocKind kind;
        std::size_t index;
    };
    std::vector<DocTarget> doc_targets;
    void document(const std::string& doc);

    /// Positions of the brackets and blocks open around the parse position (for messages).
    std::vector<ast::Loc> open_brackets;
    int nesting = 0;

    // ---- error recovery
    struct Checkpoint {
        std::size_t exprs, lists, brackets, sinks;
        int nesting;
    };
    Checkpoint checkpoint() const;
    /// Forgets what a failed statement left half-built.
    void rollback(const Checkpoint& c);
    /// Records a caught error; false once the error limit is reached (stop parsing).
    bool report(const tao::pegtl::parse_error& error);
    bool stopped() const { return stopped_; }

    [[noreturn]] void fail(const std::string& message, const tao::pegtl::position& where,
                           diag::Kind kind = diag::Kind::Syntax, bool fatal = false) const;

    std::shared_ptr<const diag::SourceFile> source;
    diag::Diagnostics& diags;
    ast::ModelFile file;

private:
    struct Entry {
        ast::Expr expr;
        int depth;
    };
    void push(ast::Expr e, int depth, const tao::pegtl::position& where);

    std::vector<Entry> exprs_;
    std::vector<std::size_t> list_starts_;
    std::size_t nodes_ = 0;
    int reported_ = 0;
    bool stopped_ = false;
};

} // namespace yamsc::parse
