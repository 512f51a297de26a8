// The .bts of a `yamsc dlc` wind: its TurbSim input run through `yamsc
// turbulence`'s function, so that the file is the one that command writes.
#include "analysis/commands.hpp"
#include "analysis/dlc.hpp"

#include <sstream>

namespace yamsc::analysis {

void generate_bts(const std::string& turbsim_input, const std::string& bts) {
    driver::TurbulenceOptions o;
    o.input = turbsim_input;
    o.output = bts;
    // Its summary and per-file progress would bury dlc's own line per wind.
    std::ostringstream summary, progress;
    turbulence(o, summary, progress);
}

} // namespace yamsc::analysis
