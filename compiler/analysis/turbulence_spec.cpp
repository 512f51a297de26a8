#include "analysis/turbulence_spec.hpp"

#include "diag/errors.hpp"
#include "wind/turbsim_input.hpp"

#include <fstream>
#include <stdexcept>

namespace yamsc::analysis {

namespace {

using runtime::TurbulenceSpec;

TurbulenceSpec from_file(const wind::TurbSimInput& t) {
    TurbulenceSpec s;
    s.ny = t.ny;
    s.nz = t.nz;
    s.width = t.grid_width;
    s.height = t.grid_height;
    s.hub_height = t.hub_height;
    s.time_step = t.time_step;
    s.analysis_time = t.analysis_time;
    s.usable_time = t.usable_time;
    s.periodic = t.periodic;
    switch (t.characteristic) {
    case wind::TurbulenceCharacteristic::A:
        s.turbulence_class = runtime::TurbulenceClass::A;
        break;
    case wind::TurbulenceCharacteristic::B:
        s.turbulence_class = runtime::TurbulenceClass::B;
        break;
    case wind::TurbulenceCharacteristic::C:
        s.turbulence_class = runtime::TurbulenceClass::C;
        break;
    case wind::TurbulenceCharacteristic::percent:
        s.turbulence_class = runtime::TurbulenceClass::intensity;
        s.intensity = t.intensity_percent / 100;
        break;
    }
    s.model = t.model == wind::IecTurbulenceModel::normal ? runtime::TurbulenceModel::normal
                                                          : runtime::TurbulenceModel::extreme;
    if (t.model == wind::IecTurbulenceModel::extreme) s.turbine_class = t.turbine_class;
    s.etm_c = t.etm_c;
    s.profile = t.profile == wind::WindProfile::power_law ? runtime::MeanProfile::power_law
                                                          : runtime::MeanProfile::logarithmic;
    s.ref_height = t.ref_height;
    s.ref_speed = t.ref_speed;
    s.power_law = t.power_law;
    s.roughness = t.roughness;
    s.seed = t.seed;
    s.scaling = t.scale_iec == 0   ? runtime::SigmaScaling::none
                : t.scale_iec == 1 ? runtime::SigmaScaling::hub
                                   : runtime::SigmaScaling::each_point;
    return s;
}

// Without a file: what the options must give, and TurbSim's defaults for the rest
// (600 s at 0.05 s, NTM, power law 0.2 through the hub, seed 1, no scaling).
TurbulenceSpec from_options_alone(const driver::TurbulenceOptions& o) {
    for (const auto& [given, name] : {std::pair{o.characteristic.has_value(), "--class"},
                                      {o.speed.has_value(), "--speed"},
                                      {o.hub_height.has_value(), "--hub-height"},
                                      {o.ny.has_value(), "--grid"},
                                      {o.width.has_value(), "--size"}})
        if (!given)
            throw diag::UsageError(std::string("turbulence without an input file needs ") + name);
    TurbulenceSpec s;
    s.time_step = 0.05;
    s.analysis_time = s.usable_time = 600;
    s.seed = 1;
    return s;
}

} // namespace

TurbulenceSpec turbulence_spec(const driver::TurbulenceOptions& o,
                               std::vector<std::string>& warnings) {
    TurbulenceSpec s;
    if (!o.input.empty()) {
        std::ifstream in(o.input, std::ios::binary);
        if (!in) throw diag::UserError(o.input + ": cannot open the TurbSim input file");
        try {
            const wind::TurbSimInput t = wind::read_turbsim_input(in, o.input);
            warnings = t.warnings;
            s = from_file(t);
        } catch (const std::runtime_error& e) {
            throw diag::UserError(e.what());
        }
    } else {
        s = from_options_alone(o);
    }
    using C = driver::TurbulenceCharacteristicOption;
    if (o.characteristic) {
        switch (*o.characteristic) {
        case C::A:
            s.turbulence_class = runtime::TurbulenceClass::A;
            break;
        case C::B:
            s.turbulence_class = runtime::TurbulenceClass::B;
            break;
        case C::C:
            s.turbulence_class = runtime::TurbulenceClass::C;
            break;
        case C::percent:
            s.turbulence_class = runtime::TurbulenceClass::intensity;
            s.intensity = o.intensity_percent / 100;
            break;
        }
    }
    if (o.model) {
        s.model = *o.model == driver::TurbulenceModelOption::ntm
                      ? runtime::TurbulenceModel::normal
                      : runtime::TurbulenceModel::extreme;
        s.turbine_class = *o.model == driver::TurbulenceModelOption::etm3   ? 3
                          : *o.model == driver::TurbulenceModelOption::etm2 ? 2
                                                                            : 1;
    }
    if (o.profile)
        s.profile = *o.profile == driver::TurbulenceProfileOption::power_law
                        ? runtime::MeanProfile::power_law
                        : runtime::MeanProfile::logarithmic;
    if (o.hub_height) s.hub_height = *o.hub_height;
    // --speed is the mean at the reference height: --ref-height, the file's RefHt, or
    // without a file the hub.
    if (o.speed) s.ref_speed = *o.speed;
    if (o.ref_height)
        s.ref_height = *o.ref_height;
    else if (o.input.empty())
        s.ref_height = s.hub_height;
    if (o.ny) s.ny = *o.ny;
    if (o.nz) s.nz = *o.nz;
    if (o.width) s.width = *o.width;
    if (o.height) s.height = *o.height;
    if (o.time_step) s.time_step = *o.time_step;
    if (o.time) s.analysis_time = s.usable_time = *o.time;
    if (o.seed) s.seed = *o.seed;
    if (o.shear) s.power_law = *o.shear;
    if (o.roughness) s.roughness = *o.roughness;
    if (o.scale)
        s.scaling = *o.scale == 0   ? runtime::SigmaScaling::none
                    : *o.scale == 1 ? runtime::SigmaScaling::hub
                                    : runtime::SigmaScaling::each_point;
    if (o.periodic) s.periodic = true;
    return s;
}

} // namespace yamsc::analysis
