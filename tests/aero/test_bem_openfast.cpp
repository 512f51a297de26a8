// The rigid NREL 5-MW rotor against OpenFAST v5 + AeroDyn (every ElastoDyn DOF
// off, quasi-steady BEM; data/reference/aero/README.md), every rigid run of its
// cases.txt: RtFldCp and RtFldCt within 0.5 %, the nine output nodes' angle of
// attack within 0.1 deg, their Fx and Fy within 1 % of the blade's largest, at
// azimuths over a revolution.
#include "aerodyn_input/rotor.hpp"
#include "analysis/commands.hpp"
#include "driver/commands.hpp"
#include "reference_cases.hpp"
#include "yamsc/aero/rigid_rotor.hpp"
#include "yamsc/aero/rotor_table.hpp"
#include "yamsc/performance_table.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace yamsc;

namespace {

constexpr double deg = 3.14159265358979323846 / 180;
const std::string data_dir = std::string(YAMSC_TEST_DATA_DIR) + "/reference/";

using Row = std::map<std::string, double>;

std::vector<Row> read_csv(const std::string& path) {
    std::ifstream in(path);
    REQUIRE(in);
    std::string line;
    std::getline(in, line);
    std::vector<std::string> names;
    std::stringstream header(line);
    for (std::string n; std::getline(header, n, ',');) names.push_back(n);
    std::vector<Row> rows;
    while (std::getline(in, line)) {
        std::stringstream s(line);
        Row row;
        std::size_t i = 0;
        for (std::string v; std::getline(s, v, ',') && i < names.size(); ++i)
            row[names[i]] = std::stod(v);
        rows.push_back(std::move(row));
    }
    return rows;
}

const aero::RotorInput& nrel5mw() {
    static const aero::RotorInput input = [] {
        diag::Diagnostics diags;
        const auto rotor = aerodyn_input::read_aerodyn_rotor(
            data_dir + "operating/deck/NRELOffshrBsline5MW_Onshore_AeroDyn15.dat", 3, diags);
        REQUIRE_MESSAGE(rotor, diags.render());
        return *rotor;
    }();
    return input;
}

// AeroDyn's output nodes (BlOutNd) of the reference runs.
constexpr int output_nodes[9] = {3, 5, 7, 9, 11, 13, 15, 17, 18};

struct Worst {
    double cp = 0, ct = 0, alpha = 0, fx = 0, fy = 0; // %, %, deg, % of largest, % of largest
};

// The deck's rotor with the run's AeroDyn entries set.
aero::RotorInput rotor_of(const reference_cases::Case& c) {
    const std::string deck = reference_cases::deck("bem_openfast_" + c.name(), c.settings);
    diag::Diagnostics diags;
    const auto rotor =
        aerodyn_input::read_aerodyn_rotor(deck + reference_cases::aerodyn_file, 3, diags);
    REQUIRE_MESSAGE(rotor, diags.render());
    return *rotor;
}

// warm: each row starts from the previous row's phi, as AeroDyn's constraint state.
Worst compare(const reference_cases::Case& c, bool warm = false) {
    const std::string name = c.name();
    const double propagation_deg = c.number("PropagationDir", 0);
    const auto rows = read_csv(c.path());
    REQUIRE(rows.size() > 80);
    const aero::RotorInput input = rotor_of(c); // the rotor keeps a reference to it
    aero::RigidRotor rotor(input, aero::RotorGeometry{});
    Worst w;
    for (const std::size_t i : {0, 13, 26, 40, 53, 67, 80}) {
        const Row& r = rows[i];
        aero::OperatingPoint op;
        op.azimuth = r.at("Azimuth_[deg]") * deg;
        op.rotor_speed = r.at("RotSpeed_[rpm]") * 2 * 3.14159265358979323846 / 60;
        op.pitch = r.at("BlPitch1_[deg]") * deg;
        op.wind_speed = std::hypot(r.at("Wind1VelX_[m/s]"), r.at("Wind1VelY_[m/s]"));
        op.wind_direction = propagation_deg * deg;
        const aero::RotorResult& res = rotor.evaluate(op, warm);
        CAPTURE(name);
        CAPTURE(r.at("Azimuth_[deg]"));
        const double cp = 100 * std::abs(res.cp / r.at("RtFldCp_[-]") - 1);
        const double ct = 100 * std::abs(res.ct / r.at("RtFldCt_[-]") - 1);
        CHECK(cp < 0.5);
        CHECK(ct < 0.5);
        w.cp = std::max(w.cp, cp);
        w.ct = std::max(w.ct, ct);
        // Secondary channels with the same definitions: thrust, TSR, skew, disk wind.
        CHECK(res.tsr == doctest::Approx(r.at("RtTSR_[-]")).epsilon(1e-5));
        CHECK(res.skew / deg == doctest::Approx(r.at("RtSkew_[deg]")).epsilon(1e-5));
        CHECK(res.v_avg_xh == doctest::Approx(r.at("RtVAvgxh_[m/s]")).epsilon(1e-5));
        double fx_max = 0, fy_max = 0;
        for (int k = 1; k <= 9; ++k) {
            const std::string n = "B1N" + std::to_string(k);
            fx_max = std::max(fx_max, std::abs(r.at(n + "Fx_[N/m]")));
            fy_max = std::max(fy_max, std::abs(r.at(n + "Fy_[N/m]")));
        }
        for (int k = 1; k <= 9; ++k) {
            const std::string n = "B1N" + std::to_string(k);
            const aero::ElementSolution& s = res.blades[0][output_nodes[k - 1] - 1].bem;
            CAPTURE(output_nodes[k - 1]);
            const double alpha =
                std::abs(std::remainder(s.alpha, 360 * deg) / deg - r.at(n + "Alpha_[deg]"));
            const double fx = 100 * std::abs(s.fx - r.at(n + "Fx_[N/m]")) / fx_max;
            const double fy = 100 * std::abs(s.fy - r.at(n + "Fy_[N/m]")) / fy_max;
            CHECK(alpha < 0.1);
            CHECK(fx < 1.0);
            CHECK(fy < 1.0);
            w.alpha = std::max(w.alpha, alpha);
            w.fx = std::max(w.fx, fx);
            w.fy = std::max(w.fy, fy);
        }
    }
    MESSAGE(name << ": worst Cp " << w.cp << " %, Ct " << w.ct << " %, alpha " << w.alpha
                 << " deg, Fx " << w.fx << " %, Fy " << w.fy << " % of the largest");
    return w;
}

} // namespace

TEST_CASE("bem: every rigid rotor run (rigid_U8, rigid_U11.4, rigid_U16, rigid_U8_prop20 and "
          "those held) as OpenFAST + AeroDyn") {
    for (const reference_cases::Case& c : reference_cases::cases(reference_cases::Kind::rigid))
        compare(c);
}

TEST_CASE("bem: every rigid rotor run from the previous azimuth's inflow angles") {
    for (const reference_cases::Case& c : reference_cases::cases(reference_cases::Kind::rigid))
        compare(c, true);
}

// ROSCO's table of the deck was made with CCBlade, not AeroDyn: CCBlade's
// integration ends at zero load at the tip while AeroDyn's last element runs to
// a loaded tip node (a = 1, phi = 0), and its polars are splined. The table from
// AeroDyn's BEM is up to 3.2 % above ROSCO's in Cp near the optimum, and differs
// by at most 0.016 in Cp and 0.008 in Ct at these points; 5 % of the table's
// largest value bounds that, and would catch a wrong normalization (radius, wind
// speed) or pitch sign.
TEST_CASE("bem table: the deck's rotor against ROSCO's Cp_Ct_Cq.NREL5MW.txt") {
    const runtime::PerformanceTable rosco =
        runtime::read_performance_table(data_dir + "operating/deck/Cp_Ct_Cq.NREL5MW.txt");
    aero::TableRequest req;
    req.tsr = {5, 7.5, 9};
    req.pitch_deg = {0, 5, 10};
    req.wind_speed = 11.4;
    req.rotor_radius = 63;
    const runtime::PerformanceTable t =
        aero::rotor_performance_table(nrel5mw(), aero::RotorGeometry{}, req);
    const double cp_max = *std::max_element(rosco.cp.begin(), rosco.cp.end());
    const double ct_max = *std::max_element(rosco.ct.begin(), rosco.ct.end());
    for (std::size_t i = 0; i < req.tsr.size(); ++i) {
        for (std::size_t j = 0; j < req.pitch_deg.size(); ++j) {
            const auto cp = runtime::interpolate(rosco, rosco.cp, req.tsr[i], req.pitch_deg[j]);
            const auto ct = runtime::interpolate(rosco, rosco.ct, req.tsr[i], req.pitch_deg[j]);
            const std::size_t at = i * req.pitch_deg.size() + j;
            CAPTURE(req.tsr[i]);
            CAPTURE(req.pitch_deg[j]);
            CHECK(std::abs(t.cp[at] - cp.value) < 0.05 * cp_max);
            CHECK(std::abs(t.ct[at] - ct.value) < 0.05 * ct_max);
        }
    }
}

TEST_CASE("bem table: rotor-table from the deck writes the rigid rotor's table") {
    const std::filesystem::path dir = std::filesystem::path(YAMSC_TEST_BINARY_DIR) / "bem_table";
    std::filesystem::create_directories(dir);
    driver::RotorTableOptions o;
    o.table = data_dir + "operating/deck/NREL-5MW.fst";
    o.output = (dir / "Cp_Ct_Cq.txt").string();
    o.tsr = {6, 7.5, 9};
    o.pitch_deg = {0, 2};
    o.azimuths = 3;
    std::ostringstream out, err;
    REQUIRE(analysis::rotor_table(o, out, err) == 0);
    const runtime::PerformanceTable written = runtime::read_performance_table(o.output);

    aero::TableRequest req;
    req.tsr = o.tsr;
    req.pitch_deg = o.pitch_deg;
    req.wind_speed = 11.4;
    req.rotor_radius = 63; // TipRad
    req.azimuths = 3;
    const runtime::PerformanceTable t =
        aero::rotor_performance_table(nrel5mw(), aero::RotorGeometry{}, req);
    REQUIRE(written.tsr == t.tsr);
    REQUIRE(written.pitch_deg == t.pitch_deg);
    for (std::size_t i = 0; i < t.cp.size(); ++i) {
        CHECK(std::abs(written.cp[i] - t.cp[i]) < 1e-6);
        CHECK(std::abs(written.ct[i] - t.ct[i]) < 1e-6);
        CHECK(std::abs(written.cq[i] - t.cq[i]) < 1e-6);
    }
}
