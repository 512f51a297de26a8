#pragma once
// Steady coefficients of an airfoil at an angle of attack, as AeroDyn's
// AFI_ComputeAirfoilCoefs gives them for AFTabMod 1 (the first table).
#include "yamsc/aero/airfoil.hpp"

#include <cstddef>
#include <vector>

namespace yamsc::aero {

struct Coefficients {
    double cl = 0, cd = 0, cm = 0;
};

// alpha in rad, any value: wrapped to [-pi, pi) first. Linear interpolation
// (InterpOrd 1); a table of one row is constant.
Coefficients lookup(const PolarTable& table, double alpha);
inline Coefficients lookup(const Airfoil& airfoil, double alpha) {
    return lookup(airfoil.tables.front(), alpha);
}

// The segment [x[i], x[i+1]] of a sorted column holding a value, found from a
// uniform grid of buckets over the column's range instead of a binary search:
// the same i as min(upper_bound(x, a), n - 1) - 1 for every a in [x[0],
// x[n-1]] (and n - 2 for NaN). The BEM looks a polar up six times per element
// solve, the unsteady models three times per element and step.
class SegmentIndex {
public:
    SegmentIndex() = default;
    explicit SegmentIndex(const std::vector<double>& x); // sorted, two values or more
    std::size_t segment(const std::vector<double>& x, double a) const;

private:
    double x0_ = 0, inverse_width_ = 0;
    std::vector<std::size_t> first_; // per bucket: the last row at or below its lower edge
};

// A polar table with its SegmentIndex: lookup() of it, bit for bit.
class IndexedPolar {
public:
    explicit IndexedPolar(const PolarTable& table);
    Coefficients at(double alpha) const;

private:
    const PolarTable* table_;
    SegmentIndex index_;
};

} // namespace yamsc::aero
