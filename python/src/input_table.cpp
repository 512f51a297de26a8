#include "input_table.hpp"

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>

namespace yamsc::python {

runtime::InputFunction table_input(std::vector<double> table, int rows, int nu) {
    const auto width = static_cast<std::size_t>(nu) + 1;
    if (rows < 1 || table.size() != static_cast<std::size_t>(rows) * width)
        throw std::invalid_argument("the input table needs rows of time and " + std::to_string(nu) +
                                    " input values");
    auto data = std::make_shared<const std::vector<double>>(std::move(table));
    std::vector<double> times;
    for (int r = 0; r < rows; ++r) times.push_back((*data)[static_cast<std::size_t>(r) * width]);
    if (!std::is_sorted(times.begin(), times.end()) ||
        std::adjacent_find(times.begin(), times.end()) != times.end())
        throw std::invalid_argument("the times of the input table must increase");
    return [data, times = std::move(times), width, nu](double t, double* u) {
        const double* first = data->data();
        if (t <= times.front() || times.size() == 1) {
            std::copy(first + 1, first + width, u);
            return;
        }
        if (t >= times.back()) {
            std::copy(first + (times.size() - 1) * width + 1, first + times.size() * width, u);
            return;
        }
        const auto hi = static_cast<std::size_t>(std::upper_bound(times.begin(), times.end(), t) -
                                                 times.begin());
        const double* a = first + (hi - 1) * width;
        const double* b = first + hi * width;
        const double w = (t - a[0]) / (b[0] - a[0]);
        for (int i = 0; i < nu; ++i) u[i] = a[1 + i] + w * (b[1 + i] - a[1 + i]);
    };
}

} // namespace yamsc::python
