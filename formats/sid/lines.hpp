#pragma once
// The first stage of the SID reader: the text split into lines by sid/grammar.hpp.
// The lines point into the text of the SourceFile, which must outlive them.
#include "sid/read_context.hpp"

#include <array>
#include <string_view>
#include <vector>

namespace yamsc::sid {

/// One line of a SID file that says something (blank lines and comments are dropped).
struct Line {
    enum class Shape : unsigned char {
        block,   // `name`: a block opens
        assign,  // `name = value`
        indexed, // `name(i, j, ...) = value`
        open,    // `new name [= value]`
        close,   // `end name`
    };
    enum class ValueKind : unsigned char { none, integer, real, text };

    std::string_view name;      // as written; compare with same_name()
    std::string_view value;     // the value without surrounding blanks (may be empty)
    std::array<int, 3> index{}; // the first three indices (1-based), clamped to the int range
    int index_count = 0;        // how many indices the line has (may exceed 3)
    int line = 0;               // where the name starts
    int col = 0;
    int value_col = 0; // where the value starts
    Shape shape = Shape::block;
    ValueKind value_kind = ValueKind::none;

    bool is_key() const { return shape == Shape::assign || shape == Shape::indexed; }
    bool has_number() const {
        return value_kind == ValueKind::integer || value_kind == ValueKind::real;
    }
};

/// Case-insensitive comparison of names (`mdCM` == `MDCM`).
bool same_name(std::string_view a, std::string_view b);

/// Splits the text of the context's file into lines. The first line is `part` if the file has
/// one (the free-text header before it is dropped); reports syntax errors and goes on.
std::vector<Line> split_lines(ReadContext& cx);

} // namespace yamsc::sid
