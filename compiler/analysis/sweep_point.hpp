#pragma once
// The operating points of `lin --sweep NAME=FROM:STEP:TO`: NAME is a
// parameter, a DOF's rate (`psi'`, a rotor speed) or an input (`V_wind`, a
// wind speed); `--schedule FILE` moves other DOFs, rates and inputs with it
// (sweep_schedule.hpp); the model's load blocks (--aero) are closed around it;
// `--trim [--adjust ..]` trims each point. Both Campbell diagrams (the plain
// one, run_model.cpp, and the MBC3 one, rotor_campbell.cpp) take their
// points from here.
#include "analysis/loaded_model.hpp"
#include "analysis/sweep_schedule.hpp"

#include <optional>
#include <string>
#include <vector>

namespace yamsc::analysis {

struct SweepPoint {
    runtime::ModelView view; // with the swept parameter and the rotor block
    std::vector<double> q, qd, u;
};

class SweepPoints {
public:
    /// Checks the swept name, reads the schedule and closes --aero; UserError
    /// for unknown names, UsageError for a parameter swept under --aero.
    SweepPoints(const Loaded& l, const driver::LinOptions& o);

    /// The point at `value`, trimmed when --trim.
    SweepPoint at(double value) const;

    /// The swept name is a DOF's rate: the DOF (else empty).
    const std::string& rate_of() const { return rate_dof_; }

private:
    const Loaded& l_;
    const driver::LinOptions& o_;
    int param_ = -1;       // the swept parameter's index
    std::string rate_dof_; // or the DOF whose rate is swept
    std::string input_;    // or the input
    std::optional<SweepSchedule> schedule_;
    std::optional<runtime::ModelView> blocks_view_; // load blocks: the view closed once
    std::optional<runtime::ModelView> trim_view_;   // and with quasi-steady derivatives
};

} // namespace yamsc::analysis
