#pragma once
// The OC3-Hywind spar's three mooring lines, as the tests place them.
#include <yamsc/mooring/mooring_system.hpp>

#include <cmath>
#include <vector>

namespace yamsc::runtime::mooring::test {

// Jonkman, "Definition of the Floating System for Phase IV of OC3",
// NREL/TP-500-47535 (2010), table 5-1: three lines 120 degrees apart, anchors
// 853.87 m from the spar's axis at 320 m depth, fairleads at 5.2 m and 70 m
// below the still water level (the reference point), 902.2 m unstretched,
// 698.094 N/m in water, EA = 384,243,000 N; FAST's seabed without friction.
inline std::vector<Line> oc3_lines() {
    std::vector<Line> lines;
    for (int k = 0; k < 3; ++k) {
        const double a = k * 2 * M_PI / 3;
        Line l;
        l.properties = {902.2, 384243000.0, 698.094, 0.0};
        l.anchor = {853.87 * std::cos(a), 853.87 * std::sin(a), -320};
        l.fairlead = {5.2 * std::cos(a), 5.2 * std::sin(a), -70};
        lines.push_back(l);
    }
    return lines;
}

} // namespace yamsc::runtime::mooring::test
