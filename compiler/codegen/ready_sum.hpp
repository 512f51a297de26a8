#pragma once
// How straight-line code groups a difference `a - t1 - t2 - ...` so that it is
// ready soon: C evaluates `a - t1 - t2` left to right, so a chain waits for
// every term in turn, while the terms of an LDL^T update become ready at very
// different times (an entry of L depends on the columns eliminated before
// it). Values carry the cycle they are ready in a simple latency model of a
// current x86 core, and the two earliest operands are always combined first
// (a Huffman tree over the ready times): the 16-DOF turbine's rhs measured
// 65 ns (3 %) faster so than with chains whose terms come in ready order.
#include <string>
#include <vector>

namespace yamsc::codegen {

inline constexpr int add_latency = 4;
inline constexpr int mul_latency = 4;
inline constexpr int div_latency = 14;

/// A printed value, the cycle it is ready in, and whether it is a sum
/// (parenthesised as the right operand of + or -).
struct Timed {
    std::string text;
    int ready = 0;
    bool sum = false;
};

/// `a * b` (operands are names or array elements).
Timed product(const Timed& a, const Timed& b);

/// first - (t1 + t2 + ...), grouped by ready times (ties by position: first,
/// then the terms in order, then the partial sums as they are made), so the
/// grouping depends on the ready times only. Without a first term (text "")
/// the negated sum: `-(t1 + t2)`. Writes exactly terms.size() additions or
/// subtractions with a first term, one fewer without.
Timed difference(const Timed& first, const std::vector<Timed>& terms);

} // namespace yamsc::codegen
