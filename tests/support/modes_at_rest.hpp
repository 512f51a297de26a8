#pragma once
// The modes of a model about its equilibrium at rest, every input 0 and every
// DOF free, as `yamsc lin --trim` finds it: what the floating models' tests set
// against published frequencies.
#include <yamsc/modal.hpp>
#include <yamsc/trim.hpp>

#include <doctest/doctest.h>

#include <vector>

namespace test_support {

inline std::vector<yamsc::runtime::Mode> modes_at_rest(const yamsc::runtime::ModelView& v) {
    const std::vector<double> u(static_cast<std::size_t>(v.nu), 0.0);
    const std::vector<double> zero(static_cast<std::size_t>(v.nq), 0.0);
    const yamsc::runtime::TrimResult t =
        yamsc::runtime::trim(v, zero, zero, u, std::vector<bool>(zero.size(), false));
    REQUIRE(t.converged);
    std::vector<double> x(t.q);
    x.insert(x.end(), t.qd.begin(), t.qd.end());
    return yamsc::runtime::modal_analysis(yamsc::runtime::state_matrix_from_view(v, x, u), v.nq);
}

} // namespace test_support
