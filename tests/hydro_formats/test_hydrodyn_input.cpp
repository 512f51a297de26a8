// HydroDyn's input file: every entry of the OC3-Hywind files read (OpenFAST v5 and v4.0
// layouts, and the layout before v4.0), the options read but not modelled warned at
// their line, and the errors located at their line and column.
#include "hydrodyn/hydrodyn_input.hpp"
#include "support.hpp"

#include <fstream>
#include <numeric>

using namespace yamsc;
using namespace hydro_test;
using diag::Severity;

namespace {

struct Read {
    std::optional<hydrodyn::Input> input;
    diag::Diagnostics diags;
};

std::unique_ptr<Read> read(const std::string& text) {
    auto r = std::make_unique<Read>();
    auto file = std::make_shared<const diag::SourceFile>("hd.dat", text);
    r->input = hydrodyn::read_hydrodyn_input(file, r->diags, aerodyn::includes_refused());
    return r;
}

/// The one diagnostic of `severity`, at the line holding `line_text` and the column
/// of `col_text` in it, with `message` in its text.
void check_one(const std::string& text, Severity severity, const std::string& line_text,
               const std::string& col_text, const std::string& message) {
    const auto r = read(text);
    const auto found = of(r->diags, severity);
    INFO(r->diags.render());
    REQUIRE(found.size() == 1);
    const int line = line_of(text, line_text);
    CHECK(found[0].loc.line == line);
    // The column of col_text in that line; a '|' in it marks the character meant.
    const auto line_start = text.rfind('\n', text.find(line_text)) + 1;
    std::string plain = col_text;
    const auto mark = plain.find('|');
    if (mark != std::string::npos) plain.erase(mark, 1);
    const auto at = text.find(plain, line_start);
    REQUIRE(at != std::string::npos);
    CHECK(found[0].loc.col ==
          static_cast<int>(at - line_start + (mark == std::string::npos ? 0 : mark)) + 1);
    CHECK(found[0].message.find(message) != std::string::npos);
    if (severity == Severity::warning) CHECK(r->input.has_value());
    if (severity == Severity::error) CHECK(!r->input.has_value());
}

double sum(const std::vector<double>& v) {
    return std::accumulate(v.begin(), v.end(), 0.0);
}

} // namespace

TEST_CASE("the OC3-Hywind strip-theory file (OpenFAST v5 layout): every entry") {
    diag::Diagnostics diags;
    const auto in = hydrodyn::read_hydrodyn_input(
        std::filesystem::path(data_dir + "oc3_spar_strip.dat"), diags);
    INFO(diags.render());
    REQUIRE(in);
    CHECK(diags.all().empty());
    CHECK(in->path == data_dir + "oc3_spar_strip.dat");
    CHECK(in->pot_mod == hydrodyn::PotentialFlow::none);
    CHECK(in->exctn_mod == 0);
    CHECK(in->exctn_disp == 0);
    CHECK(in->exctn_cutoff == 10);
    CHECK(in->ptfm_y_mod == 0);
    CHECK(in->ptfm_ref_y_deg == 0);
    CHECK(in->ptfm_y_cutoff == 0.01);
    CHECK(in->n_exctn_hdg == 36);
    CHECK(in->rdtn_mod == 0);
    CHECK(in->rdtn_tmax == 60);
    CHECK(in->rdtn_dt == 0.0125);
    CHECK(!in->rdtn_dt_default);
    CHECK(in->n_body == 1);
    CHECK(in->n_body_mod == 1);
    CHECK(in->pot_file == std::vector<std::string>{"unused"});
    CHECK(in->wamit_ulen == std::vector<double>{1});
    for (const auto* v : {&in->ptfm_ref_xt, &in->ptfm_ref_yt, &in->ptfm_ref_zt,
                          &in->ptfm_ref_zt_rot, &in->ptfm_cob_xt, &in->ptfm_cob_yt})
        CHECK(*v == std::vector<double>{0});
    CHECK(in->ptfm_vol0 == std::vector<double>{8029.21});
    CHECK(in->n_add_dof == std::vector<int>{0});
    CHECK(in->mn_drift + in->newman_app + in->diff_qtf + in->sum_qtf == 0);
    // The additional matrices, row-major: yaw stiffness, damping on the diagonal.
    CHECK(in->matrix_size == 6);
    CHECK(in->matrix_count == 1);
    CHECK(in->add_f0 == std::vector<double>(6, 0.0));
    REQUIRE(in->add_c_lin.size() == 36);
    CHECK(in->add_c_lin[35] == 98340000);
    CHECK(sum(in->add_c_lin) == 98340000);
    REQUIRE(in->add_b_lin.size() == 36);
    CHECK(in->add_b_lin[0] == 100000);
    CHECK(in->add_b_lin[7] == 100000);
    CHECK(in->add_b_lin[14] == 130000);
    CHECK(in->add_b_lin[35] == 13000000);
    CHECK(sum(in->add_b_lin) == 100000 + 100000 + 130000 + 13000000);
    CHECK(in->add_b_quad == std::vector<double>(36, 0.0));
    CHECK(in->wave_disp == 0);
    CHECK(in->am_mod == 0);
    CHECK(in->hst_mod == 0);
    REQUIRE(in->axial.size() == 1);
    CHECK(in->axial[0].id == 1);
    CHECK(in->axial[0].cd == 0);
    CHECK(in->axial[0].ca == 0);
    CHECK(in->axial[0].cp == 1);
    CHECK(in->axial[0].fd_mod == 0);
    CHECK(in->axial[0].vn_cutoff == 0);
    CHECK(in->axial[0].fd_lo_fsc == 1);
    REQUIRE(in->joints.size() == 4);
    const double z[] = {-120, -12, -4, 10};
    for (int i = 0; i < 4; ++i) {
        CHECK(in->joints[i].id == i + 1);
        CHECK(in->joints[i].position == std::array<double, 3>{0, 0, z[i]});
        CHECK(in->joints[i].axial_coefficient_id == 1);
        CHECK(in->joints[i].overlap == 0);
    }
    const std::string text = file_text("oc3_spar_strip.dat");
    CHECK(in->joints[0].line == line_of(text, "    1     0.00000     0.00000  -120.00000"));
    REQUIRE(in->sections.size() == 2);
    CHECK(in->sections[0].id == 1);
    CHECK(in->sections[0].diameter == 9.4);
    CHECK(in->sections[0].thickness == 0.01);
    CHECK(in->sections[1].id == 2);
    CHECK(in->sections[1].diameter == 6.5);
    CHECK(in->sections[1].line == line_of(text, "    2        6.50000"));
    CHECK(in->rectangular_sections == 0);
    const auto& c = in->simple;
    CHECK(c.cd == 0.6);
    CHECK(c.cd_mg == 0.6);
    CHECK(c.ca == 0.969954);
    CHECK(c.ca_mg == 0.969954);
    CHECK(c.cp == 1);
    CHECK(c.cp_mg == 1);
    CHECK(c.ax_cd == 0);
    CHECK(c.ax_ca == 0);
    CHECK(c.ax_cp == 1);
    CHECK(c.ax_cp_mg == 1);
    CHECK(c.cb == 1);
    CHECK(c.cb_mg == 1);
    CHECK(!c.mcf);
    CHECK(in->depth.empty());
    CHECK(in->member_coefficients.empty());
    REQUIRE(in->members.size() == 3);
    const int joints[3][2] = {{1, 2}, {2, 3}, {3, 4}};
    const int sets[3][2] = {{1, 1}, {1, 2}, {2, 2}};
    for (int i = 0; i < 3; ++i) {
        const auto& m = in->members[i];
        CHECK(m.id == i + 1);
        CHECK(m.joint1 == joints[i][0]);
        CHECK(m.joint2 == joints[i][1]);
        CHECK(m.section1 == sets[i][0]);
        CHECK(m.section2 == sets[i][1]);
        CHECK(m.division_size == 0.5);
        CHECK(m.coefficient_model == 1);
        CHECK(m.section_kind == 1);
        CHECK(m.spin_orientation == 0);
        CHECK(m.hydrostatic_load_model == 1);
        CHECK(!m.potential_flow);
        CHECK(m.line == line_of(text, "    1         1          2           1") + i);
    }
    CHECK(in->fill_groups.empty());
    CHECK(in->marine_growth.empty());
    CHECK(in->member_outputs.empty());
    CHECK(in->joint_outputs.empty());
    CHECK(!in->hd_sum);
    CHECK(!in->out_all);
    CHECK(in->out_switch == 2);
    CHECK(in->out_fmt == "E15.7e2");
    CHECK(in->out_sfmt == "A11");
    // A quoted first word is a list of names, as OpenFAST's GetWords splits it.
    CHECK(in->out_channels == std::vector<std::string>{"HydroFxi", "HydroFyi", "HydroFzi",
                                                       "HydroMxi", "HydroMyi", "HydroMzi",
                                                       "PRPSurge", "PRPSway", "PRPHeave", "PRPRoll",
                                                       "PRPPitch", "PRPYaw"});
    REQUIRE(in->out_channel_lines.size() == in->out_channels.size());
    CHECK(in->out_channel_lines[6] == line_of(text, "\"PRPSurge"));
    CHECK(in->out_channel_lines[8] == line_of(text, "\"PRPSurge"));
    CHECK(in->out_channel_lines[9] == line_of(text, "PRPRoll"));
    // Where the entries are.
    CHECK(in->location("potmod").line == line_of(text, "   PotMod"));
    CHECK(in->location("PotMod").col == 14);
    CHECK(in->location("AddCLin").line == line_of(text, "AddCLin"));
    CHECK(in->location("AddCLin").col == 14);
    CHECK(in->location("NJoints").line == line_of(text, "NJoints"));
    CHECK(in->location("NoSuchKey").line == 0);
}

TEST_CASE("the OC3-Hywind potential-flow file (OpenFAST v4.0 layout)") {
    const auto r = read(file_text("oc3_spar_wamit.dat"));
    INFO(r->diags.render());
    REQUIRE(r->input);
    CHECK(r->diags.all().empty());
    const auto& in = *r->input;
    CHECK(in.pot_mod == hydrodyn::PotentialFlow::wamit);
    CHECK(in.exctn_mod == 1);
    CHECK(in.rdtn_mod == 1);
    CHECK(in.pot_file == std::vector<std::string>{"spar"});
    CHECK(in.ptfm_vol0 == std::vector<double>{8029.21});
    CHECK(in.n_add_dof.empty()); // v4.0 has no NAddDOF
    CHECK(in.hst_mod == 0);      // nor HstMod
    CHECK(in.add_c_lin[35] == 98340000);
    CHECK(in.add_b_lin[14] == 130000);
    // Five axial columns: HydroDyn's defaults for the two left out.
    REQUIRE(in.axial.size() == 1);
    CHECK(in.axial[0].fd_mod == 0);
    CHECK(in.axial[0].vn_cutoff == -1);
    CHECK(in.axial[0].fd_lo_fsc == 1);
    CHECK(in.sections.size() == 2);
    CHECK(in.simple.cd == 0.6);
    CHECK(in.simple.ca == 0);
    CHECK(in.simple.cb == 1);
    REQUIRE(in.members.size() == 3);
    for (const auto& m : in.members) {
        CHECK(m.potential_flow);
        CHECK(m.hydrostatic_load_model == 1);
        CHECK(m.section_kind == 1);
    }
    CHECK(in.members[2].section1 == 2);
    CHECK(in.hd_sum);
    // Unquoted, a line gives its first word only (OpenFAST reads one item).
    CHECK(in.out_channels == std::vector<std::string>{"HydroFxi", "HydroFzi", "B1Surge"});
}

TEST_CASE("the layout before OpenFAST v4.0: no yaw-offset entries, 12 simple coefficients, "
          "8-column members, 4 axial columns") {
    std::string t = file_text("oc3_spar_wamit.dat");
    for (const char* key : {"PtfmYMod", "PtfmRefY ", "PtfmYCutOff", "NExctnHdg"}) {
        const int line = line_of(t, key);
        std::size_t start = 0;
        for (int i = 1; i < line; ++i) start = t.find('\n', start) + 1;
        t.erase(start, t.find('\n', start) - start + 1);
    }
    t = replaced(t, "    1     0.00     0.00     1.00      0\n",
                 "    1     0.00     0.20     1.00\n");
    t = replaced(t, "1.00        1.00       1.00       1.00\n", "1.00        1.00\n");
    t = replaced(
        t,
        "    2         2          3           1            2        0.5000      1         1        "
        "TRUE",
        "    2         2          3           1            2        0.2500      2        T");
    t = replaced(t, "0   NCoefDpth ", "1   NCoefDpth ");
    t = replaced(t, "---------------------- MEMBER-BASED",
                 "-30  0.7 0.7 0.8 0.8 1 1 0 0 0 0 1 1\n---------------------- MEMBER-BASED");
    const auto r = read(t);
    INFO(r->diags.render());
    REQUIRE(r->input);
    const auto& in = *r->input;
    CHECK(in.ptfm_y_mod == 0);
    CHECK(in.axial[0].ca == 0.2);
    CHECK(in.axial[0].fd_mod == 0);
    CHECK(in.axial[0].vn_cutoff == -1);
    CHECK(in.simple.ax_cp_mg == 1);
    CHECK(in.simple.cb == 1); // not in the row: HydroDyn's 1
    REQUIRE(in.depth.size() == 1);
    CHECK(in.depth[0].depth == -30);
    CHECK(in.depth[0].c.cd == 0.7);
    CHECK(in.depth[0].c.ca_mg == 0.8);
    CHECK(in.depth[0].c.ax_cp_mg == 1);
    REQUIRE(in.members.size() == 3);
    CHECK(in.members[1].division_size == 0.25);
    CHECK(in.members[1].coefficient_model == 2);
    CHECK(in.members[1].hydrostatic_load_model == 0);
    CHECK(in.members[1].potential_flow);
    CHECK(in.members[0].hydrostatic_load_model == 1);
}

TEST_CASE("tables with rows: depth-based and member-based coefficients, fill groups, marine "
          "growth, output lists") {
    std::string t = file_text("oc3_spar_strip.dat");
    t = replaced(t, "0   NCoefDpthCyl", "2   NCoefDpthCyl");
    t = replaced(t, "---------------------- DEPTH-BASED RECTANGULAR",
                 "-120 0.6 0.7 0.9 1.0 1 1 0 0 0 0 1 1 1 1\n"
                 "0    0.5 0.6 0.8 0.9 1 1 0.1 0.2 0.3 0.4 1 1 0.9 0.8\n"
                 "---------------------- DEPTH-BASED RECTANGULAR");
    t = replaced(t, "0   NCoefMembersCyl", "1   NCoefMembersCyl");
    t = replaced(t, "---------------------- MEMBER-BASED RECTANGULAR",
                 "2  0.61 0.62 0.63 0.64 0.91 0.92 0.93 0.94 1 1 1 1 0.01 0.02 0.03 0.04 0.05 "
                 "0.06 0.07 0.08 1.1 1.2 1.3 1.4 0.95 0.96 0.97 0.98\n"
                 "---------------------- MEMBER-BASED RECTANGULAR");
    t = replaced(t,
                 "    2         2          3           1            2           1         0        "
                 " 0.5000      1",
                 "    2         2          3           1            2           1         0        "
                 " 0.5000      3");
    t = replaced(t, "0   NFillGroups", "1   NFillGroups");
    t = replaced(t, "(-)      (-)                   (m)           (kg/m^3)\n",
                 "(-)      (-)                   (m)           (kg/m^3)\n2  1 2  -50  DEFAULT\n");
    t = replaced(t, "0   NMGDepths", "1   NMGDepths");
    t = replaced(t, "(m)        (m)         (kg/m^3)\n",
                 "(m)        (m)         (kg/m^3)\n-20 0.05 1100\n");
    t = replaced(t, "0   NMOutputs", "1   NMOutputs");
    t = replaced(t, "NodeLocs\n  (-)        (-)        (-)\n",
                 "NodeLocs\n  (-)        (-)        (-)\n3  2  0.0  0.5\n");
    t = replaced(t, "0   NJOutputs", "2   NJOutputs");
    t = replaced(t, "0   JOutLst", "1, 4   JOutLst");
    const auto r = read(t);
    INFO(r->diags.render());
    REQUIRE(r->input);
    const auto& in = *r->input;
    REQUIRE(in.depth.size() == 2);
    CHECK(in.depth[0].depth == -120);
    CHECK(in.depth[0].c.ca_mg == 1.0);
    CHECK(in.depth[1].depth == 0);
    CHECK(in.depth[1].c.cd == 0.5);
    CHECK(in.depth[1].c.ax_cd == 0.1);
    CHECK(in.depth[1].c.ax_ca_mg == 0.4);
    CHECK(in.depth[1].c.cb == 0.9);
    CHECK(in.depth[1].c.cb_mg == 0.8);
    REQUIRE(in.member_coefficients.size() == 1);
    const auto& m = in.member_coefficients[0];
    CHECK(m.member_id == 2);
    CHECK(m.end1.cd == 0.61);
    CHECK(m.end2.cd == 0.62);
    CHECK(m.end1.cd_mg == 0.63);
    CHECK(m.end2.cd_mg == 0.64);
    CHECK(m.end1.ca == 0.91);
    CHECK(m.end2.ca_mg == 0.94);
    CHECK(m.end1.ax_cd == 0.01);
    CHECK(m.end2.ax_ca_mg == 0.08);
    CHECK(m.end1.ax_cp == 1.1);
    CHECK(m.end2.ax_cp_mg == 1.4);
    CHECK(m.end1.cb == 0.95);
    CHECK(m.end2.cb_mg == 0.98);
    CHECK(in.members[1].coefficient_model == 3);
    REQUIRE(in.fill_groups.size() == 1);
    CHECK(in.fill_groups[0].members == std::vector<int>{1, 2});
    CHECK(in.fill_groups[0].free_surface == -50);
    CHECK(in.fill_groups[0].density_default);
    REQUIRE(in.marine_growth.size() == 1);
    CHECK(in.marine_growth[0].depth == -20);
    CHECK(in.marine_growth[0].thickness == 0.05);
    CHECK(in.marine_growth[0].density == 1100);
    REQUIRE(in.member_outputs.size() == 1);
    CHECK(in.member_outputs[0].member_id == 3);
    CHECK(in.member_outputs[0].locations == std::vector<double>{0.0, 0.5});
    CHECK(in.joint_outputs == std::vector<int>{1, 4});
    // Filled members, marine growth, member and joint outputs: read, warned.
    const auto w = of(r->diags, Severity::warning);
    REQUIRE(w.size() == 4);
    CHECK(w[0].loc.line == line_of(t, "NFillGroups"));
    CHECK(w[0].message.find("filled members") != std::string::npos);
    CHECK(w[1].loc.line == line_of(t, "NMGDepths"));
    CHECK(w[1].message.find("marine growth") != std::string::npos);
    CHECK(w[2].loc.line == line_of(t, "NMOutputs"));
    CHECK(w[3].loc.line == line_of(t, "NJOutputs"));
}

TEST_CASE("options read but not modelled: a warning at the entry's value") {
    const std::string strip = file_text("oc3_spar_strip.dat");
    const std::string wamit = file_text("oc3_spar_wamit.dat");
    using S = Severity;
    check_one(replaced(strip, "             0   PotMod", "             2   PotMod"), S::warning,
              "   PotMod", "2", "PotMod 2");
    check_one(replaced(strip, "             0   PtfmYMod", "             1   PtfmYMod"), S::warning,
              "PtfmYMod", "1", "PtfmYMod 1");
    for (const char* key : {"MnDrift", "NewmanApp", "DiffQTF", "SumQTF"}) {
        CAPTURE(key);
        const std::string line = std::string("             0   ") + key;
        check_one(replaced(wamit, line, std::string("            12   ") + key), S::warning, key,
                  "12", "second-order");
    }
    check_one(replaced(strip, "             0   AMMod", "             2   AMMod"), S::warning,
              "AMMod", "2", "AMMod 2");
    check_one(replaced(strip, "             0   HstMod", "             1   HstMod"), S::warning,
              "HstMod", "1", "HstMod 1");
    check_one(replaced(strip,
                       "1.00        1.00        0.00        0.00        0.00        0.00        "
                       "1.00        1.00       1.00       1.00",
                       "MCF         MCF         0.00        0.00        0.00        0.00        "
                       "1.00        1.00       1.00       1.00"),
              S::warning, "MCF         MCF", "MCF", "MacCamy-Fuchs");
    {
        // NBody 2 with uncoupled bodies: two files, two of every vector, two 6x6 matrices.
        std::string t = replaced(wamit, "             1   NBody", "             2   NBody");
        t = replaced(t, "             1   NBodyMod", "             2   NBodyMod");
        t = replaced(t, "\"spar\"           PotFile", "\"spar\" \"buoy\"   PotFile");
        for (const char* key : {"WAMITULEN", "PtfmRefxt", "PtfmRefyt", "PtfmRefzt", "PtfmRefztRot",
                                "PtfmCOBxt", "PtfmCOByt"})
            t = replaced(t,
                         std::string("             ") +
                             (std::string(key) == "WAMITULEN" ? "1" : "0") + "   " + key,
                         std::string("          ") +
                             (std::string(key) == "WAMITULEN" ? "1, 2" : "0, 7") + "   " + key);
        t = replaced(t, "       8029.21   PtfmVol0", "   8029.21 100   PtfmVol0");
        std::string rows;
        for (int i = 0; i < 6; ++i) rows += "0 " + std::to_string(i + 1) + "\n";
        t = replaced(t,
                     "             0   AddF0          - Additional preload (N, N-m)\n             "
                     "0\n             0\n             0\n             0\n             0\n",
                     "0 1 AddF0\n1 2\n2 3\n3 4\n4 5\n5 6\n");
        for (const char* key : {"AddCLin", "AddBLin", "AddBQuad"}) {
            const auto at = t.find(key);
            const auto start = t.rfind('\n', at) + 1;
            std::string block;
            for (int i = 0; i < 6; ++i) {
                for (int k = 0; k < 12; ++k)
                    block += std::to_string(k < 6 ? i * 6 + k : 100 + i * 6 + k - 6) + " ";
                block += i == 0 ? std::string(key) + "\n" : "\n";
            }
            std::size_t end = start;
            for (int i = 0; i < 6; ++i) end = t.find('\n', end) + 1;
            t.replace(start, end - start, block);
        }
        check_one(t, S::warning, "NBody ", "2", "NBody > 1");
        const auto r = read(t);
        REQUIRE(r->input);
        const auto& in = *r->input;
        CHECK(in.pot_file == std::vector<std::string>{"spar", "buoy"});
        CHECK(in.wamit_ulen == std::vector<double>{1, 2});
        CHECK(in.ptfm_ref_xt == std::vector<double>{0, 7});
        CHECK(in.ptfm_vol0 == std::vector<double>{8029.21, 100});
        CHECK(in.matrix_size == 6);
        CHECK(in.matrix_count == 2);
        REQUIRE(in.add_f0.size() == 12);
        CHECK(in.add_f0[5] == 5);  // body 1, row 6
        CHECK(in.add_f0[6] == 1);  // body 2, row 1
        CHECK(in.add_f0[11] == 6); // body 2, row 6
        REQUIRE(in.add_b_quad.size() == 72);
        CHECK(in.add_b_quad[7] == 7);        // body 1: (1, 1)
        CHECK(in.add_b_quad[36 + 7] == 107); // body 2: (1, 1)
        CHECK(in.add_b_quad[36 + 35] == 135);
    }
    {
        // One generalized DOF: 7 rows of 7.
        std::string t = replaced(strip, "             0   NAddDOF", "             1   NAddDOF");
        t = replaced(
            t, "             0   AddF0          - Additional preload (N, N-m)\n",
            "             0   AddF0          - Additional preload (N, N-m)\n             0\n");
        for (const char* key : {"AddCLin", "AddBLin", "AddBQuad"}) {
            const auto at = t.find(key);
            const auto start = t.rfind('\n', at) + 1;
            std::string block;
            for (int i = 0; i < 7; ++i) {
                for (int k = 0; k < 7; ++k) block += i == k ? "7 " : "0 ";
                block += i == 0 ? std::string(key) + "\n" : "\n";
            }
            std::size_t end = start;
            for (int i = 0; i < 6; ++i) end = t.find('\n', end) + 1;
            t.replace(start, end - start, block);
        }
        check_one(t, S::warning, "NAddDOF", "1", "NAddDOF > 0");
        const auto r = read(t);
        REQUIRE(r->input);
        CHECK(r->input->matrix_size == 7);
        CHECK(r->input->add_c_lin.size() == 49);
        CHECK(r->input->add_c_lin[48] == 7);
        CHECK(sum(r->input->add_b_quad) == 49);
    }
    {
        std::string t = replaced(strip, "0   NPropSetsRec", "1   NPropSetsRec");
        t = replaced(t, "   (-)        (m)           (m)          (m)\n",
                     "   (-)        (m)           (m)          (m)\n    7   2  3  0.01\n");
        check_one(t, S::warning, "NPropSetsRec", "1", "rectangular members");
        t = replaced(t, "    3         3          4           2            2           1 ",
                     "    3         3          4           7            7           2 ");
        const auto r = read(t);
        INFO(r->diags.render());
        REQUIRE(r->input);
        CHECK(r->input->rectangular_sections == 1);
        CHECK(r->input->members[2].section_kind == 2);
        REQUIRE(of(r->diags, S::warning).size() == 2);
        CHECK(of(r->diags, S::warning)[1].loc.line ==
              line_of(t, "    3         3          4           7"));
    }
}

TEST_CASE("errors at their line and column, with the entry's name") {
    const std::string strip = file_text("oc3_spar_strip.dat");
    using S = Severity;
    check_one(replaced(strip, "             0   PotMod", "             3   PotMod"), S::error,
              "   PotMod", "3", "'PotMod' must be 0, 1 or 2");
    check_one(replaced(strip, "             0   PotMod", "             x   PotMod"), S::error,
              "   PotMod", "x", "'PotMod' must be an integer");
    check_one(replaced(strip, "             4   NJoints", "        200000   NJoints"), S::error,
              "NJoints", "200000", "'NJoints' must be 0 to 100000");
    check_one(replaced(strip, "             4   NJoints", "             4   NJoint "), S::error,
              "NJoint ", "4", "expected the entry 'NJoints' here");
    check_one(replaced(strip, "             1   NBody ", "             0   NBody "), S::error,
              "NBody ", "0", "'NBody' must be 1 to 100");
    check_one(replaced(strip, "    2     0.00000     0.00000   -12.00000",
                       "    2     0.00000     0.0q000   -12.00000"),
              S::error, "0.0q000", "0.0q000",
              "joints row 2: value 3 must be a number, not '0.0q000'");
    check_one(replaced(strip,
                       "        100000             0             0             0             0     "
                       "        0   AddBLin",
                       "        100000             0             0   AddBLin"),
              S::error, "100000             0             0   AddBLin", "AddBLin",
              "AddBLin row 1: value 4 must be a number, not 'AddBLin'");
    check_one(replaced(strip,
                       "    3         3          4           2            2           1         0  "
                       "       0.5000      1         1        FALSE",
                       "    3         3          9           2            2           1         0  "
                       "       0.5000      1         1        FALSE"),
              S::error, "    3         3          9", "9",
              "member 3 names joint 9, which the file does not define");
    check_one(replaced(strip,
                       "    3         3          4           2            2           1         0  "
                       "       0.5000      1",
                       "    3         3          4           2            5           1         0  "
                       "       0.5000      1"),
              S::error, "    3         3          4           2            5", "2            |5",
              "names property set 5");
    check_one(replaced(strip,
                       "    3         3          4           2            2           1         0  "
                       "       0.5000      1",
                       "    3         3          4           2            2           1         0  "
                       "       0.5000      4"),
              S::error,
              "    3         3          4           2            2           1         0         "
              "0.5000      4",
              "0.5000      |4", "MCoefMod must be 1, 2 or 3");
    check_one(replaced(strip, "0.5000      1         1        FALSE\n    3",
                       "0.5000      1         1        7\n    3"),
              S::error, "0.5000      1         1        7", "0.5000",
              "PropPot (True or False) expected");
    check_one(replaced(strip, "    3         3          4           2",
                       "    2         3          4           2"),
              S::error, "    2         3          4           2", "    |2",
              "member 2 is defined twice (line " +
                  std::to_string(line_of(strip, "    2         2          3           1")) + ")");
    check_one(replaced(strip, "    4     0.00000     0.00000    10.00000      1",
                       "    4     0.00000     0.00000    10.00000      2"),
              S::error, "    4     0.00000     0.00000    10.00000      2", "10.00000      |2",
              "names axial coefficients 2");
    check_one(replaced(strip, "       0.60        0.60    0.969954    0.969954        1.00 ",
                       "       0.60        0.60    0.969954    0.969954        MCF  "),
              S::error, "0.969954        MCF", "MCF", "MCF is used at some but not all");
}

TEST_CASE("errors that end the reading: a file of OpenFAST v3, a file cut short") {
    const std::string strip = file_text("oc3_spar_strip.dat");
    const std::string v3 = replaced(
        strip, "---------------------- FLOATING PLATFORM ---------------------------------------\n",
        "--- ENVIRONMENTAL CONDITIONS\n\"default\"   WtrDens - Water density\n");
    const auto r = read(v3);
    const auto errors = of(r->diags, Severity::error);
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].loc.line == line_of(v3, "WtrDens"));
    CHECK(errors[0].message.find("OpenFAST v3") != std::string::npos);

    const std::string cut =
        strip.substr(0, strip.find("    3     0.00000     0.00000    -4.00000"));
    const auto c = read(cut);
    const auto e = of(c->diags, Severity::error);
    REQUIRE(e.size() == 1);
    CHECK(e[0].loc.line == line_of(cut, "    2     0.00000") + 1); // the end of the file
    CHECK(e[0].message == "the file ends before joints row 3");
    CHECK(!c->input);

    // No END line: a warning at the end of the file, the channels kept.
    const std::string no_end = strip.substr(0, strip.find("END of output"));
    const auto n = read(no_end);
    REQUIRE(n->input);
    CHECK(n->input->out_channels.size() == 12);
    REQUIRE(of(n->diags, Severity::warning).size() == 1);
    CHECK(of(n->diags, Severity::warning)[0].message.find("END") != std::string::npos);
}

TEST_CASE("the fuzz seeds are files the reader accepts (tables with rows; before v4.0)") {
    const std::string seeds = std::string(YAMSC_SOURCE_DIR) + "/tests/fuzz/seeds/hydrodyn/";
    for (const char* name : {"tables.dat", "before_v4.dat"}) {
        CAPTURE(name);
        diag::Diagnostics diags;
        const auto in = hydrodyn::read_hydrodyn_input(std::filesystem::path(seeds + name), diags);
        INFO(diags.render());
        REQUIRE(in);
        CHECK(of(diags, Severity::error).empty());
        CHECK(in->members.size() == 3);
    }
}

TEST_CASE("more located errors: a member on one joint, MDivSize, NBodyMod, a member-based row "
          "for no member") {
    const std::string strip = file_text("oc3_spar_strip.dat");
    const std::string member3 =
        "    3         3          4           2            2           1         0         0.5000";
    {
        const std::string t = replaced(strip, member3,
                                       "    3         3          3           2            2        "
                                       "   1         0         0.5000");
        const auto r = read(t);
        const auto e = of(r->diags, Severity::error);
        REQUIRE(e.size() == 1);
        CHECK(e[0].loc.line == line_of(t, "    3         3          3"));
        CHECK(e[0].loc.col == 26);
        CHECK(e[0].message == "member 3 joins joint 3 to itself");
    }
    {
        const std::string t = replaced(strip, member3,
                                       "    3         3          4           2            2        "
                                       "   1         0         0.0000");
        const auto r = read(t);
        const auto e = of(r->diags, Severity::error);
        REQUIRE(e.size() == 1);
        CHECK(e[0].loc.line == line_of(t, "0.0000      1"));
        CHECK(e[0].loc.col == col_of(t, "0.0000      1"));
        CHECK(e[0].message == "members row 3: MDivSize must be positive");
    }
    {
        const std::string t =
            replaced(strip, "             1   NBodyMod", "             4   NBodyMod");
        const auto r = read(t);
        const auto e = of(r->diags, Severity::error);
        REQUIRE(e.size() == 1);
        CHECK(e[0].loc.line == line_of(t, "NBodyMod"));
        CHECK(e[0].loc.col == 14);
        CHECK(e[0].message == "'NBodyMod' must be 1, 2 or 3");
    }
    {
        std::string t = replaced(strip, "0   NCoefMembersCyl", "1   NCoefMembersCyl");
        t = replaced(t, "---------------------- MEMBER-BASED RECTANGULAR",
                     "9  0.6 0.6 0.6 0.6 1 1 1 1 1 1 1 1 0 0 0 0 0 0 0 0 1 1 1 1 1 1 1 1\n"
                     "---------------------- MEMBER-BASED RECTANGULAR");
        const auto r = read(t);
        const auto e = of(r->diags, Severity::error);
        REQUIRE(e.size() == 1);
        CHECK(e[0].loc.line == line_of(t, "9  0.6 0.6"));
        CHECK(e[0].loc.col == 1);
        CHECK(e[0].message ==
              "member-based coefficients for member 9, which the file does not define");
    }
}

TEST_CASE("rows from a file an '@' line includes: read, and their errors located in it") {
    const std::string dir = std::string(YAMSC_TEST_BINARY_DIR) + "/hydro_formats_include/";
    std::filesystem::create_directories(dir);
    std::string main = file_text("oc3_spar_strip.dat");
    const std::string rows = "    1         1          2           1            1           1      "
                             "   0         0.5000      1         1        FALSE\n"
                             "    2         2          3           1            2           1      "
                             "   0         0.5000      1         1        FALSE\n"
                             "    3         3          7           2            2           1      "
                             "   0         0.5000      1         1        FALSE\n";
    const auto first = main.find("    1         1          2           1");
    const auto last = main.find("---------------------- FILLED MEMBERS");
    main.replace(first, last - first, "@members.inc\n");
    {
        std::ofstream(dir + "hd.dat") << main;
        std::ofstream(dir + "members.inc") << rows;
    }
    diag::Diagnostics diags;
    const auto in = hydrodyn::read_hydrodyn_input(std::filesystem::path(dir + "hd.dat"), diags);
    CHECK(!in);
    const auto e = of(diags, Severity::error);
    REQUIRE(e.size() == 1);
    REQUIRE(e[0].loc.file);
    CHECK(e[0].loc.file->path() == dir + "members.inc");
    CHECK(e[0].loc.line == 3);
    CHECK(e[0].loc.col == 26);
    CHECK(e[0].message == "member 3 names joint 7, which the file does not define");
}
