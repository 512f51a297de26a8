// `yamsc dlc` through the yamsc binary: a DLC 1.2 table of 2 speeds x 2 seeds
// and a DLC 6.1 table become the expected folder (manifest rows, TurbSim inputs
// that the TurbSim input reader reads back with the IEC values, InflowWind files
// with the yaw misalignment), the same bytes when made again, and .bts files of
// the grid and times asked for.
#include "test_files.hpp"
#include "wind/turbsim_input.hpp"

#include <doctest/doctest.h>

#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <unistd.h>

using namespace test_support;

namespace {

const std::string source_dir = YAMSC_SOURCE_DIR;
const std::string operating = source_dir + "/models/nrel5mw_land_operating.mbd";

int run_in(const std::string& dir, const std::string& command, std::string* err = nullptr) {
    const int status = exit_status("cd '" + dir + "' && " + std::string(YAMSC_EXE) + " " + command +
                                   " >out.txt 2>err.txt");
    if (err) *err = read_file(dir + "/err.txt");
    return status;
}

yamsc::wind::TurbSimInput inp(const std::string& path) {
    std::istringstream in(read_file(path));
    return yamsc::wind::read_turbsim_input(in, path);
}

/// The header of a TurbSim .bts file (TS_FileIO.f90 WrBinTURBSIM): id, nz, ny,
/// tower points, steps, then dz, dy, dt, the hub's mean speed and height, the bottom.
struct BtsHeader {
    std::int32_t nz = 0, ny = 0, ntwr = 0, nt = 0;
    float dz = 0, dy = 0, dt = 0, u_hub = 0, z_hub = 0, z_bottom = 0;
};
BtsHeader bts_header(const std::string& bytes) {
    BtsHeader h;
    REQUIRE(bytes.size() > 42);
    std::size_t at = 2;
    for (std::int32_t* v : {&h.nz, &h.ny, &h.ntwr, &h.nt}) {
        std::memcpy(v, bytes.data() + at, 4);
        at += 4;
    }
    for (float* v : {&h.dz, &h.dy, &h.dt, &h.u_hub, &h.z_hub, &h.z_bottom}) {
        std::memcpy(v, bytes.data() + at, 4);
        at += 4;
    }
    return h;
}

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

} // namespace

TEST_CASE("a DLC 1.2 table: 2 speeds x 2 seeds x 2 yaw misalignments") {
    const std::string dir = scratch_dir("dlc", "dlc12");
    write_file(dir + "/DISCON.IN", "hold 20000\n");
    write_file(dir + "/discon.so", "not loaded by dlc\n");
    const std::string command =
        "dlc '" + operating +
        "' -o out --dlc 1.2 --class IIA --hub-height 90 --rotor-diameter 126 --speeds 8,14 "
        "--seeds 2 --seed 7 --yaw -8,0 --controller discon.so --controller-input DISCON.IN "
        "--time 20 --transient 5 --dt 0.01 --dt-out 0.05 --grid 5 --wind-dt 0.1";
    std::string err;
    REQUIRE_MESSAGE(run_in(dir, command, &err) == 0, err);
    const std::string manifest = read_file(dir + "/out/cases.csv");
    // 2 speeds x 2 seeds x 2 yaws, in that order.
    INFO(manifest);
    CHECK(has(manifest, "\nid,model,tmax,dt,method,coupling,channels,dt_out,wind,aero,controller,"
                        "controller_input,u\n"
                        "dlc1.2_U08.0_s1_y-8,"));
    const std::string row = "dlc1.2_U14.0_s2_y0,";
    const std::size_t at = manifest.find(row);
    REQUIRE(at != std::string::npos);
    const std::string line = manifest.substr(at, manifest.find('\n', at) - at);
    CHECK(line.find(",25,0.01,abm4,loose,openfast,0.05,wind/NTM_U14.0_s2_y0.dat,,../discon.so,"
                    "../DISCON.IN,") != std::string::npos);
    CHECK(has(line, "nrel5mw_land_operating.mbd"));
    std::size_t rows = 0;
    for (char c : manifest) rows += c == '\n';
    CHECK(rows == 3 + 8); // two comments, the header, 8 cases
    CHECK(has(manifest, "--from 5"));

    // The TurbSim inputs, read back by the generator's reader.
    const yamsc::wind::TurbSimInput w = inp(dir + "/out/wind/NTM_U14.0_s2.inp");
    CHECK(w.ref_speed == 14);
    CHECK(w.ref_height == 90);
    CHECK(w.hub_height == 90);
    CHECK(w.characteristic == yamsc::wind::TurbulenceCharacteristic::A);
    CHECK(w.model == yamsc::wind::IecTurbulenceModel::normal);
    CHECK(w.seed == 7 + 100 * 1 + 1); // the second speed, the second seed
    CHECK(inp(dir + "/out/wind/NTM_U08.0_s1.inp").seed == 7);
    CHECK(w.ny == 5);
    CHECK(w.nz == 5);
    CHECK(w.grid_width == 145); // 1.15 x 126 m, rounded up: covers the rotor
    CHECK(w.grid_height == 145);
    CHECK(w.grid_width >= 126);
    CHECK(w.hub_height > w.grid_height / 2);
    CHECK(w.time_step == 0.1);
    CHECK(w.analysis_time == 25);
    CHECK(w.usable_time == 25);
    CHECK(w.power_law == 0.2);
    CHECK(w.scale_iec == 0);

    // The InflowWind files: the wind's .bts, turned by the yaw misalignment.
    const std::string ifw = read_file(dir + "/out/wind/NTM_U08.0_s2_y-8.dat");
    CHECK(has(ifw, "             3   WindType"));
    CHECK(has(ifw, "            -8   PropagationDir"));
    CHECK(has(ifw, "\"NTM_U08.0_s2.bts\"   FileName_BTS"));

    // The table: id and speed for `yamsc loads --speeds`.
    const std::string table = read_file(dir + "/out/table.csv");
    CHECK(table.rfind("id,dlc,speed,turbulence,seed,rand_seed,yaw,parked,transient\n"
                      "dlc1.2_U08.0_s1_y-8,1.2,8,NTM,1,7,-8,no,5\n",
                      0) == 0);

    // The .bts of each wind: the grid and the times asked for.
    for (const char* name : {"NTM_U08.0_s1", "NTM_U08.0_s2", "NTM_U14.0_s1", "NTM_U14.0_s2"}) {
        INFO(name);
        const BtsHeader g = bts_header(read_file(dir + "/out/wind/" + name + ".bts"));
        CHECK(g.ny == 5);
        CHECK(g.nz == 5);
        CHECK(g.dy == doctest::Approx(145.0 / 4));
        CHECK(g.dt == doctest::Approx(0.1));
        CHECK(g.z_hub == doctest::Approx(90));
        CHECK(g.u_hub == doctest::Approx(name[6] == '8' ? 8.0 : 14.0)); // NTM_U08.0, NTM_U14.0
        CHECK(g.z_bottom == doctest::Approx(90 - 145.0 / 2));
        CHECK((g.nt - 1) * g.dt >= 25);
    }

    // Deterministic: the same table again gives the same bytes, and makes no .bts
    // again; one thread makes the fields two made.
    const std::string bts = read_file(dir + "/out/wind/NTM_U14.0_s2.bts");
    REQUIRE(run_in(dir, command, &err) == 0);
    CHECK(read_file(dir + "/out/cases.csv") == manifest);
    CHECK(read_file(dir + "/out/wind/NTM_U08.0_s2_y-8.dat") == ifw);
    CHECK(read_file(dir + "/out/wind/NTM_U14.0_s2.bts") == bts);
    CHECK(has(read_file(dir + "/out.txt"), "(0 .bts generated, 4 unchanged)"));
    REQUIRE(run_in(dir, "dlc '" + operating +
                            "' -o again --dlc 1.2 --class IIA --hub-height 90 --rotor-diameter 126 "
                            "--speeds 8,14 --seeds 2 --seed 7 --yaw -8,0 --controller discon.so "
                            "--controller-input DISCON.IN --time 20 --transient 5 --grid 5 "
                            "--wind-dt 0.1 --threads 1") == 0);
    CHECK(read_file(dir + "/again/wind/NTM_U14.0_s2.bts") == bts);
}

TEST_CASE("DLC 6.1 and 6.2: parked in the 50-year turbulent extreme wind") {
    const std::string dir = scratch_dir("dlc", "dlc6");
    std::string err;
    REQUIRE_MESSAGE(run_in(dir,
                           "dlc '" + operating +
                               "' -o out --dlc 6.1,6.2 --class IIIC --hub-height 90 "
                               "--rotor-diameter 126 --seeds 1 --yaw-step 90 --time 10 "
                               "--transient 0 --grid 4 --no-bts",
                           &err) == 0,
                    err);
    const std::string manifest = read_file(dir + "/out/cases.csv");
    INFO(manifest);
    // V_ref of class III: 37.5 m/s; 6.1 at -8 and +8 deg, 6.2 at -180, -90, 0, 90.
    for (const char* id : {"dlc6.1_U37.5_s1_y-8,", "dlc6.1_U37.5_s1_y+8,", "dlc6.2_U37.5_s1_y-180,",
                           "dlc6.2_U37.5_s1_y-90,", "dlc6.2_U37.5_s1_y0,", "dlc6.2_U37.5_s1_y+90,"})
        CHECK(has(manifest, std::string("\n") + id));
    CHECK(!has(manifest, "y+180"));
    // Parked: no controller, feathered and unloaded.
    CHECK(has(manifest, "wind/EWM50_U37.5_s1_y+8.dat,,,,\"pitch=90deg,gen_torque=0\"\n"));
    const yamsc::wind::TurbSimInput w = inp(dir + "/out/wind/EWM50_U37.5_s1.inp");
    CHECK(w.ref_speed == 37.5);
    CHECK(w.characteristic == yamsc::wind::TurbulenceCharacteristic::percent);
    CHECK(w.intensity_percent == 11);
    CHECK(w.power_law == 0.11);
    CHECK(w.seed == 1 + 200000);
    CHECK(::access((dir + "/out/wind/EWM50_U37.5_s1.bts").c_str(), F_OK) != 0); // --no-bts
    CHECK(has(read_file(dir + "/out.txt"), "yamsc turbulence out/wind/NAME.inp"));
    // 6.1 and 6.2 share their wind: one TurbSim input.
    CHECK(has(read_file(dir + "/out/table.csv"),
              "dlc6.2_U37.5_s1_y-90,6.2,37.5,EWM50,1,200001,-90,yes,0\n"));
}

TEST_CASE("DLC 1.3: the extreme turbulence model of the turbine's class") {
    const std::string dir = scratch_dir("dlc", "dlc13");
    std::string err;
    REQUIRE_MESSAGE(run_in(dir,
                           "dlc '" + operating +
                               "' -o out --dlc 1.3 --class IIB --hub-height 90 "
                               "--rotor-diameter 126 --cut-in 3 --cut-out 25 --seeds 1 "
                               "--no-bts",
                           &err) == 0,
                    err);
    const std::string table = read_file(dir + "/out/table.csv");
    // Bins of 2 m/s from 3 to 25 m/s: their centres 4 .. 24, 11 speeds.
    std::size_t rows = 0;
    for (char c : table) rows += c == '\n';
    CHECK(rows == 1 + 11);
    CHECK(has(table, "\ndlc1.3_U04.0_s1_y0,1.3,4,ETM,"));
    CHECK(has(table, "\ndlc1.3_U24.0_s1_y0,1.3,24,ETM,"));
    const yamsc::wind::TurbSimInput w = inp(dir + "/out/wind/ETM_U24.0_s1.inp");
    CHECK(w.model == yamsc::wind::IecTurbulenceModel::extreme);
    CHECK(w.turbine_class == 2);
    CHECK(w.characteristic == yamsc::wind::TurbulenceCharacteristic::B);
}

TEST_CASE("dlc refuses what it cannot make") {
    const std::string dir = scratch_dir("dlc", "errors");
    std::string err;
    CHECK(run_in(dir, "dlc '" + operating + "' -o out --hub-height 60 --rotor-diameter 126",
                 &err) == 2);
    CHECK(has(err, "reaches the ground"));
    CHECK(run_in(dir, "dlc '" + operating + "' -o out --rotor-diameter 126", &err) == 2);
    CHECK(has(err, "--hub-height"));
    CHECK(run_in(dir,
                 "dlc '" + operating + "' -o out --hub-height 90 --rotor-diameter 126 --dlc 2.1",
                 &err) == 2);
    CHECK(run_in(dir,
                 "dlc '" + operating + "' -o out --hub-height 90 --rotor-diameter 126 --class IVB",
                 &err) == 2);
}

TEST_CASE("a DLC 1.2 folder runs in `yamsc batch` and reduces in `yamsc loads`") {
    // The operating NREL 5-MW (4 DOFs, the Cp/Ct/Cq rotor at the hub's wind)
    // under the baseline controller: 2 speeds x 2 seeds, 25 s.
    const std::string dir = scratch_dir("dlc", "run");
    const std::string table = source_dir + "/models/data/Cp_Ct_Cq.NREL5MW.txt";
    std::string err;
    REQUIRE_MESSAGE(run_in(dir,
                           "dlc '" + operating +
                               "' -o out --dlc 1.2 --hub-height 90 --rotor-diameter 126 "
                               "--speeds 8,14 --seeds 2 --time 20 --transient 5 --grid 5 "
                               "--wind-dt 0.1 --controller '" +
                               YAMSC_BASELINE_DISCON + "' --aero '" + table + "'",
                           &err) == 0,
                    err);
    REQUIRE_MESSAGE(run_in(dir, "batch out/cases.csv --threads 2 -q", &err) == 0, err);
    CHECK(has(read_file(dir + "/out.txt"), "4 cases, 4 ok, 0 failed"));
    // A case is the `yamsc sim` run of its row.
    REQUIRE_MESSAGE(run_in(dir,
                           "sim '" + operating +
                               "' --tmax 25 --dt 0.01 --method abm4 --coupling loose "
                               "--channels openfast --dt-out 0.05 --wind "
                               "out/wind/NTM_U14.0_s2_y0.dat --aero '" +
                               table + "' --controller '" + YAMSC_BASELINE_DISCON + "' -o lone.csv",
                           &err) == 0,
                    err);
    CHECK(read_file(dir + "/lone.csv") == read_file(dir + "/out/cases.out/dlc1.2_U14.0_s2_y0.csv"));
    // The seeds are other winds, so other runs.
    CHECK(read_file(dir + "/out/cases.out/dlc1.2_U14.0_s1_y0.csv") !=
          read_file(dir + "/out/cases.out/dlc1.2_U14.0_s2_y0.csv"));
    // `yamsc loads` takes each case's speed from the table, after the transient.
    REQUIRE_MESSAGE(run_in(dir,
                           "loads --batch out/cases.out --speeds out/table.csv --from 5 "
                           "--channels GenPwr,RotSpeed -o loads.csv",
                           &err) == 0,
                    err);
    const std::string loads = read_file(dir + "/loads.csv");
    INFO(loads);
    CHECK(
        has(loads, "\nruns,dlc1.2_U08.0_s1_y0,out/cases.out/dlc1.2_U08.0_s1_y0.csv,8,5,25,GenPwr"));
    CHECK(has(loads,
              "\nruns,dlc1.2_U14.0_s2_y0,out/cases.out/dlc1.2_U14.0_s2_y0.csv,14,5,25,GenPwr"));
}
