#include "parse/parser.hpp"

#include "grammar/model_grammar.hpp"
#include "parse/actions.hpp"
#include "parse/control.hpp"
#include "parse/parse_state.hpp"

#include <tao/pegtl.hpp>

#include <algorithm>
#include <new>

namespace yamsc::parse {
namespace {

/// Refuses sources too large to parse safely.
bool within_size_limits(const std::shared_ptr<const diag::SourceFile>& source,
                        diag::Diagnostics& diags) {
    const std::string& text = source->text();
    if (text.size() > Limits::max_source_bytes) {
        diags.error(diag::Kind::Limit, diag::Location{source, 0, 0},
                    "the file is too large (" + std::to_string(text.size()) +
                        " bytes; the limit is " + std::to_string(Limits::max_source_bytes >> 20) +
                        " MiB)");
        return false;
    }
    const auto lines = std::count(text.begin(), text.end(), '\n');
    if (lines >= Limits::max_lines) {
        diags.error(diag::Kind::Limit, diag::Location{source, Limits::max_lines + 1, 1},
                    "the file has more than " + std::to_string(Limits::max_lines) + " lines");
        return false;
    }
    return true;
}

/// Runs `Grammar` over the whole source; every error ends up in the diagnostics.
template <class Grammar> void run(ParseState& st) {
    const std::string& text = st.source->text();
    // PEGTL's own source name is left empty: positions carry our SourceFile instead, and an
    // empty name keeps the positions cheap to copy.
    tao::pegtl::memory_input<tao::pegtl::tracking_mode::eager, tao::pegtl::eol::lf_crlf> in(
        text.data(), text.size(), "");
    try {
        if (!tao::pegtl::parse<Grammar, action, control>(in, st)) {
            st.diags.error(diag::Kind::Syntax, st.loc(in.position()),
                           "unexpected text that is not part of any statement");
        }
    } catch (const tao::pegtl::parse_error& error) {
        st.report(error);
    } catch (const std::bad_alloc&) {
        st.diags.error(diag::Kind::Limit, st.loc(in.position()),
                       "out of memory while parsing the file");
    }
}

} // namespace

std::optional<ast::ModelFile> parse_model(std::shared_ptr<const diag::SourceFile> source,
                                          diag::Diagnostics& diags) {
    if (!source) throw diag::InternalError("parse_model called without a source");
    const int errors_before = diags.error_count();
    if (!within_size_limits(source, diags)) return std::nullopt;
    ParseState st(source, diags);
    run<grammar::model_file>(st);
    if (diags.error_count() > errors_before) return std::nullopt;
    return std::move(st.file);
}

std::optional<ast::Expr> parse_expression(std::shared_ptr<const diag::SourceFile> source,
                                          diag::Diagnostics& diags) {
    if (!source) throw diag::InternalError("parse_expression called without a source");
    const int errors_before = diags.error_count();
    if (!within_size_limits(source, diags)) return std::nullopt;
    ParseState st(source, diags);
    run<grammar::standalone_expression>(st);
    if (diags.error_count() > errors_before) return std::nullopt;
    if (st.stack_size() != 1) {
        throw diag::InternalError("parse_expression left " + std::to_string(st.stack_size()) +
                                  " expressions");
    }
    return st.pop();
}

} // namespace yamsc::parse
