// Stage tests of the checker (AST -> model::Model) on its own: models parsed from
// text, the data of flexible bodies from a fake model::DataSource that records what
// it was asked and never touches a disk.
#include "model/checker.hpp"
#include "model/load_check.hpp"
#include "parse/parser.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace yamsc;

namespace {

/// A SID of `nq` modes with distinct diagonal masses (k + 1) and stiffnesses, so a
/// reduction to some modes can be told apart.
sid::Sid small_sid(int nq) {
    sid::Sid s;
    s.mass = 10;
    s.nq = nq;
    for (int k = 0; k < nq; ++k) s.mode_names.push_back("m" + std::to_string(k + 1));
    s.md_cm = sid::Taylor::zeros(0, 3, 1, nq);
    s.J = sid::Taylor::zeros(0, 3, 3, nq);
    s.Ct = sid::Taylor::zeros(0, nq, 3, nq);
    s.Cr = sid::Taylor::zeros(0, nq, 3, nq);
    s.Me = sid::Taylor::zeros(0, nq, nq, nq);
    s.Gr = sid::Taylor::zeros(0, 3, 3 * nq, nq);
    s.Ge = sid::Taylor::zeros(0, nq, 3 * nq, nq);
    s.Oe = sid::Taylor::zeros(0, nq, 6, nq);
    s.ksigma = sid::Taylor::zeros(0, nq, 1, nq);
    s.Ke = sid::Taylor::zeros(0, nq, nq, nq);
    s.De = sid::Taylor::zeros(0, nq, nq, nq);
    for (int k = 0; k < nq; ++k) {
        s.Me.m0[static_cast<std::size_t>(k * nq + k)] = k + 1.0;
        s.Ke.m0[static_cast<std::size_t>(k * nq + k)] = 100.0 * (k + 1);
    }
    return s;
}

struct FakeData final : model::DataSource {
    std::vector<std::string> sid_names, beam_files;
    std::vector<beam::Beam> beams_integrated;
    bool fail_inside_file = false; // report an error located in the data file itself
    std::shared_ptr<const diag::SourceFile> data_file =
        std::make_shared<const diag::SourceFile>("tower.sid", "bad line\n");

    std::optional<sid::Sid> sid_file(const std::string& name, const diag::Location&,
                                     diag::Diagnostics& diags) override {
        sid_names.push_back(name);
        if (fail_inside_file) {
            diags.error(diag::Kind::Syntax, {data_file, 1, 1}, "not a SID entry");
            return std::nullopt;
        }
        return small_sid(3);
    }
    std::optional<beam::Beam> beam_file(const std::string& format, const std::string& name,
                                        double length, const std::vector<std::string>& modes,
                                        const diag::Location&, diag::Diagnostics&) override {
        beam_files.push_back(format + ":" + name);
        beam::Beam b;
        b.length = length;
        for (const auto& m : modes) b.modes.push_back({m, 0, {0, 0, 1}, 0.01, 1});
        return b;
    }
    std::optional<sid::Sid> beam_sid(const beam::Beam& beam, const std::string&,
                                     const diag::Location&, diag::Diagnostics&) override {
        beams_integrated.push_back(beam);
        return small_sid(static_cast<int>(beam.modes.size()));
    }
};

std::optional<model::Model> check_text(const std::string& text, model::DataSource& data,
                                       diag::Diagnostics& diags) {
    auto source = std::make_shared<const diag::SourceFile>("m.mbd", text);
    auto ast = parse::parse_model(source, diags);
    REQUIRE(ast);
    return model::check(*ast, data, diags);
}

const char* const rigid_chain = R"(model chain
param L = 2
dof q1, q2
rigid b2 { mass = 1; com = (0, 0, -L) }
rigid b1 { mass = 1; com = (0, 0, -L) }
joint b1 -> b2 { at (0, 0, -L); rotate y q2 }
joint ground -> b1 { rotate y q1 }
)";

} // namespace

TEST_CASE("the body tree is ordered parents first, whatever the order of declaration") {
    FakeData data;
    diag::Diagnostics diags;
    auto m = check_text(rigid_chain, data, diags);
    INFO(diags.render());
    REQUIRE(m);
    REQUIRE(m->bodies.size() == 2);
    CHECK(m->bodies[0].name == "b1");
    CHECK(m->bodies[0].parent == -1);
    CHECK(m->bodies[1].name == "b2");
    CHECK(m->bodies[1].parent == 0);
    REQUIRE(m->params.size() == 1);
    CHECK(m->params[0].value == doctest::Approx(2.0));
    CHECK(data.sid_names.empty());
    CHECK(data.beams_integrated.empty());
}

TEST_CASE("a SID file is asked of the data stage by the name the model gives, and reduced to "
          "the modes in use") {
    FakeData data;
    diag::Diagnostics diags;
    auto m = check_text(R"(model m1
dof a, b
flexible tower { sid = "no/such/folder/tower.sid"; modes = (b, _, a) }
joint ground -> tower
)",
                        data, diags);
    INFO(diags.render());
    REQUIRE(m);
    CHECK(data.sid_names == std::vector<std::string>{"no/such/folder/tower.sid"});
    const auto& flex = *m->bodies.at(0).flex;
    CHECK(flex.sid_modes == std::vector<int>{0, 2}); // SID modes 1 and 3 kept
    CHECK(flex.dofs == std::vector<int>{1, 0});      // driven by b and a
    REQUIRE(flex.sid->nq == 2);
    // Me of the kept modes: 1 and 3 on the diagonal.
    CHECK(flex.sid->Me.m0[0] == 1.0);
    CHECK(flex.sid->Me.m0[3] == 3.0);
    CHECK(m->files_read.empty()); // only the data stage knows files
}

TEST_CASE("an inline beam reaches the data stage validated and normalised; a beam file by "
          "format and name") {
    FakeData data;
    diag::Diagnostics diags;
    auto m = check_text(R"(model m1
param L = 80
dof q, r
flexible mast {
    beam {
        length = L
        mass_per_length = (0: 6000, 1: 3000)
        EI_x = 2e11
        EI_y = (0: 6e11, 0.5: 3e11, 1: 1e11)
        mode fa1 x = 2 z^2 + 2 z^3
        modes = (fa1 -> q)
        damping_ratio = 0.02
    }
}
joint ground -> mast
flexible blade {
    beam "blade.dat" elastodyn_blade { length = 60; modes = (flap1 -> r) }
}
joint mast -> blade
)",
                        data, diags);
    INFO(diags.render());
    REQUIRE(m);
    REQUIRE(data.beams_integrated.size() == 2);
    const beam::Beam& mast = data.beams_integrated[0];
    CHECK(mast.length == 80.0);
    REQUIRE(mast.stations.size() == 3); // the union of the tables' stations
    CHECK(mast.stations[1].s == 0.5);
    CHECK(mast.stations[1].mass_per_length == doctest::Approx(4500.0)); // interpolated
    CHECK(mast.stations[1].EI_x == doctest::Approx(2e11));
    CHECK(mast.stations[1].EI_y == doctest::Approx(3e11));
    REQUIRE(mast.modes.size() == 1);
    // 2 z^2 + 2 z^3 is 4 at the tip: normalised to 0.5 z^2 + 0.5 z^3.
    REQUIRE(mast.modes[0].coeffs.size() == 4);
    CHECK(mast.modes[0].coeffs[2] == doctest::Approx(0.5));
    CHECK(mast.modes[0].coeffs[3] == doctest::Approx(0.5));
    CHECK(mast.modes[0].damping_ratio == doctest::Approx(0.02));
    CHECK(data.beam_files == std::vector<std::string>{"elastodyn_blade:blade.dat"});
    CHECK(data.beams_integrated[1].length == 60.0);
    CHECK(m->bodies.at(1).flex->dofs == std::vector<int>{1});
}

TEST_CASE("an error inside a data file gets a note at the place the model names it") {
    FakeData data;
    data.fail_inside_file = true;
    diag::Diagnostics diags;
    auto m = check_text(R"(model m1
dof a
flexible tower { sid = "tower.sid"; modes = (a) }
joint ground -> tower
)",
                        data, diags);
    CHECK_FALSE(m);
    REQUIRE(diags.all().size() == 2);
    CHECK(diags.all()[0].loc.file->path() == "tower.sid");
    CHECK(diags.all()[1].severity == diag::Severity::note);
    CHECK(diags.all()[1].loc.file->path() == "m.mbd");
    CHECK(diags.all()[1].loc.line == 3);
    CHECK(diags.all()[1].message == "in the SID of flexible body 'tower'");
}

TEST_CASE("a SID whose mode count differs from `modes` is located at the modes") {
    FakeData data;
    diag::Diagnostics diags;
    auto m = check_text(R"(model m1
dof a
flexible tower { sid = "tower.sid"; modes = (a) }
joint ground -> tower
)",
                        data, diags);
    CHECK_FALSE(m);
    REQUIRE(diags.has_errors());
    CHECK(diags.all()[0].message.find("has 3 modes") != std::string::npos);
    CHECK(diags.all()[0].loc.line == 3);
}

TEST_CASE("one DOF may drive steps of several joints (a gear), not two steps of one joint") {
    const char* text = "model m\ndof psi\nparam N = 97\n"
                       "rigid rotor { mass = 1; inertia = (1, 1, 1) }\n"
                       "rigid generator { mass = 0; inertia = (0.01, 0, 0) }\n"
                       "joint ground -> rotor { rotate x psi }\n"
                       "joint ground -> generator { rotate x N * psi }\n";
    FakeData data;
    diag::Diagnostics diags;
    auto m = check_text(text, data, diags);
    INFO(diags.render());
    CHECK(m.has_value());
    CHECK(!diags.has_errors());
}

TEST_CASE("load: roles bound to the model's names; the source digest leaves the statement out") {
    const std::string base = R"(model m
param R = 63, rho = 1.2
input V, T, Q
dof s, psi
rigid tower { mass = 1 }
rigid rotor { mass = 1; inertia = (1, 1, 1) }
joint ground -> tower { translate x s }
joint tower -> rotor { rotate x psi }
force on rotor = (T, 0, 0)
torque on rotor = (Q, 0, 0)
output speed = psi'
output hub = s'
)";
    const std::string decl = "load rotor_table aero { wind = V; thrust = T; rotor_torque = Q\n"
                             "    speed = speed; hub_velocity = hub; radius = R; density = rho }\n";
    FakeData data;
    diag::Diagnostics diags;
    auto m = check_text(base + decl + "output after = s\n", data, diags);
    INFO(diags.render());
    REQUIRE(m);
    REQUIRE(m->loads.size() == 1);
    const model::LoadBlock& b = m->loads[0];
    CHECK(b.kind == model::LoadKind::rotor_table);
    CHECK(b.name == "aero");
    using Role = model::RotorTableRole;
    CHECK(b.role(Role::wind) == "V");
    CHECK(b.role(Role::pitch).empty()); // optional, not bound
    CHECK(b.role(Role::torque) == "Q");
    CHECK(b.role(Role::hub_velocity) == "hub");
    CHECK(b.role(Role::density) == "rho");
    CHECK(model::without_load_statements(base + decl + "output after = s\n", *m) ==
          base + "output after = s\n");
}
