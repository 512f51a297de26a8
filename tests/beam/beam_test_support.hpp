#pragma once
// Shared helpers of the beam tests: the NREL 5-MW files and small beams.
#include "beam/beam.hpp"
#include "diag/diagnostics.hpp"

#include <doctest/doctest.h>

#include <fstream>
#include <memory>
#include <sstream>
#include <string>

namespace beam_test {

/// A file of tests/data/nrel5mw/; a missing or empty file fails the test here, not later as a
/// puzzling parse error.
inline std::shared_ptr<const yamsc::diag::SourceFile> nrel_file(const std::string& name) {
    const std::string path = std::string(YAMSC_TEST_DATA_DIR) + "/nrel5mw/" + name;
    std::ifstream in(path);
    REQUIRE_MESSAGE(in.good(), "cannot read " << path);
    std::stringstream text;
    text << in.rdbuf();
    REQUIRE_MESSAGE(!text.str().empty(), path << " is empty");
    return std::make_shared<yamsc::diag::SourceFile>(path, text.str());
}

inline const char* const kTowerFile = "NRELOffshrBsline5MW_Onshore_ElastoDyn_Tower.dat";
inline const char* const kBladeFile = "NRELOffshrBsline5MW_Blade.dat";

/// A uniform beam: mass per length m, EI_y = EIy, EI_x = EIx, constant twist.
inline yamsc::beam::Beam uniform_beam(double L, double m, double EIy, double EIx,
                                      double twist = 0) {
    yamsc::beam::Beam b;
    b.length = L;
    b.stations = {{0, m, EIx, EIy, twist}, {1, m, EIx, EIy, twist}};
    b.integration_stations = 11;
    return b;
}

/// A mode along `direction` with shape (z/L)^power.
inline yamsc::beam::Mode power_mode(const std::string& name, int direction, int power,
                                    double damping = 0) {
    yamsc::beam::Mode m;
    m.name = name;
    m.direction = direction;
    m.coeffs.assign(static_cast<std::size_t>(power) + 1, 0.0);
    m.coeffs.back() = 1;
    m.damping_ratio = damping;
    return m;
}

} // namespace beam_test
