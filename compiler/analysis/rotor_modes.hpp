#pragma once
// The modes of a turbine with a spinning three-bladed rotor, as OpenFAST's
// MBC3 post-processing gives them: the rotor held at its speed, the model
// linearized at N azimuths, each state matrix transformed to multi-blade
// coordinates (yamsc/mbc3.hpp), averaged, eigen-analysed, and every mode
// labelled by the parts that hold most of its kinetic energy ("q_flap1 BW",
// "q_fa1"), a whirl's direction from the phase of its cyclic coordinates.
#include "yamsc/mbc3.hpp"
#include "yamsc/modal.hpp"
#include "yamsc/model_view.hpp"

#include <string>
#include <vector>

namespace yamsc::analysis {

/// The rotor as the DOF names show it: blade families are DOFs whose names
/// differ only in a `b1`/`b2`/`b3` (q_b1_flap1, q_b2_flap1, q_b3_flap1: the
/// family "q_flap1").
struct RotorLayout {
    std::vector<runtime::BladeFamily> families;
    std::vector<std::string> family_names;
};
RotorLayout rotor_layout(const std::vector<std::string>& dof_names);

struct RotorMode {
    runtime::Mode mode;
    std::string label;        ///< e.g. "q_flap1 collective", "q_edge1 FW", "q_fa1"
    std::string largest;      ///< the MBC coordinate that takes part most
    double participation = 0; ///< its share of the mode's |shape|², 0..1
};

struct RotorModesRequest {
    std::vector<double> q, qd, u; ///< the point (the azimuth DOF's q is set per azimuth)
    int azimuth_dof = -1;         ///< the DOF that turns the rotor (q[azimuth] = ψ)
    std::vector<int> held;        ///< DOFs taken out of the eigen-analysis (the azimuth, ...)
    int azimuths = 36;
};

/// The azimuth-averaged MBC3 modes, sorted by frequency; `dof_names` give the
/// labels. A model without blade families gets the azimuth average alone.
std::vector<RotorMode> rotor_modes(const runtime::ModelView& view, const RotorModesRequest& r);

/// The request of `lin --mbc3`: the azimuth DOF is `azimuth` if given, else
/// the one DOF with a rate; it and the DOFs named in `hold` are held. Throws
/// UserError for unknown names or an ambiguous azimuth.
RotorModesRequest rotor_request(const runtime::ModelView& view, std::vector<double> q,
                                std::vector<double> qd, std::vector<double> u,
                                const std::string& azimuth, const std::vector<std::string>& hold,
                                int azimuths);

/// The table `lin --mbc3` prints, and its JSON form.
std::string format_rotor_modes(const runtime::ModelView& view, const RotorModesRequest& r,
                               const std::vector<RotorMode>& modes);
std::string rotor_modes_json(const runtime::ModelView& view, const RotorModesRequest& r,
                             const std::vector<RotorMode>& modes);

} // namespace yamsc::analysis
