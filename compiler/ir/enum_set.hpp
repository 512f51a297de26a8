#pragma once
// A set of the values of a small enum (at most 32 values, numbered from 0), as
// bits: what a command needs of the generated routines, which passes ran on a
// System. Iteration is in the enum's order.
#include <cstddef>
#include <cstdint>
#include <initializer_list>

namespace yamsc::ir {

template <class Enum, std::size_t Count> class EnumSet {
    static_assert(Count <= 32, "EnumSet holds at most 32 values");

public:
    constexpr EnumSet() = default;
    constexpr EnumSet(std::initializer_list<Enum> values) {
        for (Enum v : values) bits_ |= bit(v);
    }

    constexpr bool contains(Enum v) const { return (bits_ & bit(v)) != 0; }
    constexpr bool contains_all(EnumSet other) const {
        return (bits_ & other.bits_) == other.bits_;
    }
    constexpr bool empty() const { return bits_ == 0; }
    constexpr void insert(Enum v) { bits_ |= bit(v); }
    constexpr void insert(EnumSet other) { bits_ |= other.bits_; }
    /// The values of this set that `other` lacks.
    constexpr EnumSet without(EnumSet other) const { return from_bits(bits_ & ~other.bits_); }
    constexpr EnumSet both(EnumSet other) const { return from_bits(bits_ & other.bits_); }
    constexpr bool operator==(EnumSet other) const { return bits_ == other.bits_; }
    constexpr bool operator!=(EnumSet other) const { return bits_ != other.bits_; }

    /// Calls f(value) for each value in the set, in the enum's order.
    template <class F> void for_each(F&& f) const {
        for (std::size_t i = 0; i < Count; ++i)
            if (bits_ & (1u << i)) f(static_cast<Enum>(i));
    }

private:
    static constexpr std::uint32_t bit(Enum v) { return 1u << static_cast<unsigned>(v); }
    static constexpr EnumSet from_bits(std::uint32_t bits) {
        EnumSet s;
        s.bits_ = bits;
        return s;
    }
    std::uint32_t bits_ = 0;
};

} // namespace yamsc::ir
