#include "wind_kinds.hpp"

namespace yamsc::runtime {

namespace {

const WindKind kinds[] = {
    {1, "steady", open_steady_wind},
    {2, "uniform wind file", open_uniform_wind},
    {3, "TurbSim full field", open_turbsim_wind},
    {5, "HAWC full field", open_hawc_wind},
};

} // namespace

const WindKind* wind_kind(int wind_type) {
    for (const WindKind& k : kinds)
        if (k.wind_type == wind_type) return &k;
    return nullptr;
}

std::string supported_wind_types() {
    std::string s;
    for (const WindKind& k : kinds)
        s += (s.empty() ? "" : ", ") + std::to_string(k.wind_type) + " (" + k.what + ")";
    return s;
}

} // namespace yamsc::runtime
