#pragma once
// `yamsc lin --format openfast-lin`: a model's linearization as OpenFAST's
// `.lin` files (analysis/openfast_lin.hpp), one per operating point.
//
// States are x = [q; q'] of the DOFs not held, derivative order 2 as
// ElastoDyn's; inputs u are the model's inputs and outputs y its outputs.
// DOFs named as `yamsc from-openfast` names ElastoDyn's (q_fa1, psi,
// q_b1_flap1, ...) get ElastoDyn's descriptions ("ED 1st tower fore-aft
// bending mode DOF (internal DOF index = DOF_TFA1), m") and its signs (the
// side-side modes are written negated, as ED's Q_TSS1 = -q_ss1); other DOFs
// are described by name ("yamsc q1 DOF, m", the unit from the DOF's comment).
// A blade's DOFs (families q_b1_*, q_b2_*, q_b3_*, as MBC3 finds them), inputs
// and outputs (a triplet differing in a b1/b2/b3 or a final 1/2/3) are in the
// rotating frame. A and B are those of `yamsc lin` (exact, from the generated
// Jacobians); C and D are central differences of the generated outputs.
#include "analysis/loaded_model.hpp"
#include "analysis/openfast_lin.hpp"

#include <yamsc/model_view.hpp>

#include <iosfwd>
#include <limits>
#include <string>
#include <vector>

namespace yamsc::analysis {

struct LinFilePoint {
    std::vector<double> q, qd, u; ///< the operating point
    std::vector<int> held;        ///< DOFs left out, moving as prescribed (MBC3: the azimuth)
    int azimuth_dof = -1;         ///< the rotor's DOF (header's rotor speed and azimuth), or -1
    double wind_speed = std::numeric_limits<double>::quiet_NaN();
};

/// The file of the linear model of `view` at `p`; `model` gives titles and units.
LinFile lin_file(const model::Model& model, const runtime::ModelView& view, const LinFilePoint& p);

/// `lin --format openfast-lin -o PATH` at (q, q', u): one file at the point,
/// or with --mbc3 / --azimuths one per azimuth (the rotor's DOF set to 2π k/N,
/// it and --hold held, as MBC3 linearizes). Writes each atomically and reports
/// on `out` (nothing when `quiet`).
void write_openfast_lin(const Loaded& l, const runtime::ModelView& view,
                        const driver::LinOptions& o, const std::vector<double>& q,
                        const std::vector<double>& qd, const std::vector<double>& u,
                        std::ostream& out, bool quiet);

/// Whether `lin` writes one file per azimuth.
bool lin_files_per_azimuth(const driver::LinOptions& o);

/// The files `-o PATH` names: PATH itself for one point (`azimuths` 0), else
/// `<root>.1.lin` .. `<root>.N.lin` as OpenFAST names them, root being PATH
/// without a final `.lin`.
std::vector<std::string> lin_file_paths(const std::string& path, int azimuths);

} // namespace yamsc::analysis
