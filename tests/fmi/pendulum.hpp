#pragma once
// The reference of the tests: the same generated double pendulum as a runtime view.
#include "double_pendulum.hpp"
#include "yamsc/model_view.hpp"

#include <vector>

namespace fmi_test {

/// The unit's parameters (its glue's settings: the model's, with c = 0.15).
inline double_pendulum::Params parameters() {
    double_pendulum::Params p;
    p.c = 0.15;
    return p;
}

inline yamsc::runtime::ModelView pendulum() {
    return yamsc::runtime::from_generated<double_pendulum::Model>(parameters());
}

/// The unit's start state (its glue's settings).
inline const std::vector<double> x_start{0.5, -0.3, 0.1, 0.2};

} // namespace fmi_test
