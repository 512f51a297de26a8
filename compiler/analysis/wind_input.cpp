#include "analysis/wind_input.hpp"

#include "analysis/load_blocks.hpp"
#include "diag/errors.hpp"

#include <yamsc/wind.hpp>

#include <iostream>
#include <stdexcept>

namespace yamsc::analysis {

using diag::UsageError;
using diag::UserError;

runtime::WindInput open_wind_input(const std::string& spec) {
    try {
        runtime::WindInput w = runtime::open_wind(spec);
        for (const std::string& warning : w.warnings) std::cerr << warning << "\n";
        return w;
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    } catch (const std::runtime_error& e) {
        throw UserError(e.what());
    }
}

runtime::InputFunction wind_inputs(const Loaded& l, const runtime::ModelView& v,
                                   std::vector<double> u, const std::string& spec) {
    const int w = wind_input(l, v);
    runtime::WindSignal wind = open_wind_input(spec).hub;
    return [u = std::move(u), wind = std::move(wind), w](double t, double* out) {
        for (std::size_t i = 0; i < u.size(); ++i) out[i] = u[i];
        out[w] = wind(t);
    };
}

void set_wind_at_start(const Loaded& l, const runtime::ModelView& v, std::vector<double>& u,
                       const std::string& spec) {
    std::vector<double> out(u.size());
    wind_inputs(l, v, u, spec)(0.0, out.data());
    u = out;
}

} // namespace yamsc::analysis
