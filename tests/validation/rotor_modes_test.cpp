// The spinning 16-DOF turbine's modes by MBC3 (`yamsc lin --mbc3`) against
// OpenFAST's own linearization of the same deck, MBC3-transformed and
// azimuth-averaged (tests/data/reference/linearization/rotating_*.csv): rotor
// held at 6 and 12.1 rpm (GenDOF off), yaw free and locked.
#include "validation_support.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <vector>

using namespace validation;

namespace {

struct ModeRow {
    std::string label;
    double freq_hz = 0, damping = 0;
    double share = 1; // yamsc: the largest coordinate's share of the mode's energy
};

std::vector<ModeRow> reference_modes(const std::string& file) {
    std::istringstream in(read(reference_dir + "/linearization/" + file));
    std::string line;
    std::getline(in, line); // header
    std::vector<ModeRow> rows;
    while (std::getline(in, line)) {
        const auto c2 = line.rfind(','), c1 = line.rfind(',', c2 - 1);
        REQUIRE((c1 != std::string::npos && c2 != std::string::npos));
        rows.push_back({line.substr(0, c1), std::stod(line.substr(c1 + 1, c2 - c1 - 1)),
                        std::stod(line.substr(c2 + 1))});
    }
    return rows;
}

/// `yamsc lin --mbc3` of the 16-DOF model at `rpm`, its oscillating modes.
std::vector<ModeRow> yamsc_modes(double rpm, const std::vector<std::string>& hold) {
    yamsc::driver::LinOptions o;
    o.model = model_path(land_16dof_case);
    o.mbc3 = true;
    o.hold = hold;
    o.at = {{"psi", 1, rpm * M_PI / 30}};
    std::ostringstream out, err;
    REQUIRE_MESSAGE(yamsc::analysis::lin(o, out, err) == 0, err.str());
    MESSAGE(out.str());
    std::vector<ModeRow> rows;
    std::istringstream lines(out.str());
    for (std::string line; std::getline(lines, line);) {
        std::istringstream row(line);
        int mode = 0;
        ModeRow r;
        if (!(row >> mode >> r.freq_hz >> r.damping)) continue;
        std::getline(row, r.label);
        const auto percent = r.label.rfind(", ");
        if (percent != std::string::npos) r.share = std::atof(r.label.c_str() + percent + 2) / 100;
        rows.push_back(r);
    }
    return rows;
}

/// The oscillating modes (above 0.01 Hz: the free yaw's near-zero roots aside).
std::vector<ModeRow> oscillating(std::vector<ModeRow> rows) {
    rows.erase(std::remove_if(rows.begin(), rows.end(),
                              [](const ModeRow& r) { return !(r.freq_hz > 0.01); }),
               rows.end());
    return rows;
}

void check_case(double rpm, const std::vector<std::string>& hold, const std::string& reference) {
    CAPTURE(reference);
    const std::vector<ModeRow> ours = oscillating(yamsc_modes(rpm, hold));
    const std::vector<ModeRow> theirs = oscillating(reference_modes(reference));
    REQUIRE(ours.size() == theirs.size());
    double worst = 0;
    for (std::size_t i = 0; i < ours.size(); ++i) {
        CAPTURE(theirs[i].label);
        const double error = ours[i].freq_hz / theirs[i].freq_hz - 1;
        worst = std::max(worst, std::fabs(error));
        CHECK(std::fabs(error) < 3e-3); // the bar is 2 %
        CHECK(ours[i].damping == doctest::Approx(theirs[i].damping).epsilon(0.05));
        // The labels name the same motion where OpenFAST's is a whirl or collective
        // and one coordinate holds most of the mode (strongly coupled modes, such
        // as the 6 rpm edge BW / flap FW pair, OpenFAST names by frequency order).
        if (ours[i].share < 0.5) continue;
        for (const char* kind : {"BW", "FW", "collective"}) {
            const std::string& l = theirs[i].label;
            if (l.find(kind) == std::string::npos || l.find("edge collective") != std::string::npos)
                continue;
            CHECK(ours[i].label.find(kind) != std::string::npos);
            CHECK(ours[i].label.find(l.find("flap") != std::string::npos ? "flap" : "edge") !=
                  std::string::npos);
        }
    }
    MESSAGE(reference << ": worst frequency difference " << 100 * worst << " %");
}

} // namespace

TEST_CASE("MBC3 modes of the spinning 16-DOF turbine equal OpenFAST's (6 and 12.1 rpm)") {
    convert(land_16dof_case);
    check_case(12.1, {}, "rotating_12.1.csv");
    check_case(12.1, {"nac_yaw"}, "rotating_12.1_yawlocked.csv");
    check_case(6.0, {}, "rotating_6.csv");
    check_case(6.0, {"nac_yaw"}, "rotating_6_yawlocked.csv");
}

TEST_CASE("the Campbell diagram over rotor speed: MBC3 modes at each speed, CSV and SVG") {
    convert(land_16dof_case);
    yamsc::driver::LinOptions o;
    o.model = model_path(land_16dof_case);
    o.mbc3 = true;
    o.hold = {"nac_yaw"};
    // 6 and 12.1 rpm.
    o.sweep = yamsc::driver::parse_sweep("psi'=0.6283185307:0.6387905:1.26711");
    o.output = work_dir + "/campbell_16dof.csv";
    o.plot = work_dir + "/campbell_16dof.svg";
    std::ostringstream out, err;
    REQUIRE_MESSAGE(yamsc::analysis::lin(o, out, err) == 0, err.str());
    std::istringstream csv(read(o.output));
    std::string line;
    std::getline(csv, line);
    CHECK(line == "psi',mode,label,freq_hz,damping_ratio,share");
    std::map<double, std::vector<double>> by_speed;
    while (std::getline(csv, line)) {
        std::istringstream row(line);
        std::string speed, mode, label, freq;
        std::getline(row, speed, ',');
        std::getline(row, mode, ',');
        std::getline(row, label, ',');
        std::getline(row, freq, ',');
        by_speed[std::stod(speed)].push_back(std::stod(freq));
    }
    REQUIRE(by_speed.size() == 2);
    // Each speed's modes are those of OpenFAST's linearization at that speed.
    const std::vector<std::string> references{"rotating_6_yawlocked.csv",
                                              "rotating_12.1_yawlocked.csv"};
    std::size_t k = 0;
    for (const auto& [speed, freqs] : by_speed) {
        CAPTURE(speed);
        const std::vector<ModeRow> theirs = oscillating(reference_modes(references[k++]));
        REQUIRE(freqs.size() == theirs.size());
        for (std::size_t i = 0; i < freqs.size(); ++i)
            CHECK(freqs[i] == doctest::Approx(theirs[i].freq_hz).epsilon(3e-3));
    }
    const std::string svg = read(o.plot);
    for (const char* text : {">1P<", ">3P<", ">6P<", "q_flap1 BW", "psi' [rad/s]"})
        CHECK(svg.find(text) != std::string::npos);
}

TEST_CASE(
    "trim of the parked 16-DOF turbine: the same point from rest and from a perturbed start") {
    convert(land_16dof_case);
    auto trimmed = [](const std::string& at) {
        yamsc::driver::TrimOptions o;
        o.model = model_path(land_16dof_case);
        o.at = yamsc::driver::parse_assignments(at, "--at");
        o.hold = {"psi"}; // the generator locked, as in OpenFAST's parked linearization
        o.json = true;
        std::ostringstream out, err;
        REQUIRE_MESSAGE(yamsc::analysis::trim(o, out, err) == 0, err.str());
        // "q":[...]
        const std::string json = out.str();
        const auto start = json.find("\"q\":[") + 5;
        std::istringstream list(json.substr(start, json.find(']', start) - start));
        std::vector<double> q;
        for (std::string item; std::getline(list, item, ',');) q.push_back(std::stod(item));
        return q;
    };
    const std::vector<double> rest = trimmed("psi'=0");
    const std::vector<double> perturbed =
        trimmed("psi'=0,q_fa1=0.5,q_ss1=-0.3,q_b1_flap1=2,q_b2_edge1=-0.4,drtr=0.01");
    REQUIRE(rest.size() == 16);
    REQUIRE(perturbed.size() == 16);
    for (std::size_t i = 0; i < rest.size(); ++i) {
        CAPTURE(i);
        CHECK(perturbed[i] == doctest::Approx(rest[i]).scale(1).epsilon(1e-7));
    }
    // the overhanging rotor and nacelle bend the tower 13.7 mm upwind; blade 1
    // points up, blades 2 and 3 sag edgewise under their own weight
    CHECK(rest[0] == doctest::Approx(-0.013729).epsilon(1e-4));
    CHECK(rest[11] == doctest::Approx(-rest[14]).epsilon(0.1));
}
