// The generic reader of ElastoDyn-style files: values, keys, tables, located errors.
#include "elastodyn/file.hpp"

#include <doctest/doctest.h>

using namespace yamsc;

namespace {

const char* const kText =
    R"(------- ELASTODYN v1.03.* INPUT FILE ------------------------------------------
A title line.
---------------------- SIMULATION CONTROL --------------------------------------
False         Echo        - Echo input data to "<RootName>.ech" (flag)
       6.3D+01   TipRad      - The distance from the rotor apex to the blade tip (meters)
"../nrel 5mw/Tower.dat"    TwrFile     - Name of the file
          3   NumBl       - Number of blades (-)
      abc     HubRad      - a broken value
       True   FlapDOF1    - First flapwise blade mode DOF (flag)
---------------------- DISTRIBUTED PROPERTIES ----------------------------------
  HtFract  TMassDen
   (-)      (kg/m)
0.0        1.0
1.0        2.0E+00
---------------------- END -----------------------------------------------------
)";

elastodyn::ElastoDynFile file() {
    return elastodyn::ElastoDynFile(std::make_shared<diag::SourceFile>("main.dat", kText));
}

} // namespace

TEST_CASE("ElastoDyn file: values by key") {
    diag::Diagnostics diags;
    const elastodyn::ElastoDynFile f = file();
    CHECK(f.get_bool("Echo", diags) == false);
    CHECK(f.get_bool("FlapDOF1", diags) == true);
    CHECK(f.get_double("TipRad", diags) == 63.0); // Fortran exponent
    CHECK(f.get_double("tiprad", diags) == 63.0); // keys are case-insensitive
    CHECK(f.get_string("TwrFile", diags) == "../nrel 5mw/Tower.dat");
    CHECK(f.get_int("NumBl", diags) == 3);
    CHECK(f.has("NumBl"));
    CHECK(!f.has("TMassDen(1)"));
    CHECK(diags.all().empty());
}

TEST_CASE("ElastoDyn file: bad and missing values are located") {
    diag::Diagnostics diags;
    const elastodyn::ElastoDynFile f = file();
    CHECK(!f.get_double("HubRad", diags));
    REQUIRE(diags.all().size() == 1);
    CHECK(diags.all()[0].kind == diag::Kind::InvalidValue);
    CHECK(diags.all()[0].loc.line == 8);
    CHECK(diags.all()[0].loc.col == 7);
    CHECK(diags.all()[0].message.find("abc") != std::string::npos);

    CHECK(!f.get_double("PreCone(1)", diags));
    REQUIRE(diags.all().size() == 2);
    CHECK(diags.all()[1].kind == diag::Kind::MissingProperty);
    CHECK(diags.all()[1].message.find("PreCone(1)") != std::string::npos);
    CHECK(diags.all()[1].loc.file->path() == "main.dat");

    CHECK(!f.get_bool("NumBl", diags));
    CHECK(f.get_int("TipRad", diags) == 63); // an integral number is an integer
    CHECK(diags.error_count() == 3);
    CHECK(diags.all()[2].loc.line == 7);
}

TEST_CASE("ElastoDyn file: tables") {
    diag::Diagnostics diags;
    const elastodyn::ElastoDynFile f = file();
    auto t = f.get_table("HtFract", 2, diags);
    REQUIRE(t);
    CHECK(t->columns == std::vector<std::string>{"HtFract", "TMassDen"});
    CHECK(t->column("tmassden") == 1);
    CHECK(t->column("TwFAStif") == -1);
    CHECK(t->rows[1][1] == 2.0);
    CHECK(t->lines == std::vector<int>{13, 14});
    CHECK(t->header_line == 11);
    CHECK(diags.all().empty());

    CHECK(!f.get_table("HtFract", 3, diags)); // the table ends at line 15
    REQUIRE(diags.all().size() == 1);
    CHECK(diags.all()[0].loc.line == 15);
    CHECK(diags.all()[0].message.find("has 2 rows, expected 3") != std::string::npos);

    CHECK(!f.get_table("HtFract", 1, diags)); // one numeric row too many
    REQUIRE(diags.all().size() == 2);
    CHECK(diags.all()[1].loc.line == 14);

    CHECK(!f.get_table("BlFract", 1, diags));
    CHECK(diags.all()[2].kind == diag::Kind::MissingProperty);
}

TEST_CASE("numbers") {
    CHECK(elastodyn::parse_number("1.5E+03") == 1500.0);
    CHECK(elastodyn::parse_number("-2d-1") == -0.2);
    CHECK(!elastodyn::parse_number("1.5x"));
    CHECK(!elastodyn::parse_number(""));
    CHECK(!elastodyn::parse_number("nan"));
}
