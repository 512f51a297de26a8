#pragma once
// The third stage of the SID reader for one Taylor block: checks its header (order, nrow,
// ncol, nq, nqn, structure) against the shape the block must have, and fills its matrices
// from the entries, honouring the structure (symmetric blocks list j <= i only).
#include "sid/outline.hpp"
#include "sid/sid.hpp"

#include <optional>

namespace yamsc::sid {

/// The shape a block must have: `ncol` < 0 accepts any number of columns. `text` says it in
/// words for messages ("nq x nq").
struct BlockShape {
    int nrow = 0;
    int ncol = 0;
    const char* text = "";
};

/// Builds the block, or reports why it cannot and returns std::nullopt. `nq` is the number of
/// modes of the body (nelastq).
std::optional<Taylor> build_taylor(const TaylorOutline& block, const BlockShape& shape, int nq,
                                   ReadContext& cx);

} // namespace yamsc::sid
