#pragma once
// The second stage of the SID reader: the nesting of the blocks. It finds which lines belong
// to which block (`part`, `new modal`, `refmod`, `new frame`, `new node`, the Taylor blocks),
// reports blocks that are not closed, given twice or unknown, and leaves the meaning of the
// values to the third stage (sid/reader.cpp, sid/taylor_builder.cpp).
#include "sid/lines.hpp"

#include <array>
#include <optional>
#include <vector>

namespace yamsc::sid {

/// A Taylor block as written: its header keys and its entries, not yet checked.
struct TaylorOutline {
    const Line* open = nullptr; // the line that names the block
    const Line* order = nullptr;
    const Line* nrow = nullptr;
    const Line* ncol = nullptr;
    const Line* nq = nullptr;
    const Line* nqn = nullptr;
    const Line* structure = nullptr;
    std::vector<const Line*> entries; // `m0(i, j) = x` and `m1(i, j, k) = x`
    bool has_second_order = false;    // `mn(...)` entries were seen (and ignored)
};

struct NodeOutline {
    const Line* open = nullptr; // `new node = id`
    const Line* rframe = nullptr;
    std::optional<TaylorOutline> origin, phi, psi, ap, sigma;
};

/// The Taylor blocks of the body, in the order the writer writes them.
enum class BodyBlock { mdCM, J, Ct, Cr, Me, Gr, Ge, Oe, ksigma, Ke, De };
constexpr std::size_t body_block_count = 11;
/// The name of a body block as the writer spells it.
const char* body_block_name(BodyBlock block);

struct SidOutline {
    const Line* part = nullptr;
    const Line* modal = nullptr; // `new modal`
    const Line* refmod = nullptr;
    const Line* mass = nullptr;
    const Line* nelastq = nullptr;
    std::vector<const Line*> mode_names; // `ielastq(k) = text`
    const Line* frame = nullptr;
    std::vector<NodeOutline> nodes;
    std::array<std::optional<TaylorOutline>, body_block_count> body;
    bool truncated = false; // the file ends inside a block: what is missing is not reported
};

/// Finds the blocks of the lines split_lines() produced. Reports structural errors.
SidOutline outline_sid(const std::vector<Line>& lines, ReadContext& cx);

} // namespace yamsc::sid
