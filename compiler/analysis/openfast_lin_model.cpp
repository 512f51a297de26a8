#include "analysis/openfast_lin_model.hpp"

#include "analysis/channels.hpp"
#include "analysis/rotor_modes.hpp"

#include <yamsc/atomic_file.hpp>
#include <yamsc/linear_view.hpp>
#include <yamsc/mbc3.hpp>
#include <yamsc/second_order.hpp>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <map>
#include <ostream>

namespace yamsc::analysis {

using driver::LinOptions;

namespace {

using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// ElastoDyn's description of a DOF `yamsc from-openfast` names (its
/// Init_Lin/DOF_Desc text, the glue code's "ED " prefix aside), the sign that
/// turns our DOF into ElastoDyn's and its place in ElastoDyn's order of states
/// (platform, tower, yaw, generator, drivetrain, then the blades by mode: every
/// blade's first flap mode, every first edge mode, every second flap mode);
/// empty when the name is not one of them.
struct EdDof {
    std::string description;
    double sign = 1;
    int rank = 0;
};

EdDof elastodyn_dof(const std::string& name) {
    static const std::map<std::string, EdDof> fixed{
        {"surge",
         {"Platform horizontal surge translation DOF (internal DOF index = DOF_Sg), m", 1, 0}},
        {"sway",
         {"Platform horizontal sway translation DOF (internal DOF index = DOF_Sw), m", 1, 1}},
        {"heave",
         {"Platform vertical heave translation DOF (internal DOF index = DOF_Hv), m", 1, 2}},
        {"roll", {"Platform roll tilt rotation DOF (internal DOF index = DOF_R), rad", 1, 3}},
        {"pitch", {"Platform pitch tilt rotation DOF (internal DOF index = DOF_P), rad", 1, 4}},
        {"yaw", {"Platform yaw rotation DOF (internal DOF index = DOF_Y), rad", 1, 5}},
        {"q_fa1", {"1st tower fore-aft bending mode DOF (internal DOF index = DOF_TFA1), m", 1, 6}},
        {"q_ss1",
         {"1st tower side-to-side bending mode DOF (internal DOF index = DOF_TSS1), m", -1, 7}},
        {"q_fa2", {"2nd tower fore-aft bending mode DOF (internal DOF index = DOF_TFA2), m", 1, 8}},
        {"q_ss2",
         {"2nd tower side-to-side bending mode DOF (internal DOF index = DOF_TSS2), m", -1, 9}},
        {"nac_yaw", {"Nacelle yaw DOF (internal DOF index = DOF_Yaw), rad", 1, 10}},
        {"psi", {"Variable speed generator DOF (internal DOF index = DOF_GeAz), rad", 1, 12}},
        {"drtr",
         {"Drivetrain rotational-flexibility DOF (internal DOF index = DOF_DrTr), rad", 1, 13}}};
    if (const auto it = fixed.find(name); it != fixed.end()) return it->second;
    // q_b<k>_flap1, q_b<k>_edge1, q_b<k>_flap2
    if (name.size() == 10 && name.compare(0, 3, "q_b") == 0 && name[3] >= '1' && name[3] <= '9' &&
        name[4] == '_') {
        const std::string k(1, name[3]), mode = name.substr(5);
        const char* what = mode == "flap1"   ? "1st flapwise"
                           : mode == "edge1" ? "1st edgewise"
                           : mode == "flap2" ? "2nd flapwise"
                                             : nullptr;
        const char* index = mode == "edge1" ? "DOF_BE(" : "DOF_BF(";
        const int rank = (mode == "flap1" ? 20 : mode == "edge1" ? 30 : 40) + (name[3] - '0');
        if (what)
            return {std::string(what) + " bending-mode DOF of blade " + k +
                        " (internal DOF index = " + index + k + (mode == "flap2" ? ",2" : ",1") +
                        ")), m",
                    1, rank};
    }
    return {};
}

/// The unit in a comment's last `[...]`, or "".
std::string unit_in(const std::string& doc) {
    const auto close = doc.rfind(']');
    if (close == std::string::npos) return "";
    const auto open = doc.rfind('[', close);
    return open == std::string::npos ? "" : doc.substr(open + 1, close - open - 1);
}

/// Whether `name` is one of a blade triplet: a `b1`/`B1` (or a final digit) whose
/// siblings with 2 and 3 in its place exist too (f_b2_flap1, Q_B3F1, OoPDefl2).
bool in_blade_triplet(const std::string& name, const std::vector<std::string>& all) {
    auto has = [&](const std::string& n) {
        return std::find(all.begin(), all.end(), n) != all.end();
    };
    for (std::size_t at = 0; at < name.size(); ++at) {
        const bool blade = at > 0 && (name[at - 1] == 'b' || name[at - 1] == 'B');
        const bool last = at + 1 == name.size();
        if (!(blade || last) || name[at] < '1' || name[at] > '3') continue;
        int found = 0;
        for (char k : {'1', '2', '3'}) {
            std::string other = name;
            other[at] = k;
            found += has(other) ? 1 : 0;
        }
        if (found == 3) return true;
    }
    return false;
}

/// The free DOFs' accelerations M_ff⁻¹ F_f (the held DOFs' are zero) and the lower
/// half of B, M_ff⁻¹ ∂F_f/∂u: rows and columns of the free DOFs only, as the held
/// system of runtime::state_matrix_with_held.
struct FreeDynamics {
    std::vector<double> qdd; ///< free DOFs' accelerations (held DOFs' are zero)
    RowMajor B_lower;        ///< M_ff⁻¹ dF_f/du
};

FreeDynamics free_dynamics(const runtime::ModelView& v, const std::vector<double>& q,
                           const std::vector<double>& qd, const std::vector<double>& u,
                           const std::vector<int>& free) {
    const int nq = v.nq, nu = v.nu;
    const double* up = u.empty() ? nullptr : u.data();
    RowMajor M(nq, nq), dq(nq, nq), dqd(nq, nq), du(nq, std::max(nu, 1));
    Eigen::VectorXd F(nq);
    v.mass_matrix(0.0, q.data(), up, M.data());
    v.forcing(0.0, q.data(), qd.data(), up, F.data());
    v.jacobians(0.0, q.data(), qd.data(), up, dq.data(), dqd.data(), du.data());
    const auto n = static_cast<Eigen::Index>(free.size());
    Eigen::MatrixXd Mff(n, n), Fu(n, nu);
    Eigen::VectorXd Ff(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        Ff(i) = F(free[static_cast<std::size_t>(i)]);
        for (Eigen::Index j = 0; j < n; ++j)
            Mff(i, j) = M(free[static_cast<std::size_t>(i)], free[static_cast<std::size_t>(j)]);
        for (int j = 0; j < nu; ++j) Fu(i, j) = du(free[static_cast<std::size_t>(i)], j);
    }
    const auto ldlt = Mff.ldlt();
    FreeDynamics out;
    const Eigen::VectorXd a = ldlt.solve(Ff);
    out.qdd.assign(a.data(), a.data() + a.size());
    // Without inputs B is empty: Eigen's triangular solve must not see a
    // matrix without columns (it binds a reference to its null data).
    out.B_lower = nu > 0 ? RowMajor(ldlt.solve(Fu)) : RowMajor(n, 0);
    return out;
}

} // namespace

std::vector<std::string> lin_file_paths(const std::string& path, int azimuths) {
    if (azimuths <= 0) return {path};
    const bool ext = path.size() > 4 && path.compare(path.size() - 4, 4, ".lin") == 0;
    const std::string root = ext ? path.substr(0, path.size() - 4) : path;
    std::vector<std::string> out;
    for (int k = 1; k <= azimuths; ++k) out.push_back(root + "." + std::to_string(k) + ".lin");
    return out;
}

LinFile lin_file(const model::Model& model, const runtime::ModelView& v, const LinFilePoint& p) {
    const int nq = v.nq, nu = v.nu, ny = v.ny;
    std::vector<int> free;
    for (int i = 0; i < nq; ++i)
        if (std::find(p.held.begin(), p.held.end(), i) == p.held.end()) free.push_back(i);
    const int n = static_cast<int>(free.size()), nx = 2 * n;

    // Names: ElastoDyn's when every free DOF is one of from-openfast's.
    std::vector<EdDof> ed;
    bool all_ed = true;
    for (int i : free) {
        ed.push_back(elastodyn_dof(v.dof_names[static_cast<std::size_t>(i)]));
        all_ed = all_ed && !ed.back().description.empty();
    }
    const std::string module = all_ed ? "ED " : "yamsc ";
    auto doc_of = [](const auto& items, const std::string& name) {
        for (const auto& item : items)
            if (item.name == name) return item.doc;
        return std::string();
    };
    const RotorLayout layout = rotor_layout(v.dof_names);
    auto rotating_dof = [&](int i) {
        for (const runtime::BladeFamily& f : layout.families)
            if (std::find(f.begin(), f.end(), i) != f.end()) return true;
        return false;
    };

    // A, B and the point: those of `yamsc lin` without held DOFs, else of MBC3's held system.
    std::vector<double> x(p.q);
    x.insert(x.end(), p.qd.begin(), p.qd.end());
    const FreeDynamics dyn = free_dynamics(v, p.q, p.qd, p.u, free);
    LinFile f;
    f.A = {nx, nx,
           p.held.empty() ? runtime::second_order_model(v, p.q, p.qd, p.u).A
                          : runtime::state_matrix_with_held(v, x, p.u, p.held)};
    f.B = {nx, nu, std::vector<double>(static_cast<std::size_t>(nx * nu), 0.0)};
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < nu; ++j)
            f.B.data[static_cast<std::size_t>((n + i) * nu + j)] = dyn.B_lower(i, j);

    // States, then their derivatives: ElastoDyn writes "First time derivative of" for q'.
    // File state a is S_a x[perm_a]: ElastoDyn's order and signs for its DOFs.
    std::vector<int> order(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) order[static_cast<std::size_t>(k)] = k;
    if (all_ed)
        std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
            return ed[static_cast<std::size_t>(a)].rank < ed[static_cast<std::size_t>(b)].rank;
        });
    std::vector<double> sign(static_cast<std::size_t>(nx), 1.0);
    std::vector<int> perm(static_cast<std::size_t>(nx));
    for (int d = 0; d < 2; ++d)
        for (int kk = 0; kk < n; ++kk) {
            const int k = order[static_cast<std::size_t>(kk)];
            perm[static_cast<std::size_t>(d * n + kk)] = d * n + k;
            const auto i = static_cast<std::size_t>(free[static_cast<std::size_t>(k)]);
            const EdDof& e = ed[static_cast<std::size_t>(k)];
            std::string desc = all_ed ? e.description : "";
            if (desc.empty()) {
                std::string unit = unit_in(doc_of(model.dofs, v.dof_names[i]));
                desc = v.dof_names[i] + " DOF, " + (unit.empty() ? "-" : unit);
            }
            if (d == 1) desc = "First time derivative of " + desc + "/s";
            sign[static_cast<std::size_t>(d * n + kk)] = all_ed ? e.sign : 1.0;
            const double s = sign[static_cast<std::size_t>(d * n + kk)];
            const double value = d == 0 ? p.q[i] : p.qd[i];
            const double rate = d == 0 ? p.qd[i] : dyn.qdd[static_cast<std::size_t>(k)];
            const bool rot = rotating_dof(static_cast<int>(i));
            f.x.push_back({s * value, rot, 2, module + desc});
            f.xdot.push_back(
                {s * rate, rot, 2, "First time derivative of " + module + desc + "/s"});
        }

    for (int j = 0; j < nu; ++j) {
        const std::string& name = v.input_names[static_cast<std::size_t>(j)];
        std::string unit = unit_in(doc_of(model.inputs, name));
        f.u.push_back({p.u.empty() ? 0.0 : p.u[static_cast<std::size_t>(j)],
                       in_blade_triplet(name, v.input_names), 0,
                       module + name + ", " + (unit.empty() ? "-" : unit)});
    }

    // Outputs and their derivatives (central differences of the generated outputs; the
    // held DOFs stay put).
    if (ny > 0 && v.outputs) {
        const std::vector<double>&q = p.q, &qd = p.qd, &u = p.u;
        std::vector<double> y0(static_cast<std::size_t>(ny));
        auto eval = [&](std::vector<double>& y) {
            v.outputs(0.0, q.data(), qd.data(), u.empty() ? nullptr : u.data(), y.data());
        };
        eval(y0);
        for (int r = 0; r < ny; ++r) {
            const std::string& name = v.output_names[static_cast<std::size_t>(r)];
            std::string unit = unit_in(doc_of(model.outputs, name));
            if (unit.empty())
                if (const OpenFastChannel* c = openfast_channel(name)) unit = c->unit;
            f.y.push_back({y0[static_cast<std::size_t>(r)], in_blade_triplet(name, v.output_names),
                           0, module + name + ", (" + (unit.empty() ? "-" : unit) + ")"});
        }
        // C over every DOF, then the columns of the free ones (held DOFs stay put).
        std::vector<double> x0 = q;
        x0.insert(x0.end(), qd.begin(), qd.end());
        const runtime::OutputMatrices cd = runtime::output_matrices(v, x0, u, 0.0);
        const int nx_all = 2 * v.nq;
        f.C = {ny, nx, std::vector<double>(static_cast<std::size_t>(ny * nx))};
        for (int r = 0; r < ny; ++r)
            for (int d = 0; d < 2; ++d)
                for (int k = 0; k < n; ++k)
                    f.C.data[static_cast<std::size_t>(r * nx + d * n + k)] =
                        cd.C[static_cast<std::size_t>(r * nx_all + d * v.nq +
                                                      free[static_cast<std::size_t>(k)])];
        f.D = {ny, nu, cd.D};
    }

    // x_file = S P x: A -> S P A Pᵀ S, B -> S P B, C -> C Pᵀ S.
    auto at = [](const std::vector<int>& v, int a) {
        return static_cast<std::size_t>(v[static_cast<std::size_t>(a)]);
    };
    auto sg = [&](int a) { return sign[static_cast<std::size_t>(a)]; };
    LinMatrix A = f.A, B = f.B, C = f.C;
    const auto unx = static_cast<std::size_t>(nx), unu = static_cast<std::size_t>(nu);
    for (int a = 0; a < nx; ++a) {
        const auto ua = static_cast<std::size_t>(a);
        for (int b = 0; b < nx; ++b)
            A.data[ua * unx + static_cast<std::size_t>(b)] =
                sg(a) * sg(b) * f.A.data[at(perm, a) * unx + at(perm, b)];
        for (std::size_t j = 0; j < unu; ++j)
            B.data[ua * unu + j] = sg(a) * f.B.data[at(perm, a) * unu + j];
        for (std::size_t r = 0; r < f.y.size() && !f.C.data.empty(); ++r)
            C.data[r * unx + ua] = sg(a) * f.C.data[r * unx + at(perm, a)];
    }
    f.A = std::move(A);
    f.B = std::move(B);
    f.C = std::move(C);

    f.origin = "Predictions were generated by yamsc from the model " + model.name;
    f.linked = "(yamsc lin --format openfast-lin; A and B from the generated Jacobians, C and D "
               "by central differences of the outputs)";
    f.description = model.title.empty() ? model.name : model.title;
    if (p.azimuth_dof >= 0) {
        const auto a = static_cast<std::size_t>(p.azimuth_dof);
        f.rotor_speed = p.qd[a];
        f.azimuth = std::fmod(p.q[a], 2 * M_PI);
        if (f.azimuth < 0) f.azimuth += 2 * M_PI;
    }
    f.wind_speed = p.wind_speed;
    for (int j = 0; j < nu && std::isnan(f.wind_speed) && !p.u.empty(); ++j)
        if (v.input_names[static_cast<std::size_t>(j)] == "V_wind")
            f.wind_speed = p.u[static_cast<std::size_t>(j)];
    return f;
}

bool lin_files_per_azimuth(const LinOptions& o) {
    return o.mbc3 || o.azimuths_given;
}

void write_openfast_lin(const Loaded& l, const runtime::ModelView& view, const LinOptions& o,
                        const std::vector<double>& q, const std::vector<double>& qd,
                        const std::vector<double>& u, std::ostream& out, bool quiet) {
    const model::Model& model = *l.front.model;
    const bool per_azimuth = lin_files_per_azimuth(o);
    const std::vector<std::string> paths = lin_file_paths(o.output, per_azimuth ? o.azimuths : 0);
    LinFilePoint p;
    p.q = q;
    p.qd = qd;
    p.u = u;
    if (per_azimuth) {
        const RotorModesRequest r = rotor_request(view, q, qd, u, o.azimuth, o.hold, o.azimuths);
        p.held = r.held;
        p.azimuth_dof = r.azimuth_dof;
    } else if (!o.azimuth.empty()) {
        p.azimuth_dof = rotor_request(view, q, qd, u, o.azimuth, {}, 1).azimuth_dof;
    } else {
        // The rotor, for the header: the one DOF with a rate, if there is one.
        for (std::size_t i = 0; i < qd.size(); ++i)
            if (qd[i] != 0.0) p.azimuth_dof = p.azimuth_dof < 0 ? static_cast<int>(i) : -2;
        if (p.azimuth_dof < 0) p.azimuth_dof = -1;
    }
    for (std::size_t k = 0; k < paths.size(); ++k) {
        // The azimuths of MBC3 (runtime::mbc3_averaged): 2π k/N for the rotor's DOF.
        if (per_azimuth)
            p.q[static_cast<std::size_t>(p.azimuth_dof)] =
                2.0 * M_PI * static_cast<double>(k) / static_cast<double>(paths.size());
        runtime::write_file_atomically(paths[k], format_lin_file(lin_file(model, view, p)));
    }
    if (quiet) return;
    if (!per_azimuth)
        out << "wrote " << paths.front() << "\n";
    else
        out << "wrote " << paths.size() << " files " << paths.front() << " .. " << paths.back()
            << "\n";
}

} // namespace yamsc::analysis
