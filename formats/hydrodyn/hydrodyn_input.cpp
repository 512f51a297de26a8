#include "hydrodyn/hydrodyn_input.hpp"

#include "diag/read_text.hpp"
#include "hydrodyn/entries.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace yamsc::hydrodyn {

using aerodyn::Entry;
using diag::Kind;

namespace {

/// One row of a coefficient table: `full` values (OpenFAST v4: with Cb, CbMG), or
/// `older` values (the files before), where the 0-based columns `mcf` may hold the
/// keyword MCF (MacCamy-Fuchs) instead of a number, all of them or none.
struct CoefficientRow {
    std::vector<double> v;
    bool mcf = false;
    bool full = false;
    const aerodyn::Line* line = nullptr;
};

class Reader {
public:
    Reader(aerodyn::Cursor& c, Input& out)
        : r_(c, out.entries), d_(c.diags()), out_(out), errors_at_start_(d_.error_count()) {}

    void read() {
        r_.cursor().skip_header(2);
        r_.need("Echo");
        if (!platform()) return;
        if (read_sections(*this,
                          {&Reader::second_order, &Reader::additional_matrices,
                           &Reader::strip_options, &Reader::axial, &Reader::joints,
                           &Reader::sections, &Reader::coefficients, &Reader::members,
                           &Reader::filled_members, &Reader::marine_growth, &Reader::output_lists,
                           &Reader::outputs},
                          d_, errors_at_start_))
            check_references();
    }

private:
    // ---- FLOATING PLATFORM ------------------------------------------------------
    bool platform() {
        if (r_.next_holds(1, "WtrDens") || r_.next_holds(1, "WaveMod")) {
            d_.error(Kind::InvalidValue, r_.cursor().here(),
                     "a HydroDyn file of OpenFAST v3 (waves and water inside): OpenFAST v4 "
                     "reads them from SeaState's file; write this file in the v4 format");
            return false;
        }
        if (auto e = r_.need("PotMod")) {
            int v = 0;
            r_.set(e, v);
            if (v < 0 || v > 2) d_.error(Kind::InvalidValue, e->at(), "'PotMod' must be 0, 1 or 2");
            out_.pot_mod = static_cast<PotentialFlow>(std::clamp(v, 0, 2));
            if (out_.pot_mod == PotentialFlow::fit)
                r_.unsupported(e->at(), "PotMod 2 (fluid-impulse theory)");
        }
        r_.set(r_.need("ExctnMod"), out_.exctn_mod);
        r_.set(r_.maybe("ExctnDisp"), out_.exctn_disp);
        r_.set(r_.maybe("ExctnCutOff"), out_.exctn_cutoff);
        if (auto e = r_.maybe("PtfmYMod")) {
            r_.set(e, out_.ptfm_y_mod);
            if (out_.ptfm_y_mod != 0) r_.unsupported(e->at(), "PtfmYMod 1 (large yaw offsets)");
        }
        r_.set(r_.maybe("PtfmRefY"), out_.ptfm_ref_y_deg);
        r_.set(r_.maybe("PtfmYCutOff"), out_.ptfm_y_cutoff);
        r_.set(r_.maybe("NExctnHdg"), out_.n_exctn_hdg);
        r_.set(r_.need("RdtnMod"), out_.rdtn_mod);
        r_.set(r_.need("RdtnTMax"), out_.rdtn_tmax);
        if (auto e = r_.need("RdtnDT")) {
            std::optional<double> dt;
            r_.set_or_default(e, dt);
            out_.rdtn_dt_default = aerodyn::is_default(e->value());
            out_.rdtn_dt = dt.value_or(0.0);
        }
        const auto bodies = r_.count("NBody", 1, max_bodies);
        if (bodies) out_.n_body = *bodies;
        if (auto e = r_.need("NBodyMod")) {
            r_.set(e, out_.n_body_mod);
            if (out_.n_body_mod < 1 || out_.n_body_mod > 3)
                d_.error(Kind::InvalidValue, e->at(), "'NBodyMod' must be 1, 2 or 3");
        }
        if (!bodies) return true;
        if (out_.n_body > 1 && out_.pot_mod == PotentialFlow::wamit)
            r_.unsupported(out_.location("NBody"), "NBody > 1 (several WAMIT bodies)");
        const std::size_t n = static_cast<std::size_t>(out_.n_body);
        const std::size_t objects = out_.n_body_mod == 1 ? 1 : n;
        if (auto v = r_.row("PotFile", objects, "PotFile"))
            for (const auto& t : v->tokens) out_.pot_file.push_back(t.text);
        vector("WAMITULEN", objects, out_.wamit_ulen);
        vector("PtfmRefxt", n, out_.ptfm_ref_xt);
        vector("PtfmRefyt", n, out_.ptfm_ref_yt);
        vector("PtfmRefzt", n, out_.ptfm_ref_zt);
        vector("PtfmRefztRot", n, out_.ptfm_ref_zt_rot);
        vector("PtfmVol0", n, out_.ptfm_vol0);
        vector("PtfmCOBxt", n, out_.ptfm_cob_xt);
        vector("PtfmCOByt", n, out_.ptfm_cob_yt);
        if (r_.next_holds(n, "NAddDOF")) {
            if (auto v = r_.row("NAddDOF", n, "NAddDOF"))
                for (std::size_t i = 0; i < n; ++i) {
                    const int k = r_.integer(*v, i, "NAddDOF").value_or(0);
                    if (k < 0 || k > max_added_dofs)
                        d_.error(Kind::Limit, v->at(i),
                                 "NAddDOF must be 0 to " + std::to_string(max_added_dofs));
                    else if (k > 0)
                        r_.unsupported(v->at(i), "NAddDOF > 0 (generalized body modes)");
                    out_.n_add_dof.push_back(std::clamp(k, 0, max_added_dofs));
                }
        }
        return true;
    }

    void vector(const char* key, std::size_t n, std::vector<double>& into) {
        if (auto v = r_.numbers(key, n, key)) into = *v;
    }

    // ---- 2ND-ORDER FLOATING PLATFORM FORCES ----------------------------------------
    void second_order() {
        for (auto [key, field] :
             {std::pair{"MnDrift", &out_.mn_drift}, std::pair{"NewmanApp", &out_.newman_app},
              std::pair{"DiffQTF", &out_.diff_qtf}, std::pair{"SumQTF", &out_.sum_qtf}}) {
            auto e = r_.need(key);
            r_.set(e, *field);
            if (e && *field != 0)
                r_.unsupported(e->at(), std::string(key) + " (second-order wave forces)");
        }
    }

    // ---- PLATFORM ADDITIONAL STIFFNESS AND DAMPING ----------------------------------
    void additional_matrices() {
        const int objects = out_.n_body_mod == 1 ? 1 : out_.n_body;
        const int added = out_.n_add_dof.empty() ? 0 : out_.n_add_dof.front();
        const int size =
            out_.n_body == 1 ? 6 + added : 6 * (out_.n_body_mod == 1 ? out_.n_body : 1);
        out_.matrix_size = size;
        out_.matrix_count = objects;
        const auto rows = static_cast<std::size_t>(size);
        const auto count = static_cast<std::size_t>(objects);
        out_.add_f0.assign(rows * count, 0.0);
        for (std::size_t i = 0; i < rows; ++i) {
            auto v =
                r_.numbers("AddF0 row " + std::to_string(i + 1), count, i == 0 ? "AddF0" : nullptr);
            if (!v) return;
            for (std::size_t j = 0; j < count; ++j) out_.add_f0[j * rows + i] = (*v)[j];
        }
        for (auto [key, m] :
             {std::pair{"AddCLin", &out_.add_c_lin}, std::pair{"AddBLin", &out_.add_b_lin},
              std::pair{"AddBQuad", &out_.add_b_quad}}) {
            m->assign(rows * rows * count, 0.0);
            for (std::size_t i = 0; i < rows; ++i) {
                auto v = r_.numbers(std::string(key) + " row " + std::to_string(i + 1),
                                    rows * count, i == 0 ? key : nullptr);
                if (!v) return;
                for (std::size_t j = 0; j < count; ++j)
                    for (std::size_t k = 0; k < rows; ++k)
                        (*m)[j * rows * rows + i * rows + k] = (*v)[j * rows + k];
            }
        }
    }

    // ---- STRIP THEORY OPTIONS ---------------------------------------------------------
    void strip_options() {
        r_.set(r_.need("WaveDisp"), out_.wave_disp);
        if (auto e = r_.need("AMMod")) {
            r_.set(e, out_.am_mod);
            if (out_.am_mod != 0)
                r_.unsupported(e->at(),
                               "AMMod " + std::to_string(out_.am_mod) +
                                   " (added mass up to the free surface); AMMod 0 is used");
        }
        if (auto e = r_.maybe("HstMod")) {
            r_.set(e, out_.hst_mod);
            if (out_.hst_mod != 0)
                r_.unsupported(e->at(),
                               "HstMod " + std::to_string(out_.hst_mod) +
                                   " (hydrostatics up to the free surface); HstMod 0 is used");
        }
    }

    /// A table's count, then its two lines of names and units.
    std::optional<int> table(const char* key) {
        auto n = r_.count(key, 0, max_rows);
        if (!n || !r_.skip(2, std::string("the column names and units under '") + key + "'"))
            return std::nullopt;
        return n;
    }
    std::optional<int> table_either(const char* newer, const char* older) {
        if (r_.cursor().peek() && r_.next_holds(1, newer)) return table(newer);
        return table(older);
    }

    // ---- AXIAL COEFFICIENTS -------------------------------------------------------------
    void axial() {
        const auto n = table("NAxCoef");
        for (int i = 0; n && i < *n; ++i) {
            // As HydroDyn: 7 values, else 5 (no AxVnCOff, AxFDLoFSc), else 4 (no AxFDMod).
            const std::size_t have = r_.leading_numbers();
            const std::size_t width = have >= 7 ? 7 : have >= 5 ? 5 : 4;
            const std::string what = "axial coefficients row " + std::to_string(i + 1);
            auto v = r_.row(what, width);
            if (!v) return;
            AxialCoefficient a;
            a.line = v->line->number;
            a.id = r_.integer(*v, 0, what, true).value_or(0);
            a.cd = r_.number(*v, 1, what).value_or(0);
            a.ca = r_.number(*v, 2, what).value_or(0);
            a.cp = r_.number(*v, 3, what).value_or(0);
            if (width >= 5) a.fd_mod = r_.integer(*v, 4, what, true).value_or(0);
            if (width == 7) {
                a.vn_cutoff = r_.number(*v, 5, what).value_or(0);
                a.fd_lo_fsc = r_.number(*v, 6, what).value_or(0);
            }
            out_.axial.push_back(a);
        }
    }

    // ---- MEMBER JOINTS --------------------------------------------------------------------
    void joints() {
        const auto n = table("NJoints");
        for (int i = 0; n && i < *n; ++i) {
            const std::string what = "joints row " + std::to_string(i + 1);
            auto v = r_.row(what, 6);
            if (!v) return;
            Joint j;
            j.line = v->line->number;
            j.id = r_.integer(*v, 0, what, true).value_or(0);
            for (std::size_t k = 0; k < 3; ++k)
                j.position[k] = r_.number(*v, k + 1, what).value_or(0);
            j.axial_coefficient_id = r_.integer(*v, 4, what, true).value_or(0);
            j.overlap = r_.integer(*v, 5, what, true).value_or(0);
            out_.joints.push_back(j);
            rows_.joints.push_back(v->line);
        }
    }

    // ---- MEMBER CROSS-SECTION PROPERTIES ------------------------------------------------
    void sections() {
        rectangular_ = r_.cursor().peek() && r_.next_holds(1, "NPropSetsCyl");
        const auto n = table_either("NPropSetsCyl", "NPropSets");
        for (int i = 0; n && i < *n; ++i) {
            const std::string what = "member property sets row " + std::to_string(i + 1);
            auto v = r_.numbers(what, 3);
            if (!v) return;
            out_.sections.push_back(
                {static_cast<int>(std::nearbyint((*v)[0])), (*v)[1], (*v)[2], r_.last_line()});
            rows_.sections.push_back(r_.last_row());
        }
        if (!rectangular_) return;
        const auto rec = table("NPropSetsRec");
        if (rec && *rec > 0) r_.unsupported(out_.location("NPropSetsRec"), "rectangular members");
        for (int i = 0; rec && i < *rec; ++i)
            if (!r_.numbers("rectangular property sets row " + std::to_string(i + 1), 4)) return;
        if (rec) out_.rectangular_sections = *rec;
    }

    // ---- HYDRODYNAMIC COEFFICIENTS (models 1, 2, 3) --------------------------------------
    std::optional<CoefficientRow> coefficient_row(const std::string& what, std::size_t full,
                                                  std::size_t older,
                                                  std::initializer_list<std::size_t> mcf) {
        const aerodyn::Line* l = r_.cursor().peek();
        std::size_t have = 0;
        if (l)
            while (have < l->tokens.size() &&
                   (elastodyn::parse_number(l->tokens[have].text) ||
                    (std::find(mcf.begin(), mcf.end(), have) != mcf.end() &&
                     elastodyn::same_key(l->tokens[have].text, "MCF"))))
                ++have;
        const std::size_t width = have >= full ? full : older;
        auto v = r_.row(what, width);
        if (!v) return std::nullopt;
        CoefficientRow row;
        row.line = v->line;
        row.full = width == full;
        int keywords = 0;
        for (std::size_t i = 0; i < width; ++i) {
            const bool allowed = std::find(mcf.begin(), mcf.end(), i) != mcf.end();
            if (allowed && elastodyn::same_key(v->tokens[i].text, "MCF")) {
                ++keywords;
                row.v.push_back(1.0);
                continue;
            }
            auto x = r_.number(*v, i, what);
            if (!x) return std::nullopt;
            row.v.push_back(*x);
        }
        if (keywords != 0 && keywords != static_cast<int>(mcf.size())) {
            d_.error(Kind::InvalidValue, v->at(*mcf.begin()),
                     what + ": MCF is used at some but not all of its places");
            return std::nullopt;
        }
        row.mcf = keywords > 0;
        if (row.mcf) r_.unsupported(v->at(*mcf.begin()), "MCF (MacCamy-Fuchs diffraction)");
        return row;
    }

    /// Cd, CdMG, Ca, CaMG, Cp, CpMG, AxCd, AxCdMG, AxCa, AxCaMG, AxCp, AxCpMG[, Cb, CbMG]
    /// from `v` starting at `at`, every `stride`-th value (2 for the member table's ends).
    static Coefficients coefficients_from(const CoefficientRow& row, std::size_t at,
                                          std::size_t stride) {
        Coefficients c;
        double* fields[] = {&c.cd,    &c.cd_mg,    &c.ca,       &c.ca_mg, &c.cp,
                            &c.cp_mg, &c.ax_cd,    &c.ax_cd_mg, &c.ax_ca, &c.ax_ca_mg,
                            &c.ax_cp, &c.ax_cp_mg, &c.cb,       &c.cb_mg};
        const std::size_t n = row.full ? 14 : 12;
        for (std::size_t k = 0; k < n; ++k) *fields[k] = row.v[at + k * stride];
        c.mcf = row.mcf;
        return c;
    }

    void coefficients() {
        if (!r_.skip(2, "the names and units of the simple coefficients")) return;
        if (auto row = coefficient_row("simple coefficients", 14, 12, {4, 5}))
            out_.simple = coefficients_from(*row, 0, 1);
        if (rectangular_) {
            if (!r_.skip(2, "the names and units of the simple rectangular coefficients")) return;
            coefficient_row("simple rectangular coefficients", 18, 18, {8, 9});
        }
        const auto depths = table_either("NCoefDpthCyl", "NCoefDpth");
        for (int i = 0; depths && i < *depths; ++i) {
            auto row = coefficient_row("depth-based coefficients row " + std::to_string(i + 1), 15,
                                       13, {5, 6});
            if (!row) return;
            out_.depth.push_back({row->v[0], coefficients_from(*row, 1, 1), row->line->number});
        }
        if (rectangular_) {
            const auto n = table("NCoefDpthRec");
            for (int i = 0; n && i < *n; ++i)
                if (!coefficient_row("depth-based rectangular coefficients row " +
                                         std::to_string(i + 1),
                                     19, 19, {9, 10}))
                    return;
        }
        const auto members = table_either("NCoefMembersCyl", "NCoefMembers");
        for (int i = 0; members && i < *members; ++i) {
            const std::string what = "member-based coefficients row " + std::to_string(i + 1);
            auto row = coefficient_row(what, 29, 25, {9, 10, 11, 12});
            if (!row) return;
            MemberCoefficients m;
            m.member_id = static_cast<int>(std::nearbyint(row->v[0]));
            m.end1 = coefficients_from(*row, 1, 2);
            m.end2 = coefficients_from(*row, 2, 2);
            m.line = row->line->number;
            out_.member_coefficients.push_back(m);
            rows_.member_coefficients.push_back(row->line);
        }
        if (rectangular_) {
            const auto n = table("NCoefMembersRec");
            for (int i = 0; n && i < *n; ++i)
                if (!coefficient_row("member-based rectangular coefficients row " +
                                         std::to_string(i + 1),
                                     37, 37, {17, 18, 19, 20}))
                    return;
        }
    }

    // ---- MEMBERS ------------------------------------------------------------------------------
    void members() {
        const auto n = table("NMembers");
        for (int i = 0; n && i < *n; ++i) {
            const std::string what = "members row " + std::to_string(i + 1);
            // PropPot, the LOGICAL, tells the version: after 7 values (before OpenFAST
            // v4), 8 (v4.0: MHstLMod) or 10 (v4.1: MSecGeom, MSpinOrient).
            const aerodyn::Line* l = r_.cursor().peek();
            std::size_t pot = 0;
            for (std::size_t k : {7u, 8u, 10u})
                if (l && k < l->tokens.size() && !elastodyn::parse_number(l->tokens[k].text) &&
                    parse_logical(l->tokens[k].text)) {
                    pot = k;
                    break;
                }
            if (pot == 0) {
                if (l)
                    d_.error(Kind::InvalidValue,
                             l->at(std::min<int>(7, static_cast<int>(l->tokens.size()))),
                             what + ": PropPot (True or False) expected after MCoefMod");
                else
                    r_.row(what, 8);
                return;
            }
            auto v = r_.row(what, pot + 1);
            if (!v) return;
            Member m;
            m.line = v->line->number;
            std::size_t k = 0;
            for (int* f : {&m.id, &m.joint1, &m.joint2, &m.section1, &m.section2})
                *f = r_.integer(*v, k++, what).value_or(0);
            if (pot == 10) {
                m.section_kind = r_.integer(*v, k++, what).value_or(1);
                m.spin_orientation = r_.number(*v, k++, what).value_or(0);
                if (m.section_kind == 2) r_.unsupported(v->at(5), "a rectangular member");
            }
            m.division_size = r_.number(*v, k++, what).value_or(0);
            if (auto c = r_.integer(*v, k, what)) {
                m.coefficient_model = *c;
                if (*c < 1 || *c > 3)
                    d_.error(Kind::InvalidValue, v->at(k), what + ": MCoefMod must be 1, 2 or 3");
            }
            ++k;
            if (pot >= 8) m.hydrostatic_load_model = r_.integer(*v, k++, what).value_or(0);
            m.potential_flow = r_.logical(*v, pot, what).value_or(false);
            if (m.division_size <= 0)
                d_.error(Kind::InvalidValue, v->at(pot == 10 ? 7 : 5),
                         what + ": MDivSize must be positive");
            out_.members.push_back(m);
            rows_.members.push_back(v->line);
        }
    }

    // ---- FILLED MEMBERS ------------------------------------------------------------------------
    void filled_members() {
        const auto n = table("NFillGroups");
        if (n && *n > 0) r_.unsupported(out_.location("NFillGroups"), "filled members");
        for (int i = 0; n && i < *n; ++i) {
            const std::string what = "filled groups row " + std::to_string(i + 1);
            const aerodyn::Line* l = r_.cursor().peek();
            auto count = l ? elastodyn::parse_number(l->tokens[0].text) : std::nullopt;
            std::size_t m = 0;
            if (count && *count >= 0 && *count <= max_rows && *count == std::floor(*count))
                m = static_cast<std::size_t>(*count);
            else if (l) {
                d_.error(Kind::InvalidValue, l->at(0),
                         what + ": FillNumM must be a count of members, not '" + l->tokens[0].text +
                             "'");
                return;
            }
            auto v = r_.row(what, m + 3);
            if (!v) return;
            FillGroup g;
            g.line = v->line->number;
            for (std::size_t k = 1; k <= m; ++k)
                g.members.push_back(r_.integer(*v, k, what).value_or(0));
            g.free_surface = r_.number(*v, m + 1, what).value_or(0);
            g.density_default = aerodyn::is_default(v->tokens[m + 2].text);
            if (!g.density_default) g.density = r_.number(*v, m + 2, what).value_or(0);
            out_.fill_groups.push_back(std::move(g));
        }
    }

    // ---- MARINE GROWTH
    // -----------------------------------------------------------------------------
    void marine_growth() {
        const auto n = table("NMGDepths");
        if (n && *n > 0) r_.unsupported(out_.location("NMGDepths"), "marine growth");
        for (int i = 0; n && i < *n; ++i) {
            auto v = r_.numbers("marine growth row " + std::to_string(i + 1), 3);
            if (!v) return;
            out_.marine_growth.push_back({(*v)[0], (*v)[1], (*v)[2], r_.last_line()});
        }
    }

    // ---- MEMBER and JOINT OUTPUT LISTS
    // --------------------------------------------------------------
    void output_lists() {
        const auto n = table("NMOutputs");
        if (n && *n > 0) r_.unsupported(out_.location("NMOutputs"), "member outputs");
        for (int i = 0; n && i < *n; ++i) {
            const std::string what = "member outputs row " + std::to_string(i + 1);
            const aerodyn::Line* l = r_.cursor().peek();
            auto count = l && l->tokens.size() > 1 ? elastodyn::parse_number(l->tokens[1].text)
                                                   : std::nullopt;
            if (l && (!count || *count < 0 || *count > max_rows || *count != std::floor(*count))) {
                d_.error(Kind::InvalidValue, l->at(1), what + ": NOutLoc must be a count");
                return;
            }
            auto v = r_.row(what, 2 + static_cast<std::size_t>(count.value_or(0)));
            if (!v) return;
            MemberOutput o;
            o.line = v->line->number;
            o.member_id = r_.integer(*v, 0, what).value_or(0);
            for (std::size_t k = 2; k < v->tokens.size(); ++k)
                o.locations.push_back(r_.number(*v, k, what).value_or(0));
            out_.member_outputs.push_back(std::move(o));
        }
        const auto joints = r_.count("NJOutputs", 0, max_rows);
        if (!joints) return;
        if (*joints == 0) {
            r_.skip(1, "the JOutLst line");
            return;
        }
        r_.unsupported(out_.location("NJOutputs"), "joint outputs");
        if (auto v = r_.row("JOutLst", static_cast<std::size_t>(*joints), "JOutLst"))
            for (std::size_t k = 0; k < v->tokens.size(); ++k)
                out_.joint_outputs.push_back(r_.integer(*v, k, "JOutLst").value_or(0));
    }

    // ---- OUTPUT
    // ------------------------------------------------------------------------------------
    void outputs() {
        r_.set(r_.need("HDSum"), out_.hd_sum);
        r_.set(r_.need("OutAll"), out_.out_all);
        r_.set(r_.need("OutSwtch"), out_.out_switch);
        r_.set(r_.need("OutFmt"), out_.out_fmt);
        r_.set(r_.need("OutSFmt"), out_.out_sfmt);
        if (d_.error_count() != errors_at_start_) return;
        r_.out_channels(out_.out_channels, out_.out_channel_lines);
    }

    // ---- references between the tables
    // --------------------------------------------------------------
    void check_references() {
        std::map<int, int> joint_rows, section_rows, member_rows;
        std::set<int> axial_ids;
        auto unique = [&](std::map<int, int>& seen, int id, const aerodyn::Line* line,
                          const char* what) {
            if (!seen.emplace(id, line->number).second)
                d_.error(Kind::DuplicateName, line->at(0),
                         std::string(what) + " " + std::to_string(id) + " is defined twice (line " +
                             std::to_string(seen[id]) + ")");
        };
        for (const auto& a : out_.axial) axial_ids.insert(a.id);
        for (std::size_t i = 0; i < out_.joints.size(); ++i) {
            const Joint& j = out_.joints[i];
            unique(joint_rows, j.id, rows_.joints[i], "joint");
            if (!axial_ids.count(j.axial_coefficient_id))
                d_.error(Kind::UnknownName, rows_.joints[i]->at(4),
                         "joint " + std::to_string(j.id) + " names axial coefficients " +
                             std::to_string(j.axial_coefficient_id) +
                             ", which no AxCoefID defines");
        }
        for (std::size_t i = 0; i < out_.sections.size(); ++i)
            unique(section_rows, out_.sections[i].id, rows_.sections[i], "property set");
        for (std::size_t i = 0; i < out_.members.size(); ++i) {
            const Member& m = out_.members[i];
            const aerodyn::Line* row = rows_.members[i];
            unique(member_rows, m.id, row, "member");
            auto refer = [&](std::map<int, int>& rows, int id, int column, const char* what) {
                if (rows.count(id) || (m.section_kind == 2 && column >= 3)) return;
                d_.error(Kind::UnknownName, row->at(column),
                         "member " + std::to_string(m.id) + " names " + what + " " +
                             std::to_string(id) + ", which the file does not define");
            };
            refer(joint_rows, m.joint1, 1, "joint");
            refer(joint_rows, m.joint2, 2, "joint");
            refer(section_rows, m.section1, 3, "property set");
            refer(section_rows, m.section2, 4, "property set");
            if (m.joint1 == m.joint2 && joint_rows.count(m.joint1))
                d_.error(Kind::InvalidValue, row->at(2),
                         "member " + std::to_string(m.id) + " joins joint " +
                             std::to_string(m.joint1) + " to itself");
        }
        for (std::size_t i = 0; i < out_.member_coefficients.size(); ++i)
            if (!member_rows.count(out_.member_coefficients[i].member_id))
                d_.error(Kind::UnknownName, rows_.member_coefficients[i]->at(0),
                         "member-based coefficients for member " +
                             std::to_string(out_.member_coefficients[i].member_id) +
                             ", which the file does not define");
    }

    EntryReader r_;
    diag::Diagnostics& d_;
    Input& out_;
    bool rectangular_ = false; // OpenFAST v4.1's tables of rectangular members follow
    /// The lines of the rows kept, for errors at their columns (an included file's too).
    struct {
        std::vector<const aerodyn::Line*> joints, sections, members, member_coefficients;
    } rows_;
    int errors_at_start_ = 0;
};

} // namespace

std::optional<Input> read_hydrodyn_input(const std::shared_ptr<const diag::SourceFile>& file,
                                         diag::Diagnostics& diags,
                                         const aerodyn::IncludeReader& includes) {
    return read_entries<Input, Reader>(file, diags, includes);
}

std::optional<Input> read_hydrodyn_input(const std::filesystem::path& path,
                                         diag::Diagnostics& diags) {
    auto file = diag::read_text_file(path.string(), diags);
    if (!file) return std::nullopt;
    return read_hydrodyn_input(file, diags);
}

} // namespace yamsc::hydrodyn
