// The one reader of ElastoDyn tower and blade files (formats/elastodyn/beam_file.hpp):
// each kind's columns and adjustment factors land in the right place, and the beam
// stage (beam/elastodyn.hpp) gives them the beam's axes and twist sign.
#include "beam/elastodyn.hpp"
#include "elastodyn/beam_file.hpp"

#include <cmath>
#include <doctest/doctest.h>

using namespace yamsc;

namespace {

const char* const kTower = R"(------- ELASTODYN TOWER INPUT FILE -------
A tower with distinct factors and columns.
          2   NTwInpSt    - Number of input stations
        2.0   AdjTwMa     - mass factor
        3.0   AdjFASt     - fore-aft stiffness factor
        4.0   AdjSSSt     - side-side stiffness factor
---------------------- DISTRIBUTED TOWER PROPERTIES ----
  HtFract   TMassDen   TwFAStif   TwSSStif
   (-)       (kg/m)     (Nm^2)     (Nm^2)
  0.0       100.0      1000.0     2000.0
  1.0        50.0       500.0      700.0
)";

const char* const kBlade = R"(------- ELASTODYN BLADE INPUT FILE -------
A blade with distinct factors and columns.
          2   NBlInpSt    - Number of input stations
        1.5   AdjBlMs     - mass factor
        2.0   AdjFlSt     - flap stiffness factor
        3.0   AdjEdSt     - edge stiffness factor
---------------------- DISTRIBUTED BLADE PROPERTIES ----
  BlFract  PitchAxis  StrcTwst  BMassDen  FlpStff  EdgStff
   (-)       (-)       (deg)     (kg/m)   (Nm^2)   (Nm^2)
  0.0       0.25      13.3      600.0    1.0E10   2.0E10
  1.0       0.5        0.0       10.0    1.0E6    3.0E6
)";

std::shared_ptr<const diag::SourceFile> source(const char* name, const char* text) {
    return std::make_shared<const diag::SourceFile>(name, text);
}

} // namespace

TEST_CASE("ElastoDyn tower file: columns and factors by kind") {
    diag::Diagnostics diags;
    auto f =
        elastodyn::read_beam_file(elastodyn::BeamKind::tower, source("t.dat", kTower), {}, diags);
    INFO(diags.render());
    REQUIRE(f);
    REQUIRE(f->sections.size() == 2);
    CHECK(f->sections[1].fraction == 1.0);
    CHECK(f->sections[0].mass_per_length == 200.0);
    CHECK(f->sections[0].stiffness_x == 3000.0); // TwFAStif * AdjFASt
    CHECK(f->sections[1].stiffness_y == 2800.0); // TwSSStif * AdjSSSt
    CHECK(f->sections[0].twist_deg == 0.0);
    CHECK(elastodyn::mode_names(elastodyn::BeamKind::tower).size() == 4);

    auto beam = beam::read_elastodyn_tower(source("t.dat", kTower), 80.0, {}, diags);
    REQUIRE(beam);
    CHECK(beam->length == 80.0);
    CHECK(!beam->integrated_shapes);
    CHECK(beam->stations[0].EI_y == 3000.0); // fore-aft: displacement along x
    CHECK(beam->stations[0].EI_x == 8000.0);
    CHECK(!std::signbit(beam->stations[0].twist));
}

TEST_CASE("ElastoDyn blade file: columns and factors by kind, twist about +z") {
    diag::Diagnostics diags;
    auto f =
        elastodyn::read_beam_file(elastodyn::BeamKind::blade, source("b.dat", kBlade), {}, diags);
    INFO(diags.render());
    REQUIRE(f);
    REQUIRE(f->sections.size() == 2);
    CHECK(f->sections[0].mass_per_length == 900.0);
    CHECK(f->sections[0].stiffness_x == 2.0e10); // FlpStff * AdjFlSt
    CHECK(f->sections[1].stiffness_y == 9.0e6);  // EdgStff * AdjEdSt
    CHECK(f->sections[0].twist_deg == 13.3);

    auto beam = beam::read_elastodyn_blade(source("b.dat", kBlade), 61.5, {}, diags);
    REQUIRE(beam);
    CHECK(beam->integrated_shapes);
    CHECK(beam->stations[0].EI_y == 2.0e10);
    CHECK(beam->stations[0].EI_x == 6.0e10);
    CHECK(beam->stations[0].twist == doctest::Approx(-13.3 * std::acos(-1.0) / 180));
}

TEST_CASE("ElastoDyn beam file: the length is the beam stage's, checked before the file") {
    diag::Diagnostics diags;
    CHECK(!beam::read_elastodyn_tower(source("t.dat", kTower), 0.0, {}, diags));
    REQUIRE(diags.error_count() == 1);
    CHECK(diags.render().find("must be > 0") != std::string::npos);
}
