#include "sid/lines.hpp"

#include "sid/grammar.hpp"
#include "sid/numbers.hpp"

#include <tao/pegtl.hpp>

#include <algorithm>
#include <cctype>
#include <limits>
#include <new>
#include <string>

namespace yamsc::sid {
namespace {

namespace p = tao::pegtl;
namespace g = grammar;

struct SplitState {
    ReadContext& cx;
    std::vector<Line> lines;
    Line current; // the line being read; dropped if it turns out to be broken
    bool too_many_lines = false;
};

std::string_view trim_right(std::string_view text) {
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r' ||
                             text.back() == '\f' || text.back() == '\v')) {
        text.remove_suffix(1);
    }
    return text;
}

// ---------------------------------------------------------------- actions

template <class Rule> struct action : p::nothing<Rule> {};

/// Where a name starts, and the name.
template <class Input> void take_name(const Input& in, SplitState& st) {
    st.current.name = in.string_view();
    st.current.line = static_cast<int>(in.position().line);
    st.current.col = static_cast<int>(in.position().column);
}
template <> struct action<g::key> {
    template <class Input> static void apply(const Input& in, SplitState& st) { take_name(in, st); }
};
/// `new name` and `end name` are located at `new` and `end`.
template <> struct action<g::kw_new> {
    template <class Input> static void apply(const Input& in, SplitState& st) {
        st.current.line = static_cast<int>(in.position().line);
        st.current.col = static_cast<int>(in.position().column);
    }
};
template <> struct action<g::kw_end> : action<g::kw_new> {};
template <> struct action<g::end_name> {
    template <class Input> static void apply(const Input& in, SplitState& st) {
        st.current.name = in.string_view();
    }
};
template <> struct action<g::new_name> : action<g::end_name> {};

template <class Input> void take_value(const Input& in, SplitState& st, Line::ValueKind kind) {
    st.current.value = trim_right(in.string_view());
    st.current.value_kind = kind;
    st.current.value_col = static_cast<int>(in.position().column);
}
template <> struct action<g::integer_value> {
    template <class Input> static void apply(const Input& in, SplitState& st) {
        take_value(in, st, Line::ValueKind::integer);
    }
};
template <> struct action<g::real_value> {
    template <class Input> static void apply(const Input& in, SplitState& st) {
        take_value(in, st, Line::ValueKind::real);
    }
};
template <> struct action<g::text_value> {
    template <class Input> static void apply(const Input& in, SplitState& st) {
        take_value(in, st, Line::ValueKind::text);
    }
};

template <> struct action<g::index_number> {
    template <class Input> static void apply(const Input& in, SplitState& st) {
        Line& line = st.current;
        if (line.index_count < 3) {
            const long long value = parse_integer(in.string_view()).value_or(0);
            line.index[static_cast<std::size_t>(line.index_count)] =
                static_cast<int>(std::clamp<long long>(value, std::numeric_limits<int>::min(),
                                                       std::numeric_limits<int>::max()));
        }
        if (line.index_count < 1000) ++line.index_count; // enough to say "too many"
    }
};

void finish(SplitState& st, Line::Shape shape) {
    st.current.shape = shape;
    if (st.lines.size() == Limits::max_lines) {
        st.cx.error(diag::Kind::Limit, st.current.line, 1,
                    "more than " + std::to_string(Limits::max_lines) +
                        " lines with content: the SID reader stops here");
        st.too_many_lines = true;
    }
    if (!st.too_many_lines) st.lines.push_back(st.current);
    st.current = Line{};
}
template <> struct action<g::block_rest> {
    static void apply0(SplitState& st) { st.current.shape = Line::Shape::block; }
};
template <> struct action<g::assign_rest> {
    static void apply0(SplitState& st) { st.current.shape = Line::Shape::assign; }
};
template <> struct action<g::indexed_rest> {
    static void apply0(SplitState& st) { st.current.shape = Line::Shape::indexed; }
};
template <> struct action<g::keyed_line> {
    static void apply0(SplitState& st) { finish(st, st.current.shape); }
};
template <> struct action<g::end_line> {
    static void apply0(SplitState& st) { finish(st, Line::Shape::close); }
};
template <> struct action<g::new_line> {
    static void apply0(SplitState& st) { finish(st, Line::Shape::open); }
};

/// `part` and `end part` frame the body; they become lines like any other block.
template <> struct action<g::kw_part> {
    template <class Input> static void apply(const Input& in, SplitState& st) {
        if (st.current.line == 0) {
            take_name(in, st);
        } else { // `end part`: located at `end`
            st.current.name = in.string_view();
        }
    }
};
template <> struct action<g::part_line> {
    static void apply0(SplitState& st) { finish(st, Line::Shape::block); }
};
template <> struct action<g::end_part_line> {
    static void apply0(SplitState& st) { finish(st, Line::Shape::close); }
};

template <> struct action<g::trailer> {
    template <class Input> static void apply(const Input& in, SplitState& st) {
        const std::string_view text = in.string_view();
        int line = static_cast<int>(in.position().line);
        for (const char c : text) {
            if (c == '\n') {
                ++line;
            } else if (!std::isspace(static_cast<unsigned char>(c))) {
                st.cx.warning(diag::Kind::Syntax, line, 1, "text after `end part` is ignored");
                return;
            }
        }
    }
};

// ---------------------------------------------------------------- errors

template <class Rule> constexpr const char* error_message() {
    return "cannot read this line";
}
template <> constexpr const char* error_message<g::line_start>() {
    return "expected a name at the start of the line (a block name, `name = value`, "
           "`name(i, j) = value`, `new name` or `end name`)";
}
template <> constexpr const char* error_message<g::end_name>() {
    return "expected the name of the block to close after `end`";
}
template <> constexpr const char* error_message<g::new_name>() {
    return "expected a block name after `new`";
}
template <> constexpr const char* error_message<g::key_rest>() {
    return "expected `=`, `(` or the end of the line after the name";
}
template <> constexpr const char* error_message<g::index_number>() {
    return "expected an index (a whole number)";
}
template <> constexpr const char* error_message<g::index_close>() {
    return "expected `,` or `)` in the list of indices";
}
template <> constexpr const char* error_message<g::equals>() {
    return "expected `=` after the indices";
}
template <> constexpr const char* error_message<g::line_end>() {
    return "expected the end of the line";
}

template <class Rule> struct control : p::normal<Rule> {
    template <class Input, class... States>
    [[noreturn]] static void raise(const Input& in, States&&...) {
        throw p::parse_error(error_message<Rule>(), in);
    }
};

/// A broken line is reported and skipped; reading goes on with the next line.
template <> struct control<g::body_line> : p::normal<g::body_line> {
    template <p::apply_mode A, p::rewind_mode M, template <class...> class Action,
              template <class...> class Control, class Input>
    static bool match(Input& in, SplitState& st) {
        st.current = Line{};
        if (st.cx.gave_up() || st.too_many_lines) {
            in.bump(in.size());
            return true;
        }
        try {
            return p::normal<g::body_line>::template match<A, M, Action, Control>(in, st);
        } catch (const p::parse_error& error) {
            const p::position where =
                error.positions().empty() ? in.position() : error.positions().front();
            st.cx.error(diag::Kind::Syntax, static_cast<int>(where.line),
                        static_cast<int>(where.column), std::string(error.message()));
            st.current = Line{};
            // Past the end of the broken line (the error may stand before or on it).
            while (!in.empty() && in.position().byte < where.byte) in.bump(1);
            while (!in.empty() && in.peek_char() != '\n') in.bump(1);
            if (!in.empty()) in.bump(1);
            return true;
        }
    }
};

} // namespace

bool same_name(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (std::tolower(static_cast<unsigned char>(a[i])) !=
            std::tolower(static_cast<unsigned char>(b[i]))) {
            return false;
        }
    }
    return true;
}

std::vector<Line> split_lines(ReadContext& cx) {
    const std::string& text = cx.file()->text();
    SplitState st{cx, {}, {}, false};
    p::memory_input<p::tracking_mode::eager, p::eol::lf_crlf> in(text.data(), text.size(), "");
    try {
        if (!p::parse<g::file, action, control>(in, st)) {
            cx.error(diag::Kind::Syntax, static_cast<int>(in.position().line), 1,
                     "cannot read the file");
        }
    } catch (const p::parse_error& error) {
        const p::position where =
            error.positions().empty() ? in.position() : error.positions().front();
        cx.error(diag::Kind::Syntax, static_cast<int>(where.line), static_cast<int>(where.column),
                 std::string(error.message()));
    } catch (const std::bad_alloc&) {
        cx.error(diag::Kind::Limit, static_cast<int>(in.position().line), 1,
                 "out of memory while reading the SID file");
    }
    return std::move(st.lines);
}

} // namespace yamsc::sid
