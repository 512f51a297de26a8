#include "parse/parse_state.hpp"

#include <algorithm>
#include <utility>

namespace yamsc::parse {

std::string line_col(const ast::Loc& loc) {
    return std::to_string(loc.line) + ":" + std::to_string(loc.col);
}

ParseState::ParseState(std::shared_ptr<const diag::SourceFile> src, diag::Diagnostics& d)
    : source(std::move(src)), diags(d) {
    file.source = source;
}

ast::Loc ParseState::loc(const tao::pegtl::position& where) const {
    return ast::Loc{source, static_cast<int>(where.line), static_cast<int>(where.column)};
}

void ParseState::fail(const std::string& message, const tao::pegtl::position& where,
                      diag::Kind kind, bool fatal) const {
    throw syntax_error(message, where, kind, false, fatal);
}

void ParseState::push(ast::Expr e, int depth, const tao::pegtl::position& where) {
    if (depth > Limits::max_expression_depth) {
        fail("expression is nested too deeply (more than " +
                 std::to_string(Limits::max_expression_depth) +
                 " levels of operations); split it with parameters or outputs",
             where, diag::Kind::Limit);
    }
    if (++nodes_ > Limits::max_expression_nodes) {
        fail("the model has too many expressions (more than " +
                 std::to_string(Limits::max_expression_nodes) + " terms)",
             where, diag::Kind::Limit, true);
    }
    exprs_.push_back(Entry{std::move(e), depth});
}

void ParseState::push_leaf(ast::Expr::Kind kind, std::string text,
                           const tao::pegtl::position& where) {
    ast::Expr e;
    e.kind = kind;
    e.loc = loc(where);
    e.text = std::move(text);
    push(std::move(e), 1, where);
}

void ParseState::wrap_top(ast::Expr::Kind kind, const tao::pegtl::position& where,
                          std::string text) {
    Entry operand = std::move(exprs_.back());
    exprs_.pop_back();
    ast::Expr e;
    e.kind = kind;
    e.loc = loc(where);
    e.text = std::move(text);
    e.args.push_back(std::move(operand.expr));
    push(std::move(e), operand.depth + 1, where);
}

void ParseState::combine_top(ast::Expr::Kind kind, const tao::pegtl::position& where) {
    Entry right = std::move(exprs_.back());
    exprs_.pop_back();
    Entry left = std::move(exprs_.back());
    exprs_.pop_back();
    ast::Expr e;
    e.kind = kind;
    e.loc = loc(where);
    e.args.push_back(std::move(left.expr));
    e.args.push_back(std::move(right.expr));
    push(std::move(e), std::max(left.depth, right.depth) + 1, where);
}

ast::Expr& ParseState::top() {
    return exprs_.back().expr;
}

ast::Expr ParseState::pop() {
    ast::Expr e = std::move(exprs_.back().expr);
    exprs_.pop_back();
    return e;
}

void ParseState::open_list() {
    list_starts_.push_back(exprs_.size());
}

std::vector<ast::Expr> ParseState::close_list(const tao::pegtl::position& where) {
    const std::size_t start = list_starts_.back();
    list_starts_.pop_back();
    if (exprs_.size() - start > Limits::max_list_length) {
        fail("list has more than " + std::to_string(Limits::max_list_length) + " elements", where,
             diag::Kind::Limit);
    }
    std::vector<ast::Expr> elements;
    elements.reserve(exprs_.size() - start);
    for (std::size_t i = start; i < exprs_.size(); ++i)
        elements.push_back(std::move(exprs_[i].expr));
    exprs_.resize(start);
    return elements;
}

void ParseState::finish_group(const tao::pegtl::position& where) {
    const std::size_t start = list_starts_.back();
    if (exprs_.size() - start == 1) { // `(a)` is just a
        list_starts_.pop_back();
        return;
    }
    int depth = 0;
    for (std::size_t i = start; i < exprs_.size(); ++i) depth = std::max(depth, exprs_[i].depth);
    ast::Expr v;
    v.kind = ast::Expr::Kind::vector;
    v.loc = loc(where);
    v.args = close_list(where);
    push(std::move(v), depth + 1, where);
}

void ParseState::finish_call(const tao::pegtl::position& where) {
    const std::size_t start = list_starts_.back();
    int depth = 0;
    for (std::size_t i = start; i < exprs_.size(); ++i) depth = std::max(depth, exprs_[i].depth);
    std::vector<ast::Expr> args = close_list(where);
    ast::Expr& call = exprs_.back().expr; // the function's name, pushed before `(`
    call.kind = ast::Expr::Kind::call;
    call.args = std::move(args);
    exprs_.back().depth = depth + 1;
}

void ParseState::document(const std::string& doc) {
    for (const DocTarget& target : doc_targets) {
        switch (target.kind) {
        case DocKind::param:
            file.params.at(target.index).id.doc = doc;
            break;
        case DocKind::input:
            file.inputs.at(target.index).id.doc = doc;
            break;
        case DocKind::dof:
            file.dofs.at(target.index).doc = doc;
            break;
        case DocKind::output:
            file.outputs.at(target.index).id.doc = doc;
            break;
        case DocKind::point:
            file.points.at(target.index).id.doc = doc;
            break;
        }
    }
    doc_targets.clear();
}

ParseState::Checkpoint ParseState::checkpoint() const {
    return Checkpoint{exprs_.size(), list_starts_.size(), open_brackets.size(),
                      property_sinks.size(), nesting};
}

void ParseState::rollback(const Checkpoint& c) {
    exprs_.resize(std::min(exprs_.size(), c.exprs));
    list_starts_.resize(std::min(list_starts_.size(), c.lists));
    open_brackets.resize(std::min(open_brackets.size(), c.brackets));
    property_sinks.resize(std::min(property_sinks.size(), c.sinks));
    nesting = c.nesting;
    doc_targets.clear();
}

bool ParseState::report(const tao::pegtl::parse_error& error) {
    if (stopped_) return false;
    diag::Kind kind = diag::Kind::Syntax;
    if (const auto* e = dynamic_cast<const syntax_error*>(&error)) kind = e->kind;
    ast::Loc where;
    if (!error.positions().empty()) where = loc(error.positions().front());
    diags.error(kind, where, std::string(error.message()));
    if (const auto* e = dynamic_cast<const syntax_error*>(&error); e != nullptr && e->fatal) {
        stopped_ = true;
        return false;
    }
    if (++reported_ >= Limits::max_errors) {
        diags.note(where,
                   "too many errors (" + std::to_string(Limits::max_errors) + "); stopping here");
        stopped_ = true;
        return false;
    }
    return true;
}

} // namespace yamsc::parse
