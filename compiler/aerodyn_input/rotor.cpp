#include "aerodyn_input/rotor.hpp"

#include "aerodyn/airfoil_file.hpp"
#include "aerodyn/blade_file.hpp"
#include "aerodyn_input/airfoil.hpp"
#include "diag/read_text.hpp"

#include <cmath>
#include <map>

namespace yamsc::aerodyn_input {

using diag::Kind;

namespace {

constexpr double deg = 3.14159265358979323846 / 180;

/// The slope at x of the parabola through three points (NWTC's
/// dfdxOfLagrangeInterpolant).
double parabola_slope(double x, double x1, double f1, double x2, double f2, double x3, double f3) {
    return f1 * ((x - x2) + (x - x3)) / ((x1 - x2) * (x1 - x3)) +
           f2 * ((x - x1) + (x - x3)) / ((x2 - x1) * (x2 - x3)) +
           f3 * ((x - x1) + (x - x2)) / ((x3 - x1) * (x3 - x2));
}

/// AeroDyn's setCantAngle: BlCrvAng from the slope of the mid-chord line's prebend
/// (BlCrvAC plus a quarter chord along the twisted chord) over the span.
void cant_angles(std::vector<aero::BladeNode>& nodes) {
    const std::size_t n = nodes.size();
    std::vector<double> x(n), z(n);
    for (std::size_t i = 0; i < n; ++i) {
        x[i] = nodes[i].curve_ac + 0.25 * nodes[i].chord * std::sin(nodes[i].twist);
        z[i] = nodes[i].span;
    }
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t a = i == 0 ? 0 : (i == n - 1 ? n - 3 : i - 1);
        const double slope =
            parabola_slope(z[i], z[a], x[a], z[a + 1], x[a + 1], z[a + 2], x[a + 2]);
        nodes[i].curve_angle = std::atan2(slope, 1.0);
    }
}

template <typename Enum> Enum as(int v) {
    return static_cast<Enum>(v);
}

class Converter {
public:
    Converter(const aerodyn::PrimaryFile& p, diag::Diagnostics& diags) : p_(p), diags_(diags) {}

    std::optional<aero::RotorInput> convert(int num_blades, const AeroDynDefaults& defaults) {
        const int errors = diags_.error_count();
        aero::RotorInput r;
        switches(r, defaults);
        airfoils(r);
        blades(r, num_blades);
        for (const aerodyn::TowerRow& t : p_.tower)
            r.tower.push_back({t.elevation, t.diameter, t.cd, t.ti});
        r.output_nodes = p_.blade_out_nodes;
        if (diags_.error_count() != errors) return std::nullopt;
        return r;
    }

private:
    void switches(aero::RotorInput& r, const AeroDynDefaults& defaults) {
        // What the reader warns of as not converted becomes what yamsc computes
        // instead: the BEM wake for the free vortex wake, the legacy BEM projection,
        // quasi-steady airfoils for the unsteady models other than 3 and 6.
        r.wake = p_.wake_mod == 3 ? aero::WakeModel::bem : as<aero::WakeModel>(p_.wake_mod);
        r.bem_mod = 1;
        r.skew = as<aero::SkewModel>(p_.skew_mod);
        r.skew_momentum_correction = p_.skew_mom_corr;
        r.skew_redistribution = as<aero::SkewRedistribution>(p_.skew_redistr_mod);
        r.skew_redistribution_factor = p_.skew_redistr_factor;
        r.tip_loss = p_.tip_loss;
        r.hub_loss = p_.hub_loss;
        r.tangential_induction = p_.tan_ind;
        r.axial_drag = p_.ai_drag;
        r.tangential_drag = p_.ti_drag;
        r.induction_tolerance = p_.ind_toler.value_or(0);
        r.max_iterations = p_.max_iter;
        // DBEMT_Mod acts with the BEM wake (Wake_Mod 1, or the older WakeMod 2);
        // -1 is the frozen wake of linearization, not a dynamic model.
        r.dynamic_inflow = r.wake == aero::WakeModel::bem && p_.dbemt_mod > 0
                               ? as<aero::DynamicInflow>(p_.dbemt_mod)
                               : aero::DynamicInflow::none;
        r.tau1_const = p_.tau1_const;
        r.unsteady = p_.ua_mod == 3 || p_.ua_mod == 6 ? as<aero::UnsteadyModel>(p_.ua_mod)
                                                      : aero::UnsteadyModel::none;
        r.f_lookup = p_.flookup;
        r.aoa_34 = p_.aoa34;
        r.ua_start_radius = p_.ua_start_rad;
        r.ua_end_radius = p_.ua_end_rad;
        r.tower_potential = as<aero::TowerPotential>(p_.twr_potent);
        r.tower_shadow = as<aero::TowerShadow>(p_.twr_shadow);
        r.tower_drag = p_.twr_aero;
        r.use_pitching_moment = p_.use_bl_cm;
        r.air_density = p_.air_density.value_or(defaults.air_density);
        r.kinematic_viscosity = p_.kinematic_viscosity.value_or(defaults.kinematic_viscosity);
        r.speed_of_sound = p_.speed_of_sound.value_or(defaults.speed_of_sound);
    }

    void airfoils(aero::RotorInput& r) {
        aerodyn::AirfoilColumns columns;
        columns.alpha = p_.in_col_alfa;
        columns.cl = p_.in_col_cl;
        columns.cd = p_.in_col_cd;
        columns.cm = p_.in_col_cm;
        columns.cpmin = p_.in_col_cpmin;
        for (const aerodyn::FileName& name : p_.airfoils) {
            auto source = diag::read_text_file(name.path, diags_, name.at);
            if (!source) continue;
            if (auto file = aerodyn::read_airfoil_file(source, columns, diags_))
                r.airfoils.push_back(to_airfoil(*file, r.unsteady));
        }
    }

    void blades(aero::RotorInput& r, int num_blades) {
        if (num_blades < 1 || num_blades > static_cast<int>(p_.blade_files.size())) {
            diags_.error(Kind::InvalidValue, {p_.file, 0, 0},
                         "the AeroDyn file names " + std::to_string(p_.blade_files.size()) +
                             " blade files (ADBlFile), not one for each of " +
                             std::to_string(num_blades) + " blades");
            return;
        }
        std::map<std::string, std::optional<aerodyn::BladeFile>> read; // one file, read once
        for (int k = 0; k < num_blades; ++k) {
            const aerodyn::FileName& name = p_.blade_files[static_cast<std::size_t>(k)];
            auto it = read.find(name.path);
            if (it == read.end()) {
                std::optional<aerodyn::BladeFile> file;
                if (auto source = diag::read_text_file(name.path, diags_, name.at))
                    file = aerodyn::read_blade_file(source, diags_);
                it = read.emplace(name.path, std::move(file)).first;
            }
            if (!it->second) continue;
            if (!r.blades.empty() && r.blades.front().size() != it->second->nodes.size())
                diags_.error(Kind::InvalidValue, name.at,
                             "every blade file must have as many nodes (NumBlNds) as the first");
            r.blades.push_back(nodes(*it->second, r.airfoils.size()));
        }
    }

    std::vector<aero::BladeNode> nodes(const aerodyn::BladeFile& file, std::size_t airfoils) {
        std::vector<aero::BladeNode> out;
        bool curved = false;
        for (const aerodyn::BladeNodeRow& row : file.nodes) {
            aero::BladeNode n;
            n.span = row.span;
            n.curve_ac = row.curve_ac;
            n.sweep_ac = row.sweep_ac;
            n.curve_angle = row.curve_angle * deg;
            n.twist = row.twist * deg;
            n.chord = row.chord;
            n.airfoil = row.airfoil_id - 1;
            if (row.airfoil_id > static_cast<int>(p_.airfoils.size()))
                diags_.error(Kind::InvalidValue, row.airfoil_id_at,
                             "BlAFID " + std::to_string(row.airfoil_id) +
                                 " names no airfoil: the AeroDyn file lists " +
                                 std::to_string(p_.airfoils.size()) + " (NumAFfiles)");
            else if (static_cast<std::size_t>(n.airfoil) >= airfoils)
                n.airfoil = 0; // its file had errors, reported
            curved = curved || row.curve_ac != 0;
            out.push_back(n);
        }
        // ReadBladeInputs: without prebend the curve angle is zero; AeroDyn computes it
        // when the column is absent (and for the polar projection, BEM_Mod 2, which
        // yamsc does not convert: the legacy projection's rule applies).
        if (!curved)
            for (aero::BladeNode& n : out) n.curve_angle = 0;
        if (!file.has_curve_angle) {
            if (out.size() < 3)
                diags_.error(Kind::InvalidValue, file.nodes.front().at,
                             "without a BlCrvAng column, AeroDyn computes it from 3 blade "
                             "nodes or more");
            else
                cant_angles(out);
        }
        return out;
    }

    const aerodyn::PrimaryFile& p_;
    diag::Diagnostics& diags_;
};

} // namespace

std::optional<aero::RotorInput> to_rotor_input(const aerodyn::PrimaryFile& primary, int num_blades,
                                               diag::Diagnostics& diags,
                                               const AeroDynDefaults& defaults) {
    return Converter(primary, diags).convert(num_blades, defaults);
}

std::optional<aero::RotorInput> read_aerodyn_rotor(const std::filesystem::path& primary,
                                                   int num_blades, diag::Diagnostics& diags,
                                                   const AeroDynDefaults& defaults) {
    auto source = diag::read_text_file(primary.string(), diags);
    if (!source) return std::nullopt;
    auto file = aerodyn::read_primary_file(source, num_blades, diags);
    if (!file) return std::nullopt;
    return to_rotor_input(*file, num_blades, diags, defaults);
}

} // namespace yamsc::aerodyn_input
