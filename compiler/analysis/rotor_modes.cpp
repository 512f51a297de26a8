#include "analysis/rotor_modes.hpp"

#include "diag/diagnostics.hpp"
#include "driver/bindings.hpp"
#include "driver/json.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace yamsc::analysis {

using diag::UserError;
namespace json = driver::json;

namespace {

/// `name` without its blade number at `at` ("q_b1_flap1" -> "q_flap1").
std::string family_name(const std::string& name, std::size_t at) {
    std::string out = name.substr(0, at) + name.substr(at + 2);
    for (std::size_t p = out.find("__"); p != std::string::npos; p = out.find("__"))
        out.erase(p, 1);
    while (!out.empty() && out.back() == '_') out.pop_back();
    return out;
}

/// The names of the MBC coordinates, in q order.
std::vector<std::string> coordinate_names(const std::vector<std::string>& dof_names,
                                          const RotorLayout& layout) {
    std::vector<std::string> names = dof_names;
    const char* parts[3] = {" collective", " cos", " sin"};
    for (std::size_t f = 0; f < layout.families.size(); ++f)
        for (int b = 0; b < 3; ++b)
            names[static_cast<std::size_t>(layout.families[f][static_cast<std::size_t>(b)])] =
                layout.family_names[f] + parts[b];
    return names;
}

} // namespace

RotorLayout rotor_layout(const std::vector<std::string>& dof_names) {
    RotorLayout layout;
    auto index = [&](const std::string& n) {
        const auto it = std::find(dof_names.begin(), dof_names.end(), n);
        return it == dof_names.end() ? -1 : static_cast<int>(it - dof_names.begin());
    };
    for (std::size_t i = 0; i < dof_names.size(); ++i) {
        const std::string& name = dof_names[i];
        for (std::size_t at = name.find("b1"); at != std::string::npos;
             at = name.find("b1", at + 1)) {
            std::string two = name, three = name;
            two[at + 1] = '2';
            three[at + 1] = '3';
            const int i2 = index(two), i3 = index(three);
            if (i2 < 0 || i3 < 0) continue;
            layout.families.push_back({static_cast<int>(i), i2, i3});
            layout.family_names.push_back(family_name(name, at));
            break;
        }
    }
    return layout;
}

std::vector<RotorMode> rotor_modes(const runtime::ModelView& view, const RotorModesRequest& r) {
    const RotorLayout layout = rotor_layout(view.dof_names);
    // A rotor without blade DOFs (a rigid rotor on a flexible tower) has no
    // coordinates to transform: its modes are those of the azimuth average.
    const auto azimuth = static_cast<std::size_t>(r.azimuth_dof);
    if (r.azimuth_dof < 0 || azimuth >= r.q.size())
        throw UserError("MBC3: no azimuth DOF (the DOF with a rate, or --azimuth)");
    const double omega = r.qd[azimuth];
    // The free DOFs, and the families in their numbering.
    const std::vector<std::string> all_names = coordinate_names(view.dof_names, layout);
    std::vector<std::string> names;
    std::map<int, int> kept_index; // q index -> index among the free DOFs
    for (int i = 0; i < view.nq; ++i)
        if (std::find(r.held.begin(), r.held.end(), i) == r.held.end()) {
            kept_index[i] = static_cast<int>(names.size());
            names.push_back(all_names[static_cast<std::size_t>(i)]);
        }
    std::vector<runtime::BladeFamily> families;
    for (const runtime::BladeFamily& f : layout.families) {
        if (!kept_index.count(f[0]) || !kept_index.count(f[1]) || !kept_index.count(f[2]))
            throw UserError("MBC3: a blade DOF is held");
        families.push_back({kept_index.at(f[0]), kept_index.at(f[1]), kept_index.at(f[2])});
    }
    const int n = static_cast<int>(names.size());
    std::vector<double> x = r.q;
    x.insert(x.end(), r.qd.begin(), r.qd.end());
    auto A_at = [&](double psi) {
        x[azimuth] = psi;
        return runtime::state_matrix_with_held(view, x, r.u, r.held);
    };
    const std::vector<runtime::Mode> modes =
        runtime::modal_analysis(runtime::mbc3_averaged(A_at, n, families, omega, r.azimuths), n);

    // The diagonal of M at the first azimuth (the same for each blade of a family).
    std::vector<double> weight;
    {
        x[azimuth] = 0.0;
        std::vector<double> M(static_cast<std::size_t>(view.nq * view.nq));
        view.mass_matrix(0.0, x.data(), r.u.empty() ? nullptr : r.u.data(), M.data());
        for (int i = 0; i < view.nq; ++i)
            if (kept_index.count(i))
                weight.push_back(std::fabs(M[static_cast<std::size_t>(i * view.nq + i)]));
    }
    // What a mode is named after: each DOF alone, a family's collective, or
    // its two cyclic coordinates together (the whirl).
    struct Group {
        std::string name;
        std::vector<int> members;
        int family = -1; // cyclic groups: the family
    };
    std::vector<Group> groups;
    std::vector<bool> grouped(static_cast<std::size_t>(n), false);
    for (std::size_t f = 0; f < families.size(); ++f) {
        groups.push_back({layout.family_names[f] + " cyclic",
                          {families[f][1], families[f][2]},
                          static_cast<int>(f)});
        grouped[static_cast<std::size_t>(families[f][1])] = true;
        grouped[static_cast<std::size_t>(families[f][2])] = true;
    }
    for (int k = 0; k < n; ++k)
        if (!grouped[static_cast<std::size_t>(k)])
            groups.push_back({names[static_cast<std::size_t>(k)], {k}, -1});

    std::vector<RotorMode> out;
    for (const runtime::Mode& m : modes) {
        RotorMode rm;
        rm.mode = m;
        if (m.shape.empty()) {
            out.push_back(std::move(rm));
            continue;
        }
        // Shares of kinetic energy (M_ii |φ_i|²), not of |φ|: DOFs in metres of
        // tower top and of blade tip, or in radians, compare only through mass.
        std::vector<double> energy(groups.size(), 0.0);
        double total = 0;
        for (std::size_t g = 0; g < groups.size(); ++g)
            for (int k : groups[g].members) {
                const auto i = static_cast<std::size_t>(k);
                energy[g] += weight[i] * std::norm(m.shape[i]);
            }
        for (double e : energy) total += e;
        std::vector<std::size_t> order(groups.size());
        for (std::size_t g = 0; g < order.size(); ++g) order[g] = g;
        std::sort(order.begin(), order.end(),
                  [&](std::size_t a, std::size_t b) { return energy[a] > energy[b]; });
        auto label_of = [&](const Group& g) {
            if (g.family < 0) return g.name;
            // A rotor at rest has standing cyclic modes (degenerate pairs): no whirl.
            if (omega == 0.0) return g.name;
            const runtime::BladeFamily& f = families[static_cast<std::size_t>(g.family)];
            const runtime::Whirl w = runtime::whirl_of(m.shape[static_cast<std::size_t>(f[1])],
                                                       m.shape[static_cast<std::size_t>(f[2])]);
            return layout.family_names[static_cast<std::size_t>(g.family)] +
                   (w == runtime::Whirl::forward    ? " FW"
                    : w == runtime::Whirl::backward ? " BW"
                                                    : " cyclic");
        };
        const Group& first = groups[order[0]];
        rm.largest = first.name;
        rm.participation = total > 0 ? energy[order[0]] / total : 0;
        rm.label = label_of(first);
        // A second part with a quarter of the energy or more is named too:
        // drivetrain and collective edge, yaw and cyclic flap couple strongly.
        if (order.size() > 1 && total > 0 && energy[order[1]] >= 0.25 * total)
            rm.label += " + " + label_of(groups[order[1]]);
        if (m.rigid_body) rm.label += " (rigid-body)";
        out.push_back(std::move(rm));
    }
    return out;
}

namespace {

int dof_index(const runtime::ModelView& view, const std::string& name, const char* option) {
    const auto it = std::find(view.dof_names.begin(), view.dof_names.end(), name);
    if (it == view.dof_names.end())
        throw UserError(std::string(option) + ": unknown DOF '" + name + "'" +
                        diag::did_you_mean(name, view.dof_names));
    return static_cast<int>(it - view.dof_names.begin());
}

std::string held_names(const runtime::ModelView& view, const RotorModesRequest& r) {
    std::string out;
    for (int i : r.held)
        out += (out.empty() ? "" : ", ") + view.dof_names[static_cast<std::size_t>(i)];
    return out;
}

} // namespace

RotorModesRequest rotor_request(const runtime::ModelView& view, std::vector<double> q,
                                std::vector<double> qd, std::vector<double> u,
                                const std::string& azimuth, const std::vector<std::string>& hold,
                                int azimuths) {
    RotorModesRequest r;
    if (!azimuth.empty()) {
        r.azimuth_dof = dof_index(view, azimuth, "--azimuth");
    } else {
        for (std::size_t i = 0; i < qd.size(); ++i) {
            if (qd[i] == 0.0) continue;
            if (r.azimuth_dof >= 0)
                throw UserError("--mbc3: several DOFs have a rate at the point (" +
                                view.dof_names[static_cast<std::size_t>(r.azimuth_dof)] + ", " +
                                view.dof_names[i] + "): name the rotor's with --azimuth");
            r.azimuth_dof = static_cast<int>(i);
        }
        if (r.azimuth_dof < 0)
            throw UserError("--mbc3: no DOF has a rate at the point: give the rotor speed "
                            "(--at psi'=1.2671) or name the rotor's DOF with --azimuth");
    }
    r.held.push_back(r.azimuth_dof);
    for (const std::string& name : hold) {
        const int i = dof_index(view, name, "--hold");
        if (std::find(r.held.begin(), r.held.end(), i) == r.held.end()) r.held.push_back(i);
    }
    std::sort(r.held.begin(), r.held.end());
    r.q = std::move(q);
    r.qd = std::move(qd);
    r.u = std::move(u);
    r.azimuths = azimuths;
    return r;
}

std::string format_rotor_modes(const runtime::ModelView& view, const RotorModesRequest& r,
                               const std::vector<RotorMode>& modes) {
    const double omega = r.qd[static_cast<std::size_t>(r.azimuth_dof)];
    char line[200];
    std::snprintf(line, sizeof line,
                  "MBC3: %d azimuths, rotor at %.6g rad/s (%.4g rpm); held: %s\n", r.azimuths,
                  omega, omega * 30.0 / M_PI, held_names(view, r).c_str());
    std::string out = line;
    out += "mode  frequency [Hz]  damping ratio  label (largest part, its share of the kinetic "
           "energy)\n";
    for (std::size_t i = 0; i < modes.size(); ++i) {
        const RotorMode& m = modes[i];
        if (m.mode.rigid_body)
            std::snprintf(line, sizeof line, "%4zu  %14s  %13s  %s\n", i + 1, "0", "-",
                          m.label.c_str());
        else
            std::snprintf(line, sizeof line, "%4zu  %14.6g  %13.4g  %s (%s, %.0f %%)\n", i + 1,
                          m.mode.freq_hz, m.mode.damping_ratio, m.label.c_str(), m.largest.c_str(),
                          100.0 * m.participation);
        out += line;
    }
    return out;
}

std::string rotor_modes_json(const runtime::ModelView& view, const RotorModesRequest& r,
                             const std::vector<RotorMode>& modes) {
    std::vector<std::string> held;
    for (int i : r.held) held.push_back(view.dof_names[static_cast<std::size_t>(i)]);
    std::string out = "{\"azimuths\":" + std::to_string(r.azimuths) + ",\"rotor_speed\":" +
                      json::number(r.qd[static_cast<std::size_t>(r.azimuth_dof)]) +
                      ",\"held\":" + json::strings(held) + ",\"modes\":[";
    for (std::size_t i = 0; i < modes.size(); ++i) {
        const RotorMode& m = modes[i];
        out += std::string(i ? "," : "") + "{\"label\":" + json::quote(m.label) +
               ",\"freq_hz\":" + json::number(m.mode.freq_hz) +
               ",\"damping_ratio\":" + json::number(m.mode.damping_ratio) +
               ",\"rigid_body\":" + (m.mode.rigid_body ? "true" : "false") +
               ",\"participation\":" + json::number(m.participation) + "}";
    }
    return out + "]}\n";
}

} // namespace yamsc::analysis
