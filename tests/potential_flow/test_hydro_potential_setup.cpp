// HydroDyn's potential flow from its files: WAMIT's nondimensional coefficients
// redimensionalized with rho, g and WAMITULEN as HydroDyn's WAMIT_Init does, the
// cylinder's closed forms through a HydroDyn file, and the files' errors located.
#include "analysis/hydro_potential_setup.hpp"
#include "diag/read_text.hpp"
#include "hydrodyn/hydrodyn_input.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <string>

using namespace yamsc;

namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double rho = 1025, g = 9.80665;
const std::string data = std::string(YAMSC_SOURCE_DIR) + "/tests/data/hydro/";

std::shared_ptr<const diag::SourceFile> source(const std::string& name, const std::string& text) {
    return std::make_shared<const diag::SourceFile>(name, text);
}

std::string file_text(const std::string& path) {
    diag::Diagnostics diags;
    const auto f = diag::read_text_file(path, diags);
    REQUIRE(static_cast<bool>(f));
    return f->text();
}

std::string replaced(std::string text, const std::string& what, const std::string& with) {
    const auto at = text.find(what);
    REQUIRE(at != std::string::npos);
    return text.replace(at, what.size(), with);
}

/// The OC3 HydroDyn file of data/hydro with PotFile naming the cylinder's files.
hydrodyn::Input cylinder_input(const std::string& edit_from = "", const std::string& edit_to = "") {
    std::string text =
        replaced(file_text(data + "oc3_spar_wamit.dat"), "\"spar\"", "\"" + data + "cylinder\"");
    if (!edit_from.empty()) text = replaced(text, edit_from, edit_to);
    const std::string path = std::string(YAMSC_TEST_BINARY_DIR) + "/cylinder_hydrodyn.dat";
    std::ofstream(path) << text;
    diag::Diagnostics diags;
    auto in = hydrodyn::read_hydrodyn_input(std::filesystem::path(path), diags);
    INFO(diags.render());
    REQUIRE(in);
    return *in;
}

} // namespace

TEST_CASE(
    "redimensionalization: rho L^3..5 (A), rho L^3..5 w (B), rho g L^2..4 (C), rho g L^2..3 (X)") {
    const double L = 2.0;
    diag::Diagnostics diags;
    const auto r = wamit::read_radiation(
        source("r.1", "-1 1 1 1\n-1 5 5 1\n0 1 1 2\n0 1 5 3\n0 5 5 4\n6.283185307179586 1 1 5 6\n"
                      "6.283185307179586 1 5 7 8\n6.283185307179586 5 5 9 10\n"),
        diags);
    const auto x = wamit::read_excitation(
        source("r.3", "6.283185307179586 0 1 1 0 1.5 -2\n6.283185307179586 0 5 1 0 3 4\n"), diags);
    const auto h = wamit::read_hydrostatics(source("r.hst", "3 3 2\n3 5 3\n5 5 4\n"), diags);
    REQUIRE(r);
    REQUIRE(x);
    REQUIRE(h);
    const auto c = analysis::wamit_coefficients(*r, &*x, *h, rho, g, L, diags);
    INFO(diags.render());
    REQUIRE(c);
    REQUIRE(c->omega.size() == 3); // 0, 1 rad/s, "infinity" just above 1
    CHECK(c->omega[0] == 0);
    CHECK(c->omega[1] == doctest::Approx(1.0).epsilon(1e-15));
    CHECK(c->omega[2] > 1.0);
    CHECK(c->omega[2] < 1.0 + 1e-6);
    CHECK(c->added_mass_infinite[0] == doctest::Approx(2 * rho * 8));
    CHECK(c->added_mass_infinite[4] == doctest::Approx(3 * rho * 16));
    CHECK(c->added_mass_infinite[28] == doctest::Approx(4 * rho * 32));
    CHECK(c->added_mass[1][0] == doctest::Approx(5 * rho * 8));
    CHECK(c->damping[1][0] == doctest::Approx(6 * rho * 8 * 1.0));
    CHECK(c->damping[1][4] == doctest::Approx(8 * rho * 16));
    CHECK(c->damping[1][28] == doctest::Approx(10 * rho * 32));
    CHECK(c->damping[0][0] == 0);
    CHECK(c->damping[2][0] == 0);
    CHECK(c->hydrostatic[14] == doctest::Approx(2 * rho * g * 4));
    CHECK(c->hydrostatic[16] == doctest::Approx(3 * rho * g * 8));
    CHECK(c->hydrostatic[28] == doctest::Approx(4 * rho * g * 16));
    const auto& t = c->excitation;
    REQUIRE(t.heading.size() == 1);
    CHECK(t.force[6 + 0] == std::complex<double>(1.5 * rho * g * 4, -2 * rho * g * 4));
    CHECK(t.force[6 + 4] == std::complex<double>(3 * rho * g * 8, 4 * rho * g * 8));
    CHECK(t.force[0] == t.force[6]); // zero frequency: the lowest positive one's
    CHECK(t.force[12] == 0.0);       // infinite frequency: none
}

TEST_CASE("the cylinder through a HydroDyn file: A_inf, C and B(w) of the closed forms") {
    const double R = 5, T = 50, S = pi * R * R, V = S * T;
    diag::Diagnostics diags;
    const auto s = analysis::potential_setup(cylinder_input(), {rho, g, 320}, diags);
    INFO(diags.render());
    REQUIRE(s);
    // Written with 7 significant digits.
    CHECK(s->added_mass_infinite[0] == doctest::Approx(rho * S * T).epsilon(1e-6));
    CHECK(s->added_mass_infinite[4] == doctest::Approx(-rho * S * T * T / 2).epsilon(1e-6));
    CHECK(s->added_mass_infinite[28] == doctest::Approx(rho * S * T * T * T / 3).epsilon(1e-6));
    CHECK(s->hydrostatic[14] == doctest::Approx(rho * g * S).epsilon(1e-6));
    CHECK(s->hydrostatic[28] ==
          doctest::Approx(rho * g * (V * -T / 2 + pi * std::pow(R, 4) / 4)).epsilon(1e-6));
    CHECK(s->displaced_volume == 8029.21);
    CHECK(s->additional.c_lin[35] == 98340000);
    CHECK(s->additional.b_lin[14] == 130000);
    // RdtnTMax 60 s, RdtnDT 0.0125 s: K(t) = (2/pi) int B cos(w t) dw of the table as
    // HydroDyn takes it: the Gaussian (B0 2e5, sigma 1 rad/s) from 0.05 to 4 rad/s,
    // linear from B(0) = 0 (the zero-frequency limit has no damping) to B(0.05):
    // the closed form less int_0^0.05 B plus that ramp's area. What is left (1e-3)
    // is the kernel's trapezoid rule (dw = pi / 60) across the ramp's kink.
    REQUIRE(s->kernel_dt == 0.0125);
    const double b0 = 2e5,
                 ramp = -(0.05 - std::pow(0.05, 3) / 6) + 0.025 * std::exp(-0.05 * 0.05 / 2);
    CHECK(s->radiation_kernel[0][0] ==
          doctest::Approx(2 / pi * b0 * (std::sqrt(pi / 2) + ramp)).epsilon(2e-3));
    CHECK(s->radiation_kernel[80][0] == // t = 1 s
          doctest::Approx(2 / pi * b0 * (std::sqrt(pi / 2) * std::exp(-0.5) + ramp)).epsilon(2e-3));
    // Waves toward +x at 0.5 rad/s: the surge force's amplitude 2 rho g S (1 - exp(-k T)).
    const auto x = s->excitation.at(0.5, 0.0);
    const double k = 0.25 / g;
    CHECK(std::abs(x[0]) ==
          doctest::Approx(2 * rho * g * S * (1 - std::exp(-k * T))).epsilon(1e-6));
    CHECK(std::abs(x[1]) < 1e-6 * std::abs(x[0]));
}

TEST_CASE("errors: in the HydroDyn file at the entry, in a WAMIT file at its row") {
    {
        diag::Diagnostics diags;
        auto in = cylinder_input("    0.0125   RdtnDT", "    1.0      RdtnDT");
        CHECK(!analysis::potential_setup(in, {rho, g, 320}, diags));
        CHECK(diags.render().find("cylinder_hydrodyn.dat:15:") != std::string::npos);
        CHECK(diags.render().find("RdtnDT must be smaller than") != std::string::npos);
    }
    {
        diag::Diagnostics diags;
        auto in = cylinder_input("\"" + data + "cylinder\"", "\"no_such_body\"");
        CHECK(!analysis::potential_setup(in, {rho, g, 320}, diags));
        CHECK(diags.render().find("cylinder_hydrodyn.dat:18:") != std::string::npos);
    }
    {
        diag::Diagnostics diags;
        const auto r = wamit::read_radiation(source("z.1", "0 1 1 1\n5 1 1 1 1\n"), diags);
        const auto h = wamit::read_hydrostatics(source("z.hst", "7 7 1\n"), diags);
        REQUIRE(r);
        REQUIRE(h);
        CHECK(!analysis::wamit_coefficients(*r, nullptr, *h, rho, g, 1, diags));
        CHECK(diags.render().find("z.hst:1:1: error: modes beyond 6") != std::string::npos);
    }
    {
        diag::Diagnostics diags;
        const auto r = wamit::read_radiation(source("z.1", "0 1 1 1\n5 1 1 1 1\n"), diags);
        const auto h = wamit::read_hydrostatics(source("z.hst", "3 3 1\n"), diags);
        CHECK(!analysis::wamit_coefficients(*r, nullptr, *h, rho, g, 1, diags));
        CHECK(diags.render().find("z.1:1:1: error: the WAMIT .1 file must hold both") !=
              std::string::npos);
    }
    {
        diag::Diagnostics diags;
        const auto r =
            wamit::read_radiation(source("z.1", "-1 1 1 1\n0 1 1 1\n5 1 1 1 1\n"), diags);
        const auto x = wamit::read_excitation(source("z.3", "6 0 1 1 0 1 0\n"), diags);
        const auto h = wamit::read_hydrostatics(source("z.hst", "3 3 1\n"), diags);
        CHECK(!analysis::wamit_coefficients(*r, &*x, *h, rho, g, 1, diags));
        CHECK(diags.render().find("z.3:1:1: error: the .3 file's periods") != std::string::npos);
    }
}
