// AeroDyn's output channels that `load blade_elements` computes (named as
// AeroDyn names them, docs/aerodynamics.md), with AeroDyn's units: the rotor's
// RtFld* and the blade nodes' BkNj* (blade k, j-th node of BlOutNd).
#include "analysis/channels.hpp"

#include <string>

namespace yamsc::analysis {

const std::vector<OpenFastChannel>& aerodyn_channels() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> n;
        for (int k = 1; k <= 3; ++k)
            for (int j = 1; j <= 9; ++j)
                for (const char* what :
                     {"Alpha", "Phi", "Vrel", "AxInd", "TnInd", "Cl", "Cd", "Fx", "Fy"})
                    n.push_back("B" + std::to_string(k) + "N" + std::to_string(j) + what);
        return n;
    }();
    static const std::vector<OpenFastChannel> channels = [] {
        std::vector<OpenFastChannel> c{
            {"RtSpeed", "rpm", false}, {"RtTSR", "-", false},    {"RtVAvgxh", "m/s", false},
            {"RtSkew", "deg", false},  {"RtFldFxh", "N", false}, {"RtFldMxh", "N-m", false},
            {"RtFldPwr", "W", false},  {"RtFldCp", "-", false},  {"RtFldCt", "-", false},
            {"RtFldCq", "-", false},
        };
        for (const std::string& n : names) {
            const std::string what = n.substr(4);
            const char* unit = what == "Alpha" || what == "Phi" ? "deg"
                               : what == "Vrel"                 ? "m/s"
                               : what == "Fx" || what == "Fy"   ? "N/m"
                                                                : "-";
            c.push_back({n.c_str(), unit, false});
        }
        return c;
    }();
    return channels;
}

} // namespace yamsc::analysis
