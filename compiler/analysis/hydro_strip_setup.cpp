#include "analysis/hydro_strip_setup.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace yamsc::analysis {
namespace {

using diag::Kind;
using runtime::hydro::StripCoefficients;

StripCoefficients without_growth(const hydrodyn::Coefficients& c) {
    return {c.cd, c.ca, c.cp, c.ax_cd, c.ax_ca, c.ax_cp};
}

// The depth-based table at height z (below SWL negative; its Dpth rows are depths,
// positive down): linear between rows, the end rows beyond them, as HydroDyn's
// SetDepthBasedCoefs.
StripCoefficients at_depth(const std::vector<hydrodyn::DepthCoefficients>& rows, double z) {
    const double depth = -z;
    if (depth <= rows.front().depth) return without_growth(rows.front().c);
    if (depth >= rows.back().depth) return without_growth(rows.back().c);
    std::size_t i = 1;
    while (rows[i].depth < depth) ++i;
    const double s = (depth - rows[i - 1].depth) / (rows[i].depth - rows[i - 1].depth);
    const StripCoefficients a = without_growth(rows[i - 1].c), b = without_growth(rows[i].c);
    auto mix = [s](double x, double y) { return (1 - s) * x + s * y; };
    return {mix(a.cd, b.cd),       mix(a.ca, b.ca),       mix(a.cp, b.cp),
            mix(a.ax_cd, b.ax_cd), mix(a.ax_ca, b.ax_ca), mix(a.ax_cp, b.ax_cp)};
}

} // namespace

std::optional<runtime::hydro::StripSetup> strip_setup(const hydrodyn::Input& in,
                                                      const runtime::hydro::Water& water,
                                                      diag::Diagnostics& diags) {
    int errors = 0;
    auto at = [&](int line) { return diag::Location{in.file, line, 1}; };
    auto error = [&](int line, std::string message) {
        ++errors;
        diags.error(Kind::InvalidValue, at(line), std::move(message));
    };
    runtime::hydro::StripSetup setup;
    setup.water = water;
    setup.kinematics_displaced = in.wave_disp != 0;
    if (in.am_mod != 0)
        diags.warning(Kind::NotSupported, in.location("AMMod"),
                      "AMMod " + std::to_string(in.am_mod) +
                          ": the added mass is taken on the nodes below the still-water level "
                          "at the undisplaced position (AMMod 0)");
    auto joint = [&](int id) -> const hydrodyn::Joint* {
        for (const hydrodyn::Joint& j : in.joints)
            if (j.id == id) return &j;
        return nullptr;
    };
    auto section = [&](int id) -> const hydrodyn::CrossSection* {
        for (const hydrodyn::CrossSection& s : in.sections)
            if (s.id == id) return &s;
        return nullptr;
    };
    auto axial = [&](const hydrodyn::Joint& j, StripCoefficients& c, int& model) {
        for (const hydrodyn::AxialCoefficient& a : in.axial) {
            if (a.id != j.axial_coefficient_id) continue;
            c = {0, 0, 0, a.cd, a.ca, a.cp};
            model = a.fd_mod;
            if (a.vn_cutoff > 0)
                diags.warning(Kind::NotSupported, at(a.line),
                              "AxVnCOff: the high-pass filter of the joints' axial flow is not "
                              "modelled (the unfiltered flow is used)");
            return;
        }
        error(j.line, "joint " + std::to_string(j.id) + ": no axial coefficients with AxCoefID " +
                          std::to_string(j.axial_coefficient_id));
    };
    for (const hydrodyn::Joint& j : in.joints)
        if (j.overlap != 0)
            diags.warning(Kind::NotSupported, at(j.line),
                          "JointOvrlp 1 (super members) is not modelled: overlapping members "
                          "are counted each");
    for (const hydrodyn::Member& m : in.members) {
        const std::string which = "member " + std::to_string(m.id);
        const hydrodyn::Joint* j1 = joint(m.joint1);
        const hydrodyn::Joint* j2 = joint(m.joint2);
        const hydrodyn::CrossSection* s1 = section(m.section1);
        const hydrodyn::CrossSection* s2 = section(m.section2);
        if (!j1 || !j2) {
            error(m.line, which + ": no joint with ID " + std::to_string(j1 ? m.joint2 : m.joint1));
            continue;
        }
        if (!s1 || !s2) {
            error(m.line, which + ": no member property set with ID " +
                              std::to_string(s1 ? m.section2 : m.section1));
            continue;
        }
        if (m.section_kind != 1) {
            error(m.line, which + ": rectangular members are not modelled");
            continue;
        }
        if (m.hydrostatic_load_model == 2)
            diags.warning(Kind::NotSupported, at(m.line),
                          which + ": MHstLMod 2 is taken as 1 (the closed-form buoyancy of the "
                                  "submerged frustum)");
        runtime::hydro::StripMember out;
        out.end1 = j1->position;
        out.end2 = j2->position;
        out.diameter1 = s1->diameter;
        out.diameter2 = s2->diameter;
        out.division_size = m.division_size;
        out.potential_flow = m.potential_flow;
        if (out.end1 == out.end2) error(m.line, which + " has no length");
        if (!(s1->diameter > 0) || !(s2->diameter > 0))
            error(m.line, which + ": its diameters must be positive");
        if (!(m.division_size > 0)) error(m.line, which + ": MDivSize must be positive");
        if (std::min(out.end1[2], out.end2[2]) < -water.depth)
            diags.warning(Kind::NotSupported, at(m.line),
                          which + " reaches below the seabed: the part below it is not removed");
        switch (m.coefficient_model) {
        case 1:
            out.c1 = out.c2 = without_growth(in.simple);
            break;
        case 2:
            if (in.depth.empty()) {
                error(m.line, which + ": MCoefMod 2 with no depth-based coefficients");
                break;
            }
            out.c1 = at_depth(in.depth, out.end1[2]);
            out.c2 = at_depth(in.depth, out.end2[2]);
            for (const hydrodyn::DepthCoefficients& d : in.depth) {
                const double lo = -std::max(out.end1[2], out.end2[2]);
                const double hi = -std::min(out.end1[2], out.end2[2]);
                if (d.depth > lo && d.depth < hi) {
                    diags.warning(Kind::NotSupported, at(m.line),
                                  which + ": its coefficients are interpolated linearly between "
                                          "its ends, not at the depth table's rows between them");
                    break;
                }
            }
            break;
        case 3: {
            const auto row = std::find_if(
                in.member_coefficients.begin(), in.member_coefficients.end(),
                [&](const hydrodyn::MemberCoefficients& c) { return c.member_id == m.id; });
            if (row == in.member_coefficients.end()) {
                error(m.line, which + ": MCoefMod 3 with no member-based coefficients for it");
                break;
            }
            out.c1 = without_growth(row->end1);
            out.c2 = without_growth(row->end2);
            break;
        }
        default:
            error(m.line, which + ": MCoefMod must be 1, 2 or 3, not " +
                              std::to_string(m.coefficient_model));
        }
        axial(*j1, out.joint1_axial, out.joint1_drag_model);
        axial(*j2, out.joint2_axial, out.joint2_drag_model);
        setup.members.push_back(out);
    }
    if (errors > 0) return std::nullopt;
    return setup;
}

} // namespace yamsc::analysis
