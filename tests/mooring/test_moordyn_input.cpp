// MoorDyn's input file: every field of the OC3-Hywind lines read, the lines equal
// to those of the MAP++ file of the same system, and the errors located.
#include "analysis/map_mooring.hpp"
#include "analysis/moordyn_mooring.hpp"
#include "diag/read_text.hpp"
#include "moordyn/moordyn_input.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <string>

using namespace yamsc;

namespace {

const analysis::MooringEnvironment oc3{320, 1025, 9.80665};

const std::string data_dir = std::string(YAMSC_SOURCE_DIR) + "/tests/data/mooring/";
const std::string moordyn_path = data_dir + "oc3_hywind_moordyn.dat";

std::string file_text(const std::string& path) {
    diag::Diagnostics diags;
    const auto f = diag::read_text_file(path, diags);
    REQUIRE(f);
    return f->text();
}

std::optional<std::vector<runtime::mooring::Line>>
lines_of(const std::string& text, diag::Diagnostics& diags,
         const analysis::MooringEnvironment& env = oc3) {
    auto file = std::make_shared<const diag::SourceFile>("moor.dat", text);
    const auto in = moordyn::read_moordyn_input(file, diags);
    if (!in) return std::nullopt;
    return analysis::moordyn_lines(*in, env, diags);
}

std::string diagnostics_of(const std::string& text) {
    diag::Diagnostics diags;
    lines_of(text, diags);
    return diags.render();
}

bool has(const std::string& rendered, const std::string& message) {
    const bool found = rendered.find(message) != std::string::npos;
    if (!found) MESSAGE(rendered.substr(0, 600));
    return found;
}

std::string replaced(std::string text, const std::string& what, const std::string& with) {
    const auto at = text.find(what);
    REQUIRE(at != std::string::npos);
    return text.replace(at, what.size(), with);
}

} // namespace

TEST_CASE("the OC3-Hywind MoorDyn file: every field read") {
    diag::Diagnostics diags;
    auto file = diag::read_text_file(moordyn_path, diags);
    REQUIRE(file);
    const auto in = moordyn::read_moordyn_input(file, diags);
    INFO(diags.render());
    REQUIRE(in);
    CHECK(diags.render().empty());
    REQUIRE(in->line_types.size() == 1);
    const moordyn::LineType& t = in->line_types[0];
    CHECK(t.name == "chain");
    CHECK(t.diameter == 0.09);
    CHECK(t.mass_density == 77.7066);
    CHECK(t.axial_stiffness == 384.243e6);
    CHECK(t.stiffness_values == 1);
    CHECK(t.internal_damping == -1.0);
    CHECK(t.bending_stiffness == 0.0);
    CHECK(t.drag_normal == 1.2);
    CHECK(t.added_mass_normal == 1.0);
    CHECK(t.drag_axial == 0.2);
    CHECK(t.added_mass_axial == 0.0);
    CHECK(t.lift == 0.0);
    CHECK(t.at.line == 6);
    REQUIRE(in->points.size() == 6);
    for (int k = 0; k < 6; ++k) {
        const moordyn::Point& p = in->points[k];
        CHECK(p.id == k + 1);
        CHECK(p.attachment == (k < 3 ? moordyn::Attachment::fixed : moordyn::Attachment::coupled));
        CHECK(p.z == (k < 3 ? -320.0 : -70.0));
        CHECK(!p.on_seabed);
        CHECK(p.mass == 0);
        CHECK(p.volume == 0);
        CHECK(p.drag_area == 0);
        CHECK(p.added_mass == 0);
        CHECK(p.at.line == 10 + k);
    }
    CHECK(in->points[1].x == -426.935);
    CHECK(in->points[1].y == -739.4731);
    CHECK(in->points[5].y == 4.5033);
    REQUIRE(in->lines.size() == 3);
    for (int k = 0; k < 3; ++k) {
        const moordyn::LineRow& l = in->lines[k];
        CHECK(l.id == k + 1);
        CHECK(l.type == "chain");
        CHECK(!l.end_a.rod);
        CHECK(l.end_a.number == k + 1);
        CHECK(l.end_b.number == k + 4);
        CHECK(l.unstretched_length == 902.2);
        CHECK(l.segments == 20);
        CHECK(l.outputs == "-");
    }
    CHECK(in->options.size() == 10);
    CHECK(in->options_at.line == 22);
    CHECK(in->time_step == 0.002);
    CHECK(in->water_depth == 320.0);
    CHECK(in->water_density == 1025.0);
    CHECK(in->gravity == 9.80665);
    CHECK(in->seabed_stiffness == 3.0e6);
    CHECK(in->seabed_damping == 3.0e5);
    CHECK(in->options[9].name == "THRESHIC");
    CHECK(in->options[9].value == "0.001");
    const std::vector<std::string> outputs = {"FairTen1", "FairTen2", "FairTen3",
                                              "AnchTen1", "AnchTen2", "AnchTen3"};
    CHECK(in->outputs == outputs);
    // Cl (VIV) as an 11th value, Z on the seabed by keyword.
    auto other = std::make_shared<const diag::SourceFile>(
        "moor.dat",
        replaced(replaced(file->text(), "0.2    0.0\n", "0.2    0.0  0.8\n"), "-320.0", "Seabed"));
    const auto in2 = moordyn::read_moordyn_input(other, diags);
    REQUIRE(in2);
    CHECK(in2->line_types[0].lift == 0.8);
    CHECK(in2->points[0].on_seabed);
    CHECK(!in2->points[1].on_seabed);
}

TEST_CASE("the OC3-Hywind MoorDyn file gives the lines of the MAP++ file, and the published "
          "restoring matrix") {
    diag::Diagnostics diags;
    const auto lines = analysis::read_moordyn_mooring(moordyn_path, oc3, diags);
    const auto map_lines = analysis::read_map_mooring(data_dir + "oc3_hywind.map", oc3, diags);
    REQUIRE(lines);
    REQUIRE(map_lines);
    // The one warning: the lines run quasi-static, at the OPTIONS header.
    CHECK(has(diags.render(), "oc3_hywind_moordyn.dat:22:1: warning: MoorDyn's lines run here "
                              "quasi-static"));
    REQUIRE(lines->size() == 3);
    REQUIRE(map_lines->size() == 3);
    const double d = 0.09;
    for (std::size_t k = 0; k < 3; ++k) {
        const runtime::mooring::Line& a = (*lines)[k];
        const runtime::mooring::Line& b = (*map_lines)[k];
        CHECK(a.anchor == b.anchor);
        CHECK(a.fairlead == b.fairlead);
        CHECK(a.properties.length == b.properties.length);
        CHECK(a.properties.axial_stiffness == b.properties.axial_stiffness);
        CHECK(a.properties.seabed_friction == b.properties.seabed_friction);
        // MoorDyn's pi is acos(-1); MAP++'s is 3.14159264: the weights differ by
        // g rho (pi - pi_MAP) d^2 / 4 (4e-10 relative), and by nothing else.
        const double pi_difference = 9.80665 * 1025 * (M_PI - 3.14159264) * d * d / 4;
        const double w = a.properties.weight_in_fluid;
        CHECK(std::abs(b.properties.weight_in_fluid - pi_difference - w) < 1e-12 * w);
        CHECK(std::abs(w - 9.80665 * (77.7066 - 1025 * M_PI * d * d / 4)) < 1e-12 * w);
    }
    // Jonkman, NREL/TP-500-47535, section 5.2, as tests/mooring/test_mooring_system.cpp.
    const auto m = runtime::mooring::mooring_loads(*lines, {});
    CHECK(-m.derivative[0] == doctest::Approx(41180).epsilon(0.002));
    CHECK(-m.derivative[6 * 2 + 2] == doctest::Approx(11940).epsilon(0.002));
    CHECK(-m.derivative[6 * 3 + 3] == doctest::Approx(311100000).epsilon(0.002));
    CHECK(-m.derivative[6 * 5 + 5] == doctest::Approx(11560000).epsilon(0.002));
    CHECK(-m.derivative[6 * 0 + 4] == doctest::Approx(-2816000).epsilon(0.002));
    CHECK(-m.force[2] == doctest::Approx(1607000).epsilon(0.001));
}

TEST_CASE("MoorDyn's options win over the glue code's environment, which fills what they omit") {
    const std::string good = file_text(moordyn_path);
    const analysis::MooringEnvironment other{200, 1000, 9.8};
    diag::Diagnostics diags;
    const auto own = lines_of(good, diags, other);
    REQUIRE(own);
    const double d = 0.09;
    const double w = 9.80665 * (77.7066 - 1025 * M_PI * d * d / 4);
    CHECK(std::abs((*own)[0].properties.weight_in_fluid - w) < 1e-12 * w);
    std::string bare = replaced(good, "320.0     WtrDpth", "!");
    bare = replaced(bare, "1025.0    rhoW", "!");
    bare = replaced(bare, "9.80665   g  ", "!");
    bare = replaced(bare, "-320.0", "seabed"); // point 1 at the environment's depth
    for (int k = 0; k < 2; ++k) bare = replaced(bare, "-320.0", "-200.0");
    const auto env = lines_of(bare, diags, other);
    INFO(diags.render());
    REQUIRE(env);
    const double w_env = 9.8 * (77.7066 - 1000 * M_PI * d * d / 4);
    CHECK(std::abs((*env)[0].properties.weight_in_fluid - w_env) < 1e-12 * w_env);
    CHECK((*env)[0].anchor[2] == -200.0);
    CHECK((*env)[2].anchor[2] == -200.0);
}

TEST_CASE("MoorDyn files with errors: each at its line and column, naming its entry") {
    const std::string good = file_text(moordyn_path);
    CHECK(diagnostics_of(good).find("error") == std::string::npos);
    CHECK(has(diagnostics_of(replaced(good, "384.243E6", "384.243Q6")),
              "moor.dat:6:31: error: EA of line type 'chain' is not a number: '384.243Q6'"));
    CHECK(has(diagnostics_of(replaced(good, "384.243E6  ", "384.243E6|1e9")),
              "moor.dat:6:1: error: the visco-elastic EA of line type 'chain' is not supported"));
    CHECK(has(diagnostics_of(replaced(good, "0.0    1.2", "1.2")),
              "moor.dat:6:1: error: a LINE TYPES row has 10, 11 or 13 values"));
    CHECK(has(diagnostics_of(replaced(good, "1    Fixed ", "1    Fixd  ")),
              "moor.dat:10:6: error: unknown attachment 'Fixd' of point 1 (Fixed, Vessel, "
              "Coupled, Free, Body<n> or Turbine<n>) (did you mean 'Fixed'?)"));
    CHECK(has(diagnostics_of(replaced(good, "4    Vessel", "4    Free  ")),
              "moor.dat:13:6: error: Free point 4 is not supported: each line must run from a "
              "Fixed point"));
    CHECK(has(diagnostics_of(replaced(good, "6    Vessel       -2.6        4.5033      -70.0    0",
                                      "6    Vessel       -2.6        4.5033      -70.0    9")),
              "moor.dat:15:1: error: the mass and volume of point 6 are not supported"));
    CHECK(has(diagnostics_of(
                  replaced(good, "-70.0    0     0     0     0\n5", "-70.0    0     0     0\n5")),
              "moor.dat:13:1: error: a POINTS row has 9 values (ID Attachment X Y Z M V CdA Ca), "
              "found 8"));
    CHECK(has(diagnostics_of(replaced(good, "5    Vessel", "7    Vessel")),
              "moor.dat:14:1: error: point 7 is out of order: MoorDyn numbers its points 1, 2, "
              "... (expected 5)"));
    CHECK(has(diagnostics_of(replaced(good, "-320.0   0     0     0     0\n3",
                                      "-300.0   0     0     0     0\n3")),
              "moor.dat:11:43: error: anchor point 2 is not on the seabed"));
    CHECK(has(diagnostics_of(replaced(good, "2    chain ", "2    chian ")),
              "moor.dat:20:6: error: unknown line type 'chian' of line 2 (did you mean 'chain'?)"));
    CHECK(has(diagnostics_of(
                  replaced(good, "3    chain      3         6", "3    chain      3         7")),
              "moor.dat:21:27: error: no point 7 for line 3 (the file has 6)"));
    CHECK(has(diagnostics_of(
                  replaced(good, "3    chain      3         6", "3    chain      3         R1A")),
              "moor.dat:21:27: error: no rod 1 for line 3 (the file has 0)"));
    CHECK(has(diagnostics_of(
                  replaced(good, "3    chain      3         6", "3    chain      3         Q6 ")),
              "moor.dat:21:27: error: the end of line 3 is neither a point"));
    CHECK(has(diagnostics_of(
                  replaced(good, "3    chain      3         6", "3    chain      4         6")),
              "moor.dat:21:17: error: line 3 must run from a Fixed point to a Vessel or Coupled "
              "point (it joins Vessel point 4 to Vessel point 6)"));
    CHECK(has(diagnostics_of(replaced(good, "902.2      20 ", "902.2      0.5")),
              "moor.dat:19:48: error: NumSegs of line 1 must be a whole number from 1 to 10000"));
    CHECK(has(diagnostics_of(replaced(good, "0.002     dtM ", "0.002     dtMM")),
              "moor.dat:23:11: warning: unknown MoorDyn option 'dtMM' (ignored) (did you mean "
              "'DTM'?)"));
    CHECK(has(diagnostics_of(replaced(good, "320.0     WtrDpth", "bathy.txt WtrDpth")),
              "moor.dat:24:1: error: a bathymetry file as the water depth is not read: "
              "'bathy.txt'"));
    CHECK(has(diagnostics_of(replaced(good, "1025.0    rhoW", "1O25.0    rhoW")),
              "moor.dat:25:1: error: the value of option rhoW is not a number: '1O25.0'"));
    CHECK(has(diagnostics_of(replaced(good, "0.001     threshIC", "0.3     mu_kT")),
              "moor.dat:32:9: warning: MoorDyn's seabed friction (mu_kT, mu_kA) acts on its "
              "dynamic lines only"));
    const std::string bodies = replaced(good, "---------------------- POINTS",
                                        "---------------------- BODIES ---\nID Attachment\n"
                                        "(-) (-)\n1 coupled 0 0 0\n---------------------- POINTS");
    CHECK(has(diagnostics_of(bodies),
              "moor.dat:10:1: error: bodies are not supported: MoorDyn's lines are converted "
              "alone ('1')"));
    CHECK(has(diagnostics_of(replaced(good, "---------------------- OPTIONS",
                                      "---------------------- FAILURE ---\nx\n"
                                      "---------------------- OPTIONS")),
              "moor.dat:22:1: warning: this MoorDyn section is not read"));
    CHECK(has(diagnostics_of(replaced(good, "4    Vessel", "4    Body1 ")),
              "moor.dat:13:6: error: no body 1 for point 4 (the file has 0)"));
    CHECK(has(diagnostics_of(replaced(good, "4    Vessel", "4    T2    ")),
              "moor.dat:13:6: error: Turbine point 4 is not supported"));
    CHECK(has(diagnostics_of(replaced(good, "0.0    1.2   1.0   0.2    0.0",
                                      "0.0    1.2   1.0   0.2    0.0  0.7  0.1")),
              "moor.dat:6:1: error: a LINE TYPES row has 10, 11 or 13 values"));
    std::string many;
    for (int k = 0; k <= moordyn::max_rows; ++k) many += "FairTen1\n";
    CHECK(has(diagnostics_of(replaced(good, "AnchTen1\n", many)),
              "moor.dat:10032:1: error: more than 10000 entries in a section of a MoorDyn file"));
}

TEST_CASE("MoorDyn v1's layout: the same lines, its count lines checked") {
    const std::string v1_path = data_dir + "oc3_hywind_moordyn_v1.dat";
    diag::Diagnostics diags;
    auto file = diag::read_text_file(v1_path, diags);
    REQUIRE(file);
    const auto in = moordyn::read_moordyn_input(file, diags);
    INFO(diags.render());
    REQUIRE(in);
    CHECK(in->layout == 1);
    REQUIRE(in->line_types.size() == 1);
    CHECK(in->line_types[0].added_mass_normal == 1.0);
    CHECK(in->line_types[0].added_mass_axial == 0.0);
    CHECK(in->line_types[0].drag_normal == 1.2);
    CHECK(in->line_types[0].drag_axial == 0.2);
    CHECK(in->points.size() == 6);
    CHECK(in->outputs.size() == 3);
    const auto lines = analysis::read_moordyn_mooring(v1_path, oc3, diags);
    const auto v2 = analysis::read_moordyn_mooring(moordyn_path, oc3, diags);
    REQUIRE(lines);
    REQUIRE(v2);
    REQUIRE(lines->size() == 3);
    for (std::size_t k = 0; k < 3; ++k) {
        CHECK((*lines)[k].anchor == (*v2)[k].anchor);
        CHECK((*lines)[k].fairlead == (*v2)[k].fairlead);
        CHECK((*lines)[k].properties.length == (*v2)[k].properties.length);
        CHECK((*lines)[k].properties.axial_stiffness == (*v2)[k].properties.axial_stiffness);
        CHECK((*lines)[k].properties.weight_in_fluid == (*v2)[k].properties.weight_in_fluid);
    }
    const std::string good = file_text(v1_path);
    CHECK(has(diagnostics_of(replaced(good, "3        NLines", "4        NLines")),
              "moor.dat:20:1: error: the table announces 4 rows and holds 3"));
    CHECK(has(diagnostics_of(replaced(good,
                                      "4    Vessel  5.2         0.0         -70.0    0     0"
                                      "     0 ",
                                      "4    Vessel  5.2         0.0         -70.0    0     0"
                                      "     9 ")),
              "moor.dat:16:1: error: the forces (FX, FY, FZ) on point 4 are not supported"));
    CHECK(has(diagnostics_of(replaced(good, "4    Vessel", "4    Connect")),
              "moor.dat:16:6: error: Free point 4 is not supported"));
}
