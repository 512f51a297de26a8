// The model text of an ElastoDyn turbine (see model.hpp and docs/openfast.md).
//
// Frames follow OpenFAST's inertial axes: x downwind, y to the left looking downwind, z
// up. The tower's fore-aft modes bend along +x, its side-side modes along +y; ElastoDyn's
// side-side DOF points the other way, so `Q_TSS1 = -q_ss1`. The shaft frame is turned
// about y by -ShftTilt (ElastoDyn's negative tilt raises the upwind rotor) and the rotor
// spins about its +x axis (clockwise seen from upwind), blade 1 along +z at azimuth 0.
#include "openfast/model.hpp"

#include "openfast/gauges.hpp"
#include "text/number.hpp"

#include <cctype>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <sstream>

namespace yamsc::openfast {

namespace {

struct DofInfo {
    const char* flag;
    const char* name; // the model's DOF (blade DOFs: with {k} for the blade number)
    const char* doc;
};

const std::vector<DofInfo>& dof_table() {
    static const std::vector<DofInfo> table{
        {"PtfmSgDOF", "surge", "platform surge of the reference point, along x [m]"},
        {"PtfmSwDOF", "sway", "platform sway of the reference point, along y [m]"},
        {"PtfmHvDOF", "heave", "platform heave of the reference point, along z [m]"},
        {"PtfmRDOF", "roll", "platform roll about x [rad]"},
        {"PtfmPDOF", "pitch", "platform pitch about y, tower top downwind when > 0 [rad]"},
        {"PtfmYDOF", "yaw", "platform yaw about z [rad]"},
        {"TwFADOF1", "q_fa1", "tower fore-aft mode 1: tower-top deflection along x [m]"},
        {"TwSSDOF1", "q_ss1", "tower side-side mode 1: tower-top deflection along y [m]"},
        {"TwFADOF2", "q_fa2", "tower fore-aft mode 2 [m]"},
        {"TwSSDOF2", "q_ss2", "tower side-side mode 2 [m]"},
        {"YawDOF", "nac_yaw", "nacelle yaw about the tower-top z axis [rad]"},
        {"GenDOF", "psi", "generator azimuth (the rotor's without drivetrain twist) [rad]"},
        {"DrTrDOF", "drtr", "drivetrain torsion: rotor azimuth minus generator azimuth [rad]"}};
    return table;
}

const char* const blade_modes[3][4] = {{"FlapDOF1", "flap1", "F1", "first flapwise mode"},
                                       {"EdgeDOF", "edge1", "E1", "first edgewise mode"},
                                       {"FlapDOF2", "flap2", "F2", "second flapwise mode"}};

class Writer {
public:
    Writer(const OpenFastModelInput& in, diag::Diagnostics& diags)
        : in_(in), d_(*in.deck), diags_(diags) {}

    std::string text() {
        header();
        parameters();
        inputs();
        dofs();
        out_ << "\ngravity (0, 0, -Gravity)\n";
        bodies();
        loads();
        initial_state();
        outputs();
        displacement_outputs();
        load_outputs();
        operation_outputs();
        rotor_block();
        platform_blocks();
        return out_.str();
    }

private:
    bool on(const std::string& flag) const {
        auto it = in_.dofs.find(flag);
        return it != in_.dofs.end() && it->second;
    }
    bool platform() const {
        for (const char* f :
             {"PtfmSgDOF", "PtfmSwDOF", "PtfmHvDOF", "PtfmRDOF", "PtfmPDOF", "PtfmYDOF"})
            if (on(f)) return true;
        return false;
    }
    /// A platform frame: platform DOFs, or platform offsets held fixed (ElastoDyn's
    /// PtfmSurge .. PtfmYaw are "initial or fixed").
    bool platform_frame() const {
        if (platform()) return true;
        for (const char* k :
             {"PtfmSurge", "PtfmSway", "PtfmHeave", "PtfmRoll", "PtfmPitch", "PtfmYaw"})
            if (v(k) != 0) return true;
        return false;
    }
    /// HydroDyn (CompHydro 1) as `load hydrodyn` on the platform, instead of the
    /// hydrodynamic inputs; MAP++ or MoorDyn (CompMooring 1 or 3) as `load
    /// mooring`, quasi-static lines either way (their seabed needs the .fst's
    /// WtrDpth).
    bool hydro_block() const { return platform() && !d_.offshore.hydro_file.empty(); }
    bool mooring_block() const {
        return platform() && !d_.offshore.mooring_file.empty() && d_.offshore.water_depth;
    }
    bool flexible_tower() const { return openfast::flexible_tower(in_.dofs); }
    bool flexible_blades() const { return openfast::flexible_blades(in_.dofs); }
    /// A body per blade (flexible, or rigid when every DOF is off): blade root loads.
    bool blade_bodies() const { return flexible_blades() || !in_.blades.empty(); }
    /// In wind the blades turn with the controller's pitch, as ElastoDyn turns them
    /// with ServoDyn's BlPitchCom; otherwise they sit at the deck's BlPitch.
    bool pitched_by_input() const { return in_.operation && blade_bodies(); }
    /// Blade k's pitch in the model's expressions ("" when it is 0).
    std::string blade_pitch(int k) const {
        if (pitched_by_input()) return "pitch";
        const std::string name = "BlPitch" + std::to_string(k);
        return v(name) != 0 ? name : "";
    }
    double v(const std::string& key) const { return d_[key]; }
    /// The rotating body the generator torque acts on and the rotor hangs from.
    std::string shaft_body() const {
        return on("DrTrDOF") ? "gen_shaft" : flexible_blades() ? "hub" : "rotor";
    }

    static std::string pad(const std::string& s, std::size_t width) {
        return s.size() >= width ? s + " " : s + std::string(width - s.size(), ' ');
    }
    void param(const std::string& name, const std::string& value, const std::string& doc) {
        out_ << pad("param " + name + " = " + value, 34) << "# " << doc << "\n";
    }
    void param(const std::string& name, double value, const std::string& doc) {
        param(name, mbd_number(value), doc);
    }
    void param_deg(const std::string& name, double degrees, const std::string& doc) {
        param(name, mbd_number(degrees) + " deg", doc);
    }
    std::string where(const std::string& key) const {
        std::string k;
        for (char c : key)
            if (c != '(' && c != ')')
                k += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        auto it = d_.where.find(k);
        return it == d_.where.end() ? key : key + ", " + it->second;
    }

    void header() {
        out_ << "# Generated by `yamsc from-openfast " << in_.source << "`.\n";
        if (!d_.title.empty()) out_ << "# " << d_.title << "\n";
        out_ << "#\n"
                "# A template model (docs/openfast.md): the DOFs the deck enables, ElastoDyn's\n"
                "# geometry, masses and inertias, gravity and initial conditions. Aerodynamic,\n"
                "# generator, hydrodynamic and distributed tower loads are inputs (0 unless\n"
                "# given). Outputs named as OpenFAST channels feed `yamsc sim --channels "
                "openfast`.\n"
                "# To switch a DOF off, write the model again with `--dofs NAME=off` (ElastoDyn's\n"
                "# flag), or delete its `dof` line, its joint step or mode, and its genforce,\n"
                "# initial and output lines.\n";
        if (d_.tmax && d_.dt)
            out_ << "# The OpenFAST run: TMax = " << mbd_number(*d_.tmax)
                 << " s, DT = " << mbd_number(*d_.dt) << " s.\n";
        if (in_.operation) operation_header(*in_.operation);
        if (hydro_block() || mooring_block()) {
            out_ << "# The platform's loads are load blocks (docs/hydrodynamics.md, Using it):\n"
                 << "#   yamsc sim " << in_.output_file;
            if (hydro_block()) {
                out_ << " --hydro " << d_.offshore.hydro_file;
                if (!d_.offshore.sea_state_file.empty())
                    out_ << " --sea-state " << d_.offshore.sea_state_file;
            }
            if (mooring_block()) out_ << " --mooring " << d_.offshore.mooring_file;
            out_ << "\n";
        }
        std::string enabled, disabled;
        for (const std::string& flag : openfast::elastodyn_dof_flags()) {
            if (flag == "TeetDOF") continue;
            (on(flag) ? enabled : disabled) +=
                (on(flag) ? enabled : disabled).empty() ? flag : ", " + flag;
        }
        out_ << "# DOFs on:  " << (enabled.empty() ? "none" : enabled) << "\n";
        wrapped("# DOFs off: ", disabled.empty() ? "none" : disabled);
        if (!d_.ignored.empty())
            out_ << "# Entries without effect on the structural model (outputs, simulation "
                    "control,\n# glue code, two-bladed rotors), by file, as key:line:\n";
        for (std::size_t i = 0; i < d_.ignored.size();) {
            const std::string& file = d_.ignored[i].first;
            std::string list;
            for (; i < d_.ignored.size() && d_.ignored[i].first == file; ++i)
                list += (list.empty() ? "" : ", ") + d_.ignored[i].second;
            wrapped("#   " + file + ":", list);
        }
        out_ << "model " << in_.name << " " << mbd_string(d_.title.empty() ? in_.name : d_.title)
             << "\n";
    }

    void wrapped(const std::string& first, const std::string& text) {
        std::string line = first;
        std::istringstream words(text);
        for (std::string w; words >> w;) {
            if (line.size() + w.size() + 1 > 92 && line.size() > 6) {
                out_ << line << "\n";
                line = "#     ";
            }
            line += (line.back() == ' ' ? "" : " ") + w;
        }
        out_ << line << "\n";
    }

    void parameters() {
        out_ << "\n# ---- ElastoDyn entries (names as in the deck; lengths in m, masses in kg)\n";
        param("Gravity", v("Gravity"),
              "gravitational acceleration [m/s^2] (" + where("Gravity") + ")");
        param("TowerHt", v("TowerHt"), "height of the tower top above ground or MSL [m]");
        param("TowerBsHt", v("TowerBsHt"), "height of the tower base above ground or MSL [m]");
        param("Twr2Shft", v("Twr2Shft"), "height of the shaft above the tower top [m]");
        param("OverHang", v("OverHang"), "rotor apex from the yaw axis, along the shaft [m]");
        param_deg("ShftTilt", v("ShftTilt"), "shaft tilt; < 0 raises the upwind end");
        param("NacCMxn", v("NacCMxn"), "nacelle centre of mass from the tower top, downwind [m]");
        param("NacCMyn", v("NacCMyn"), "... lateral (along y) [m]");
        param("NacCMzn", v("NacCMzn"), "... vertical [m]");
        param("NacMass", v("NacMass"), "nacelle mass [kg]");
        param("NacYIner", v("NacYIner"), "nacelle inertia about the yaw axis [kg m^2]");
        if (v("YawBrMass") != 0) param("YawBrMass", v("YawBrMass"), "yaw bearing mass [kg]");
        param("GenIner", v("GenIner"), "generator inertia about the high-speed shaft [kg m^2]");
        param("GBRatio", v("GBRatio"), "gearbox ratio");
        param("ShftGagL", v("ShftGagL"),
              "shaft strain gages from the rotor apex, > 0 for upwind rotors [m]");
        if (on("DrTrDOF")) {
            param("DTTorSpr", v("DTTorSpr"), "drivetrain torsional stiffness [N m/rad]");
            param("DTTorDmp", v("DTTorDmp"), "drivetrain torsional damping [N m s/rad]");
        }
        if (v("AzimB1Up") != 0)
            param_deg("AzimB1Up", v("AzimB1Up"), "azimuth reported when blade 1 points up");
        if (platform_frame()) {
            param("PtfmRefzt", v("PtfmRefzt"), "height of the platform reference point [m]");
            param("PtfmCMxt", v("PtfmCMxt"), "platform centre of mass, downwind [m]");
            param("PtfmCMyt", v("PtfmCMyt"), "... lateral [m]");
            param("PtfmCMzt", v("PtfmCMzt"), "... height above ground or MSL [m]");
            param("PtfmMass", v("PtfmMass"), "platform mass [kg]");
            param("PtfmRIner", v("PtfmRIner"), "platform roll inertia about its CM [kg m^2]");
            param("PtfmPIner", v("PtfmPIner"), "platform pitch inertia about its CM [kg m^2]");
            param("PtfmYIner", v("PtfmYIner"), "platform yaw inertia about its CM [kg m^2]");
            for (const char* k : {"PtfmXYIner", "PtfmYZIner", "PtfmXZIner"})
                if (v(k) != 0) param(k, v(k), "platform product of inertia (-integral) [kg m^2]");
            if ((hydro_block() || mooring_block()) && d_.offshore.water_density)
                param("WtrDens", *d_.offshore.water_density, "water density (the .fst's) [kg/m^3]");
            if ((hydro_block() || mooring_block()) && d_.offshore.water_depth)
                param("WtrDpth", *d_.offshore.water_depth, "water depth (the .fst's) [m]");
        }
        if (blade_bodies()) {
            param("HubMass", v("HubMass"), "hub mass [kg]");
            param("HubIner", v("HubIner"), "hub inertia about the shaft [kg m^2]");
            param("HubCM", v("HubCM"), "hub centre of mass from the apex, downwind [m]");
            param("HubRad", v("HubRad"), "blade root from the apex [m]");
            if (flexible_blades()) param("TipRad", v("TipRad"), "blade tip from the apex [m]");
            for (int k = 1; k <= d_.blades; ++k) {
                const std::string n = std::to_string(k);
                param_deg("PreCone" + n, v("PreCone" + n), "cone of blade " + n + "; > 0 downwind");
                if (!pitched_by_input() && v("BlPitch" + n) != 0)
                    param_deg("BlPitch" + n, v("BlPitch" + n), "pitch of blade " + n);
                if (flexible_blades() && v("TipMass" + n) != 0)
                    param("TipMass" + n, v("TipMass" + n),
                          "tip-brake mass of blade " + n + " [kg]");
            }
            if (!flexible_blades()) rigid_blade_parameters();
        } else if (in_.rotor) {
            const RigidProperties& r = *in_.rotor;
            out_ << "# The rigid rotor: hub (HubMass at HubCM, HubIner) and " << d_.blades
                 << " blades with their precone, each\n# lumped on BldNodes = " << d_.blade_nodes
                 << " elements as ElastoDyn does (AdjBlMs included); tip masses.\n";
            param("RotMass", r.mass, "rotor mass [kg]");
            param("RotCMx", r.cm[0], "rotor centre of mass from the apex, along the shaft [m]");
            if (r.cm[1] != 0 || r.cm[2] != 0) {
                param("RotCMy", r.cm[1], "... along y [m]");
                param("RotCMz", r.cm[2], "... along z [m]");
            }
            param("RotIxx", r.inertia[0], "rotor inertia about the shaft [kg m^2]");
            param("RotIyy", r.inertia[1], "rotor inertia about y through its CM [kg m^2]");
            param("RotIzz", r.inertia[2], "rotor inertia about z through its CM [kg m^2]");
            if (r.inertia[3] != 0 || r.inertia[4] != 0 || r.inertia[5] != 0) {
                param("RotIxy", r.inertia[3], "product of inertia [kg m^2]");
                param("RotIyz", r.inertia[4], "product of inertia [kg m^2]");
                param("RotIxz", r.inertia[5], "product of inertia [kg m^2]");
            }
        }
        if (!flexible_tower() && in_.tower) {
            out_ << "# The rigid tower, lumped on TwrNodes = " << d_.tower_nodes
                 << " elements as ElastoDyn does (AdjTwMa included).\n";
            param("TwrMass", in_.tower->mass, "tower mass [kg]");
            param("TwrCMz", in_.tower->cm[2], "tower centre of mass above its base [m]");
            param("TwrIner", in_.tower->inertia[0],
                  "tower inertia about a horizontal axis through its CM [kg m^2]");
        }
        if (!on("GenDOF")) {
            param("psi0", mbd_number(v("Azimuth") - v("AzimB1Up")) + " deg",
                  "rotor azimuth at t = 0 (Azimuth - AzimB1Up)");
            param("Omega0", rpm(v("RotSpeed")), "fixed rotor speed (RotSpeed, GenDOF off) [rad/s]");
        }
        if (in_.operation) operation_parameters(*in_.operation);
        if (in_.yaw_spring) yaw_spring_parameters(*in_.yaw_spring);
    }

    void yaw_spring_parameters(const YawSpring& y) {
        out_ << "\n# ---- ServoDyn's nacelle-yaw spring and damper (names as in its file)\n";
        param("YawSpr", y.stiffness,
              "nacelle-yaw spring constant [N m/rad] (" + y.stiffness_from + ")");
        param("YawDamp", y.damping,
              "nacelle-yaw damping constant [N m s/rad] (" + y.damping_from + ")");
        param_deg("YawNeut", y.neutral_deg,
                  "neutral yaw position: the spring's moment is 0 there (" + y.neutral_from + ")");
    }

    static std::string rpm(double value) {
        return value == 0 ? "0" : mbd_number(value) + " * pi / 30";
    }

    void inputs() {
        out_ << "\n# ---- loads (inputs; 0 unless given, e.g. `yamsc sim --u thrust=8e5`)\n";
        if (in_.operation) {
            input("V_wind", "hub-height wind speed [m/s] (`--wind`)");
            if (pitched_by_input())
                // ElastoDyn without PitchDOF takes the pitch as prescribed and leaves its
                // rates out of the blades' motion: pitch' and pitch'' stay 0.
                input("pitch order 2", "collective blade pitch [rad] (the controller's): the "
                                       "blades turn with it; pitch', pitch'' 0 as in ElastoDyn");
            else
                input("pitch",
                      "collective blade pitch of the rotor block [rad] (the controller's)");
        }
        const std::string added = in_.operation ? " (`--aero` adds the table's)" : "";
        input("thrust", "rotor thrust at the apex along the shaft [N]" + added);
        input("aero_torque", "aerodynamic torque on the rotor about the shaft [N m]" + added);
        input("gen_torque", "generator torque on the high-speed shaft [N m]");
        if (platform() && !hydro_block())
            for (const char* c : {"x", "y", "z"}) {
                input(std::string("hydro_f") + c, std::string("platform force along ") + c +
                                                      " (ground axes) at the reference point [N]");
                input(std::string("hydro_m") + c,
                      std::string("platform moment about ") + c + " (ground axes) [N m]");
            }
        for (const char* m : {"fa1", "ss1", "fa2", "ss2"})
            if (tower_mode_on(m))
                input(std::string("f_") + m,
                      std::string("generalized force of distributed tower loads on mode ") + m +
                          " [N]");
        if (on("YawDOF")) input("yaw_moment", "yaw moment of the tower on the nacelle [N m]");
        for (int k = 1; k <= d_.blades; ++k)
            for (const auto& mode : blade_modes)
                if (on(mode[0]))
                    input(blade_dof(k, mode[1], "f_"),
                          std::string("generalized aerodynamic force on the ") + mode[3] +
                              " of blade " + std::to_string(k) + " [N]");
    }
    void input(const std::string& name, const std::string& doc) {
        out_ << pad("input " + name, 34) << "# " << doc << "\n";
    }
    bool tower_mode_on(const std::string& m) const {
        if (m == "fa1") return on("TwFADOF1");
        if (m == "ss1") return on("TwSSDOF1");
        if (m == "fa2") return on("TwFADOF2");
        return on("TwSSDOF2");
    }
    static std::string blade_dof(int k, const std::string& mode, const std::string& prefix = "q_") {
        return prefix + "b" + std::to_string(k) + "_" + mode;
    }

    /// Every DOF off: each blade one rigid body, lumped on BldNodes elements as ElastoDyn
    /// lumps it, so that its root loads are the reactions of its joint.
    void rigid_blade_parameters() {
        out_ << "# The rigid blades, each lumped on BldNodes = " << d_.blade_nodes
             << " elements as ElastoDyn does (AdjBlMs\n# included) with its tip mass, in its "
                "own frame (root at the origin, along z).\n";
        for (std::size_t i = 0; i < in_.blades.size(); ++i) {
            const RigidProperties& b = in_.blades[i];
            const std::string n = std::to_string(i + 1);
            param("BldMass" + n, b.mass, "blade " + n + " with its tip mass [kg]");
            param("BldCM" + n, b.cm[2], "its centre of mass from the root [m]");
            param("BldIner" + n, b.inertia[0], "its inertia about the CM, flap and edge [kg m^2]");
        }
    }

    void dofs() {
        out_ << "\n# ---- DOFs (ElastoDyn's order)\n";
        int count = 0;
        for (const DofInfo& info : dof_table())
            if (on(info.flag)) {
                out_ << pad(std::string("dof ") + info.name, 34) << "# " << info.flag << ": "
                     << info.doc << "\n";
                ++count;
            }
        for (int k = 1; k <= d_.blades; ++k)
            for (const auto& mode : blade_modes)
                if (on(mode[0])) {
                    out_ << pad("dof " + blade_dof(k, mode[1]), 34) << "# " << mode[0] << ": "
                         << mode[3] << " of blade " << k << ", tip deflection [m]\n";
                    ++count;
                }
        if (count == 0) out_ << "# (none: every DOF is off)\n";
    }

    void bodies() {
        out_ << "\n# ---- bodies and joints\n";
        std::string tower_parent = "ground";
        std::string tower_at = "(0, 0, TowerBsHt)";
        if (platform_frame()) {
            out_ << "rigid platform {\n    mass = PtfmMass\n"
                    "    com = (PtfmCMxt, PtfmCMyt, PtfmCMzt - PtfmRefzt)\n";
            if (v("PtfmXYIner") != 0 || v("PtfmYZIner") != 0 || v("PtfmXZIner") != 0)
                out_ << "    inertia = (PtfmRIner, PtfmPIner, PtfmYIner, "
                     << (v("PtfmXYIner") != 0 ? "PtfmXYIner" : "0") << ", "
                     << (v("PtfmYZIner") != 0 ? "PtfmYZIner" : "0") << ", "
                     << (v("PtfmXZIner") != 0 ? "PtfmXZIner" : "0") << ")\n";
            else
                out_ << "    inertia = (PtfmRIner, PtfmPIner, PtfmYIner)\n";
            out_ << "}\n";
            // ElastoDyn's platform rotations are small-angle (closest orthonormal matrix);
            // here they are exact rotations about x, then y, then z.
            std::string steps = "at (0, 0, PtfmRefzt)";
            const char* names[6][4] = {{"PtfmSgDOF", "translate x", "surge", "PtfmSurge"},
                                       {"PtfmSwDOF", "translate y", "sway", "PtfmSway"},
                                       {"PtfmHvDOF", "translate z", "heave", "PtfmHeave"},
                                       {"PtfmRDOF", "rotate x", "roll", "PtfmRoll"},
                                       {"PtfmPDOF", "rotate y", "pitch", "PtfmPitch"},
                                       {"PtfmYDOF", "rotate z", "yaw", "PtfmYaw"}};
            for (const auto& n : names) {
                const bool angle = std::string(n[1]).rfind("rotate", 0) == 0;
                if (on(n[0]))
                    steps += std::string("; ") + n[1] + " " + n[2];
                else if (v(n[3]) != 0) // held at the deck's value
                    steps += std::string("; ") + n[1] + " " + mbd_number(v(n[3])) +
                             (angle ? " deg" : "");
            }
            out_ << "joint ground -> platform { " << steps << " }\n";
            tower_parent = "platform";
            tower_at = "(0, 0, TowerBsHt - PtfmRefzt)";
        }
        std::string top; // how a joint starts at the tower top
        if (flexible_tower()) {
            std::string modes;
            for (const char* m : {"fa1", "ss1", "fa2", "ss2"})
                if (tower_mode_on(m))
                    modes += (modes.empty() ? "" : ", ") + std::string(m) + " -> q_" + m;
            out_ << "flexible tower {\n    beam " << mbd_string(in_.tower_path)
                 << " elastodyn_tower {\n        length = TowerHt - TowerBsHt\n        modes = ("
                 << modes << ")\n        elements = " << d_.tower_nodes << "\n    }\n}\n";
            top = "joint tower.tip -> ";
        } else {
            out_ << "rigid tower { mass = TwrMass; com = (0, 0, TwrCMz); inertia = (TwrIner, "
                    "TwrIner, 0) }\n";
            top = "joint tower -> ";
        }
        out_ << "joint " << tower_parent << " -> tower { at " << tower_at << " }\n";
        const std::string top_at = flexible_tower() ? "" : "at (0, 0, TowerHt - TowerBsHt)";
        if (v("YawBrMass") != 0) {
            out_ << "rigid yaw_bearing { mass = YawBrMass }\n"
                 << top << "yaw_bearing" << (top_at.empty() ? "" : " { " + top_at + " }") << "\n";
        }
        // ElastoDyn's nacelle has inertia about the yaw axis only.
        out_ << "rigid nacelle {\n    mass = NacMass\n    com = (NacCMxn, NacCMyn, NacCMzn)\n"
                "    inertia = (0, 0, NacYIner - NacMass * (NacCMxn^2 + NacCMyn^2))\n}\n";
        // ElastoDyn turns the tower top by an orthonormal matrix of the slopes (its
        // SmllRotTrans) with the slopes' rates as angular velocity, which `exact` (the
        // default, written out) matches closest: 0.03 % in a 2 m free decay, 0.08 % with
        // `small` (docs/validation.md).
        std::string yaw_steps = flexible_tower() ? "elastic_rotation = exact" : top_at;
        if (on("YawDOF"))
            yaw_steps += (yaw_steps.empty() ? "" : "; ") + std::string("rotate z nac_yaw");
        else if (v("NacYaw") != 0)
            yaw_steps += (yaw_steps.empty() ? "" : "; ") + std::string("rotate z ") +
                         mbd_number(v("NacYaw")) + " deg";
        out_ << top << "nacelle" << (yaw_steps.empty() ? "" : " { " + yaw_steps + " }") << "\n";
        rotor();
    }

    void rotor() {
        const std::string shaft = "at (0, 0, Twr2Shft); rotate y -ShftTilt; at (OverHang, 0, 0)";
        const std::string spin = on("GenDOF") ? "psi" : "psi0 + Omega0 * t";
        std::string rotor_name = flexible_blades() ? "hub" : "rotor";
        std::string rotor_parent = "nacelle", rotor_steps = shaft + "; rotate x " + spin;
        // ElastoDyn's generator turns at GBRatio times the generator azimuth with the
        // inertia GenIner about the shaft: its spin energy is that of GenIner GBRatio^2
        // on the low-speed shaft, its angular momentum (gyroscopic moments on the nacelle
        // and tower) only GBRatio times GenIner's. A body on the low-speed shaft with
        // GenIner GBRatio^2 would carry GBRatio times too much (docs/openfast.md).
        out_ << "# The generator: GenIner about the high-speed shaft, geared to the rotor.\n";
        out_ << "rigid generator { mass = 0; inertia = (GenIner, 0, 0) }\n";
        out_ << "joint nacelle -> generator { " << shaft << "; rotate x GBRatio * "
             << (on("GenDOF") ? spin : "(" + spin + ")") << " }\n";
        if (on("DrTrDOF")) {
            out_ << "# The generator side of the drivetrain (the low-speed shaft at the generator "
                    "azimuth)\n# and the rotor, twisted by drtr against the drivetrain spring.\n";
            out_ << "rigid gen_shaft { mass = 0 }\n";
            out_ << "joint nacelle -> gen_shaft { " << shaft << "; rotate x " << spin << " }\n";
            rotor_parent = "gen_shaft";
            rotor_steps = "rotate x drtr";
        }
        if (blade_bodies()) {
            out_ << "rigid " << rotor_name
                 << " { mass = HubMass; com = (HubCM, 0, 0); inertia = (HubIner, 0, 0) }\n";
        } else {
            const RigidProperties& r = *in_.rotor;
            const bool offset = r.cm[1] != 0 || r.cm[2] != 0;
            const bool products = r.inertia[3] != 0 || r.inertia[4] != 0 || r.inertia[5] != 0;
            out_ << "rigid rotor {\n    mass = RotMass\n    com = (RotCMx, "
                 << (offset ? "RotCMy, RotCMz" : "0, 0") << ")\n    inertia = (RotIxx"
                 << ", RotIyy, RotIzz" << (products ? ", RotIxy, RotIyz, RotIxz" : "") << ")\n}\n";
        }
        out_ << "joint " << rotor_parent << " -> " << rotor_name << " { " << rotor_steps << " }\n";
        if (on("DrTrDOF")) out_ << "spring drtr stiffness DTTorSpr damping DTTorDmp\n";
        if (!blade_bodies()) return;
        for (int k = 1; k <= d_.blades; ++k) {
            const std::string n = std::to_string(k);
            if (flexible_blades())
                flexible_blade(k);
            else
                out_ << "rigid blade" << n << " { mass = BldMass" << n << "; com = (0, 0, BldCM"
                     << n << "); inertia = (BldIner" << n << ", BldIner" << n << ", 0) }\n";
            std::string steps;
            if (k > 1) steps = "rotate x " + mbd_number(360.0 * (k - 1) / d_.blades) + " deg; ";
            steps += "rotate y PreCone" + n + "; at (0, 0, HubRad)";
            // ElastoDyn pitches a blade about its -z axis (towards feather).
            if (!blade_pitch(k).empty()) steps += "; rotate z -" + blade_pitch(k);
            out_ << "joint " << rotor_name << " -> blade" << n << " { " << steps << " }\n";
            if (flexible_blades() && v("TipMass" + n) != 0)
                out_ << "rigid tip_mass" << n << " { mass = TipMass" << n << " }\njoint blade" << n
                     << ".tip -> tip_mass" << n << "\n";
        }
    }

    void flexible_blade(int k) {
        std::string modes;
        for (const auto& mode : blade_modes)
            if (on(mode[0]))
                modes += (modes.empty() ? "" : ", ") + std::string(mode[1]) + " -> " +
                         blade_dof(k, mode[1]);
        out_ << "flexible blade" << k << " {\n    beam "
             << mbd_string(in_.blade_paths[static_cast<std::size_t>(k - 1)])
             << " elastodyn_blade {\n        length = TipRad - HubRad\n        modes = (" << modes
             << ")\n        elements = " << d_.blade_nodes << "\n    }\n}\n";
    }

    void loads() {
        out_ << "\n# ---- loads\n";
        const std::string rotor = flexible_blades() ? "hub" : "rotor";
        const std::string gen = on("DrTrDOF") ? "gen_shaft" : rotor;
        out_ << "force  on " << rotor << " in " << rotor << " = (thrust, 0, 0)\n";
        const std::string tq = generator_torque();
        if (gen == rotor) {
            out_ << "torque on " << rotor << " in " << rotor << " = (aero_torque - GBRatio * " << tq
                 << ", 0, 0)\n";
        } else {
            out_ << "torque on " << rotor << " in " << rotor << " = (aero_torque, 0, 0)\n";
            out_ << "torque on " << gen << " in " << gen << " = (-GBRatio * " << tq << ", 0, 0)\n";
        }
        out_ << "torque on nacelle in " << gen << " = (GBRatio * " << tq
             << ", 0, 0)     # the generator's reaction\n";
        if (platform() && !hydro_block()) {
            out_ << "force  on platform in ground = (hydro_fx, hydro_fy, hydro_fz)\n";
            out_ << "torque on platform in ground = (hydro_mx, hydro_my, hydro_mz)\n";
        }
        for (const char* m : {"fa1", "ss1", "fa2", "ss2"})
            if (tower_mode_on(m)) out_ << "genforce q_" << m << " = f_" << m << "\n";
        if (on("YawDOF")) {
            out_ << "torque on nacelle in nacelle = (0, 0, yaw_moment)\n";
            out_ << "torque on tower in nacelle = (0, 0, -yaw_moment)\n";
        }
        if (on("YawDOF") && in_.yaw_spring)
            out_ << "# ServoDyn's yaw moment on the yaw DOF, -YawSpr (nac_yaw - YawNeut) - YawDamp "
                    "nac_yaw':\n# the spring and damper, and the spring's moment at zero yaw\n"
                    "spring nac_yaw stiffness YawSpr damping YawDamp\n"
                    "genforce nac_yaw = YawSpr * YawNeut\n";
        for (int k = 1; k <= d_.blades; ++k)
            for (const auto& mode : blade_modes)
                if (on(mode[0]))
                    out_ << "genforce " << blade_dof(k, mode[1]) << " = "
                         << blade_dof(k, mode[1], "f_") << "\n";
        spin_inertia_torque();
    }

    /// The blades' inertia about the shaft changes to second order with their
    /// deflection (the flapped blade shortens radially, the edge deflection moves mass
    /// sideways); ElastoDyn's kinematics hold it, the SID's inertia is first order in q.
    /// Its missing rate of angular momentum, -d/dt(J2(q) Omega), acts on the hub. The
    /// blades' equations already carry its counterpart, the centrifugal stiffening.
    void spin_inertia_torque() {
        if (!flexible_blades() || in_.blade_tips.size() < static_cast<std::size_t>(d_.blades))
            return;
        std::string j2, j2dot;
        for (int k = 1; k <= d_.blades; ++k) {
            const auto& c = in_.blade_tips[static_cast<std::size_t>(k - 1)].spin_inertia;
            for (std::size_t a = 0; a < 3; ++a) {
                if (!on(blade_modes[a][0])) continue;
                const std::string qa = blade_dof(k, blade_modes[a][1]);
                for (std::size_t b = 0; b < 3; ++b) {
                    if (!on(blade_modes[b][0])) continue;
                    const std::string qb = blade_dof(k, blade_modes[b][1]);
                    if (b >= a) j2 += term((a == b ? 1 : 2) * c[a][b], qa + " * " + qb);
                    j2dot += term(2 * c[a][b], qa + " * " + qb + "'");
                }
            }
        }
        std::string omega, omega_dot;
        if (on("GenDOF")) {
            omega = on("DrTrDOF") ? "(psi' + drtr')" : "psi'";
            omega_dot = on("DrTrDOF") ? "(psi'' + drtr'')" : "psi''";
        } else {
            omega = on("DrTrDOF") ? "(Omega0 + drtr')" : "Omega0";
            omega_dot = on("DrTrDOF") ? "drtr''" : "";
        }
        out_
            << "# The blades' second-order inertia about the shaft, J2 = sum c q_j q_k (the SID's\n"
               "# is first order; docs/openfast.md): its rate of angular momentum on the hub.\n";
        out_ << "torque on hub in hub = (-((" << strip(j2dot) << ") * " << omega;
        if (!omega_dot.empty()) out_ << " + (" << strip(j2) << ") * " << omega_dot;
        out_ << "), 0, 0)\n";
        shortening_coriolis_forces(omega);
    }

    /// The Coriolis forces of the blades' radial shortening (BladeTipShapes::
    /// shortening_coriolis, D): the spin Omega and the shortening rate give an in-plane
    /// force on the edge mode, the in-plane velocities a radial one on the shortening:
    /// Q_i = 2 Omega sum_jk (D_jik - D_ijk) q_k q_j', gyroscopic (no power). Their moment
    /// about the shaft is already in the spin-inertia torque, which acts on the hub; without
    /// these the blades' share of it is missing and the drivetrain-edge mode (1.7 Hz) is
    /// driven at twice the flap frequency with the wrong sign (docs/openfast.md).
    void shortening_coriolis_forces(const std::string& omega) {
        out_ << "# The Coriolis forces of the blades' radial shortening on their modes\n"
                "# (ElastoDyn's AxRedBld in the partial velocities; docs/openfast.md).\n";
        for (int k = 1; k <= d_.blades; ++k) {
            const auto& d = in_.blade_tips[static_cast<std::size_t>(k - 1)].shortening_coriolis;
            for (std::size_t i = 0; i < 3; ++i) {
                if (!on(blade_modes[i][0])) continue;
                std::string sum;
                for (std::size_t j = 0; j < 3; ++j) {
                    if (!on(blade_modes[j][0])) continue;
                    for (std::size_t l = 0; l < 3; ++l) {
                        if (!on(blade_modes[l][0])) continue;
                        const double c = 2 * (d[j][i][l] - d[i][j][l]);
                        if (std::fabs(c) < 1e-12) continue;
                        sum += term(c, blade_dof(k, blade_modes[l][1]) + " * " +
                                           blade_dof(k, blade_modes[j][1]) + "'");
                    }
                }
                if (!sum.empty())
                    out_ << "genforce " << blade_dof(k, blade_modes[i][1]) << " = " << omega
                         << " * (" << strip(sum) << ")\n";
            }
        }
    }

    void initial_state() {
        std::vector<std::pair<std::string, std::string>> lines; // "name = value", comment
        auto set = [&](const std::string& dof, const std::string& value, const std::string& doc) {
            lines.emplace_back(dof + " = " + value, doc);
        };
        const char* platform_ic[6][3] = {
            {"PtfmSgDOF", "surge", "PtfmSurge"}, {"PtfmSwDOF", "sway", "PtfmSway"},
            {"PtfmHvDOF", "heave", "PtfmHeave"}, {"PtfmRDOF", "roll", "PtfmRoll"},
            {"PtfmPDOF", "pitch", "PtfmPitch"},  {"PtfmYDOF", "yaw", "PtfmYaw"}};
        for (int i = 0; i < 6; ++i)
            if (on(platform_ic[i][0]))
                set(platform_ic[i][1], mbd_number(v(platform_ic[i][2])) + (i >= 3 ? " deg" : ""),
                    std::string(platform_ic[i][2]) + " (" + d_.where.at(lower(platform_ic[i][2])) +
                        ")");
        // ElastoDyn puts the tower-top displacement into the first mode of each direction.
        if (on("TwFADOF1") || on("TwFADOF2"))
            set(on("TwFADOF1") ? "q_fa1" : "q_fa2", mbd_number(v("TTDspFA")),
                "TTDspFA (" + d_.where.at("ttdspfa") + ")");
        if (on("TwSSDOF1") || on("TwSSDOF2"))
            set(on("TwSSDOF1") ? "q_ss1" : "q_ss2", mbd_number(v("TTDspSS")),
                "TTDspSS (" + d_.where.at("ttdspss") + "); OpenFAST's Q_TSS1 = -q_ss1");
        if (on("YawDOF"))
            set("nac_yaw", mbd_number(v("NacYaw")) + " deg",
                "NacYaw (" + d_.where.at("nacyaw") + ")");
        if (on("GenDOF")) {
            set("psi", mbd_number(v("Azimuth") - v("AzimB1Up")) + " deg",
                "Azimuth - AzimB1Up (" + d_.where.at("azimuth") + ")");
            set("psi'", rpm(v("RotSpeed")),
                "RotSpeed = " + mbd_number(v("RotSpeed")) + " rpm (" + d_.where.at("rotspeed") +
                    ")");
        }
        if (flexible_blades() && (v("OoPDefl") != 0 || v("IPDefl") != 0)) blade_initial_state(set);
        if (lines.empty()) return;
        out_ << "\n# ---- initial conditions of the deck (`yamsc sim` starts here; --ic "
                "overrides)\n";
        out_ << "initial {\n";
        for (const auto& [assignment, doc] : lines)
            out_ << "    " << pad(assignment, 28) << "# " << doc << "\n";
        out_ << "}\n";
        if (on("GenDOF") && v("RotSpeed") != 0)
            out_ << "linearize { psi' = " << rpm(v("RotSpeed"))
                 << " }   # `yamsc lin` and `sim --linear` about the rotor speed\n";
    }

    /// ElastoDyn's InitBlDefl: OoPDefl and IPDefl (coned frame) solved for the flap and
    /// edge DOFs with the tip values of the twisted shapes (docs/openfast.md).
    template <class Set> void blade_initial_state(Set& set) {
        const double deg = std::acos(-1.0) / 180;
        for (int k = 1; k <= d_.blades; ++k) {
            const std::size_t i = static_cast<std::size_t>(k - 1);
            if (i >= in_.blade_tips.size()) break;
            const BladeInitial b = initial_blade_deflection(
                in_.blade_tips[i], v("BlPitch" + std::to_string(k)) * deg, v("OoPDefl"),
                v("IPDefl"), on("FlapDOF1"), on("FlapDOF2"), on("EdgeDOF"));
            if (!b.warning.empty())
                diags_.warning(diag::Kind::NotSupported, {d_.ed, 0, 0},
                               "blade " + std::to_string(k) + ": " + b.warning);
            const std::string why = "OoPDefl = " + mbd_number(v("OoPDefl")) +
                                    ", IPDefl = " + mbd_number(v("IPDefl")) +
                                    " m at the tip, as ElastoDyn's InitBlDefl";
            if (on("FlapDOF1")) set(blade_dof(k, "flap1"), mbd_number(b.flap1), why);
            if (on("EdgeDOF")) set(blade_dof(k, "edge1"), mbd_number(b.edge1), why);
            if (on("FlapDOF2") && !on("FlapDOF1"))
                set(blade_dof(k, "flap2"), mbd_number(b.flap2), why);
        }
    }

    static std::string lower(std::string s) {
        for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        return s;
    }

    void outputs() {
        out_ << "\n# ---- OpenFAST channels (names, signs and units of OpenFAST's outputs)\n";
        const char* platform_out[6][4] = {{"PtfmSgDOF", "PtfmSurge", "surge", "m"},
                                          {"PtfmSwDOF", "PtfmSway", "sway", "m"},
                                          {"PtfmHvDOF", "PtfmHeave", "heave", "m"},
                                          {"PtfmRDOF", "PtfmRoll", "roll * 180 / pi", "deg"},
                                          {"PtfmPDOF", "PtfmPitch", "pitch * 180 / pi", "deg"},
                                          {"PtfmYDOF", "PtfmYaw", "yaw * 180 / pi", "deg"}};
        for (const auto& p : platform_out)
            if (on(p[0])) output(p[1], p[2], p[3]);
        if (on("TwFADOF1")) output("Q_TFA1", "q_fa1", "m");
        if (on("TwSSDOF1")) output("Q_TSS1", "-q_ss1", "m");
        if (on("TwFADOF2")) output("Q_TFA2", "q_fa2", "m");
        if (on("TwSSDOF2")) output("Q_TSS2", "-q_ss2", "m");
        if (on("YawDOF")) output("NacYaw", "nac_yaw * 180 / pi", "deg");
        const std::string offset = v("AzimB1Up") != 0 ? " + AzimB1Up * 180 / pi" : "";
        if (on("GenDOF")) {
            const std::string azimuth = on("DrTrDOF") ? "(psi + drtr)" : "psi";
            const std::string speed = on("DrTrDOF") ? "(psi' + drtr')" : "psi'";
            output("Azimuth", azimuth + " * 180 / pi" + offset, "deg");
            output("RotSpeed", speed + " * 30 / pi", "rpm");
            output("GenSpeed", "GBRatio * psi' * 30 / pi", "rpm");
        } else {
            // ElastoDyn keeps the generator's speed at RotSpeed and advances its azimuth at it.
            output("Azimuth",
                   "(psi0 + Omega0 * t" + std::string(on("DrTrDOF") ? " + drtr" : "") +
                       ") * 180 / pi" + offset,
                   "deg");
            output("RotSpeed",
                   std::string(on("DrTrDOF") ? "(Omega0 + drtr')" : "Omega0") + " * 30 / pi",
                   "rpm");
            output("GenSpeed", "GBRatio * Omega0 * 30 / pi", "rpm");
        }
        if (on("DrTrDOF")) output("Q_DrTr", "drtr", "rad");
        for (int k = 1; k <= d_.blades; ++k)
            for (const auto& mode : blade_modes)
                if (on(mode[0]))
                    output("Q_B" + std::to_string(k) + mode[2], blade_dof(k, mode[1]), "m");
    }
    /// ElastoDyn's displacement channels (OutListParameters), in its signs and units.
    void displacement_outputs() {
        if (flexible_tower()) {
            out_ << "\n# ---- ElastoDyn's tower-top displacements, in the tower-base frame\n";
            out_ << "# (the nacelle frame starts at the tower top)\n";
            output("TTDspFA", "position(nacelle).x in tower", "m");
            output("TTDspSS", "position(nacelle).y in tower", "m");
        }
        if (on("TwFADOF1")) output("QD_TFA1", "q_fa1'", "m/s");
        if (on("TwSSDOF1")) output("QD_TSS1", "-q_ss1'", "m/s");
        if (on("TwFADOF2")) output("QD_TFA2", "q_fa2'", "m/s");
        if (on("TwSSDOF2")) output("QD_TSS2", "-q_ss2'", "m/s");
        if (on("YawDOF")) {
            output("Q_Yaw", "nac_yaw", "rad");
            output("QD_Yaw", "nac_yaw'", "rad/s");
        }
        if (on("GenDOF")) output("QD_GeAz", "psi'", "rad/s");
        if (on("DrTrDOF")) output("QD_DrTr", "drtr'", "rad/s");
        for (int k = 1; k <= d_.blades; ++k)
            for (const auto& mode : blade_modes)
                if (on(mode[0]))
                    output("QD_B" + std::to_string(k) + mode[2], blade_dof(k, mode[1]) + "'",
                           "m/s");
        if (!flexible_blades() || in_.blade_tips.size() < static_cast<std::size_t>(d_.blades))
            return;
        // A point is fixed in its body's frame, so the tips' deflections are written from
        // the tip node of each blade's SID (ElastoDyn's TwistedSF and AxRedBld at its
        // TipNode): in the coned frame (the blade frame before its pitch).
        out_ << "\n# ---- ElastoDyn's blade-tip deflections in the coned frame: OoPDefl (TipDxc)\n"
                "# out of plane, IPDefl (TipDyc) in plane, TipDzc along the blade; the tip node's\n"
                "# shapes (x, y per unit DOF; axial: second order) from the blade's SID\n";
        for (int k = 1; k <= d_.blades; ++k) {
            const BladeTipShapes& tip = in_.blade_tips[static_cast<std::size_t>(k - 1)];
            const std::array<double, 2>* shapes[3] = {&tip.flap1, &tip.edge1, &tip.flap2};
            std::string dx, dy;
            for (std::size_t m = 0; m < 3; ++m) {
                if (!on(blade_modes[m][0])) continue;
                const std::string q = blade_dof(k, blade_modes[m][1]);
                dx += term((*shapes[m])[0], q);
                dy += term((*shapes[m])[1], q);
            }
            const std::string n = std::to_string(k);
            const std::string pitch = blade_pitch(k);
            if (pitch.empty()) {
                output("OoPDefl" + n, strip(dx), "m");
                output("IPDefl" + n, strip(dy), "m");
            } else {
                output("OoPDefl" + n,
                       "cos(" + pitch + ") * (" + strip(dx) + ") + sin(" + pitch + ") * (" +
                           strip(dy) + ")",
                       "m");
                output("IPDefl" + n,
                       "-sin(" + pitch + ") * (" + strip(dx) + ") + cos(" + pitch + ") * (" +
                           strip(dy) + ")",
                       "m");
            }
            std::string dz;
            for (std::size_t a = 0; a < 3; ++a)
                for (std::size_t b = a; b < 3; ++b) {
                    if (!on(blade_modes[a][0]) || !on(blade_modes[b][0])) continue;
                    const double c = (a == b ? 0.5 : 1.0) * tip.axial[a][b];
                    dz += term(c, blade_dof(k, blade_modes[a][1]) + " * " +
                                      blade_dof(k, blade_modes[b][1]));
                }
            output("TipDzc" + n, strip(dz), "m");
        }
    }
    /// " + c * q" in the model's syntax (empty when c is 0).
    static std::string term(double c, const std::string& q) {
        if (c == 0) return "";
        return (c < 0 ? " - " : " + ") + mbd_number(std::fabs(c)) + " * " + q;
    }
    /// A sum of terms without its leading " + " ("0" when empty).
    static std::string strip(const std::string& sum) {
        if (sum.empty()) return "0";
        return sum.compare(0, 3, " - ") == 0 ? "-" + sum.substr(3) : sum.substr(3);
    }
    /// ElastoDyn's load channels from the reactions of the joints (docs/language.md):
    /// ElastoDyn reports the load the part beyond a cut puts on it, the opposite of
    /// reaction_force/reaction_moment (the load on the child), in kN and kN m.
    /// Distributed loads entered as `genforce` on modes (f_fa1, f_flap1, ...) are not
    /// in them; thrust and torques are (docs/openfast.md).
    void load_outputs() {
        out_ << "\n# ---- OpenFAST load channels (ElastoDyn's names, signs and units: the load\n"
                "# beyond the cut on the cut, -reaction; genforce loads on modes not included)\n";
        // Tower base (point T(0)), tower-base axes.
        for (const char* c : {"x", "y", "z"})
            output(std::string("TwrBsM") + c + "t",
                   std::string("-reaction_moment(tower).") + c + " / 1000 in tower", "kN m");
        // Yaw bearing (point O), axes of the tower top before the yaw.
        const std::string above = "nacelle";
        if (v("YawBrMass") != 0) {
            output("YawBrMxp", "-reaction_moment(" + above + ").x / 1000 in yaw_bearing", "kN m");
            output("YawBrMyp", "-reaction_moment(" + above + ").y / 1000 in yaw_bearing", "kN m");
        } else {
            const std::string yaw = on("YawDOF")       ? "nac_yaw"
                                    : v("NacYaw") != 0 ? mbd_number(v("NacYaw")) + " deg"
                                                       : "";
            const std::string mx = "reaction_moment(" + above + ").x",
                              my = "reaction_moment(" + above + ").y";
            if (yaw.empty()) {
                output("YawBrMxp", "-" + mx + " / 1000 in nacelle", "kN m");
                output("YawBrMyp", "-" + my + " / 1000 in nacelle", "kN m");
            } else {
                // The nacelle's axes turned back by the yaw angle.
                output("YawBrMxp",
                       "-(" + mx + " * cos(" + yaw + ") - " + my + " * sin(" + yaw +
                           ")) / 1000 in nacelle",
                       "kN m");
                output("YawBrMyp",
                       "-(" + mx + " * sin(" + yaw + ") + " + my + " * cos(" + yaw +
                           ")) / 1000 in nacelle",
                       "kN m");
            }
        }
        // Blade 1 root (point S(0)): b = the blade's pitched axes, c = before the pitch.
        if (blade_bodies()) {
            const std::string m = "reaction_moment(blade1)";
            const std::string pitch = blade_pitch(1);
            if (!pitch.empty()) {
                output("RootMxc1",
                       "-(" + m + ".x * cos(" + pitch + ") + " + m + ".y * sin(" + pitch +
                           ")) / 1000 in blade1",
                       "kN m");
                output("RootMyc1",
                       "-(" + m + ".y * cos(" + pitch + ") - " + m + ".x * sin(" + pitch +
                           ")) / 1000 in blade1",
                       "kN m");
            } else {
                output("RootMxc1", "-" + m + ".x / 1000 in blade1", "kN m");
                output("RootMyc1", "-" + m + ".y / 1000 in blade1", "kN m");
            }
            output("RootMzc1", "-" + m + ".z / 1000 in blade1", "kN m");
            output("RootMxb1", "-" + m + ".x / 1000 in blade1", "kN m");
            output("RootMyb1", "-" + m + ".y / 1000 in blade1", "kN m");
        }
        // Low-speed shaft at the rotor apex (point P), shaft axes turning with the rotor.
        // Without the drivetrain DOF the generator torque acts on the rotor and the
        // rotor's body carries the generator's inertia: the shaft then carries the
        // generator torque and the generator's inertial torque.
        const std::string rotor = flexible_blades() ? "hub" : "rotor";
        const std::string mom = "reaction_moment(" + rotor + ")",
                          frc = "reaction_force(" + rotor + ")";
        std::string generator;
        if (!on("DrTrDOF"))
            generator = on("GenDOF") ? " + (GBRatio * " + generator_torque() +
                                           " + GenIner * GBRatio^2 * psi'') / 1000"
                                     : " + GBRatio * " + generator_torque() + " / 1000";
        const std::string torque = "-" + mom + ".x / 1000" + generator + " in " + rotor;
        output("LSShftMxa", torque, "kN m");
        output("LSSGagMya", "-(" + mom + ".y + ShftGagL * " + frc + ".z) / 1000 in " + rotor,
               "kN m");
        output("LSSGagMza", "-(" + mom + ".z - ShftGagL * " + frc + ".y) / 1000 in " + rotor,
               "kN m");
        output("RotThrust", "-" + frc + ".x / 1000 in " + rotor, "kN");
        output("RotTorq", torque, "kN m");
        out_ << gauge_outputs(d_, flexible_tower(), flexible_blades(), diags_);
    }

    /// The generator torque on the high-speed shaft: the input, plus ServoDyn's simple
    /// region-2 law k w^2 when the deck runs in wind (VS_Rgn2K, 0 under a controller).
    std::string generator_torque() const {
        if (!in_.operation) return "gen_torque";
        const std::string speed = on("GenDOF") ? "psi'" : "Omega0";
        return "(gen_torque + VS_Rgn2K * (GBRatio * " + speed + ")^2)";
    }

    /// The command that runs the model in the deck's wind under its controller.
    /// HydroDyn's and MAP++'s loads on the platform, in the .fst's water.
    void platform_blocks() {
        if (platform() && !d_.offshore.mooring_file.empty() && !d_.offshore.water_depth)
            diags_.warning(diag::Kind::NotSupported, {d_.fst, 0, 0},
                           "CompMooring without WtrDpth in the .fst: the mooring's seabed needs "
                           "the depth; declare `load mooring` with a depth parameter yourself");
        if (!hydro_block() && !mooring_block()) return;
        out_ << "\n# ---- the platform's loads: HydroDyn (--hydro, --sea-state), MAP++ or "
                "MoorDyn (--mooring)\n";
        std::string water;
        if (d_.offshore.water_depth) water += "; depth = WtrDpth";
        if (d_.offshore.water_density) water += "; density = WtrDens";
        water += "; gravity = Gravity";
        if (hydro_block()) out_ << "load hydrodyn hydro { platform = platform" << water << " }\n";
        if (mooring_block()) out_ << "load mooring lines { platform = platform" << water << " }\n";
    }

    void operation_header(const Operation& op) {
        if (op.blade_elements)
            out_ << "# In wind (docs/openfast.md, \"A full deck\"): AeroDyn becomes its blade\n"
                    "# elements on the flexible blades (docs/aerodynamics.md), InflowWind its\n"
                    "# wind at every node, ServoDyn's controller the DISCON library it names:\n";
        else
            out_
                << "# In wind (docs/openfast.md, \"A full deck\"): AeroDyn becomes the "
                   "quasi-steady\n"
                   "# rotor block of a Cp/Ct/Cq table, InflowWind the hub-height wind, ServoDyn's\n"
                   "# controller the DISCON library it names:\n";
        const std::string aero = op.blade_elements ? (op.aerodyn.empty() ? "AERODYN" : op.aerodyn)
                                                   : (op.table.empty() ? "TABLE" : op.table);
        std::vector<std::string> options{"--aero " + aero,
                                         "--wind " + (op.wind.empty() ? "SPEED" : op.wind)};
        if (!op.controller.empty()) {
            options.push_back("--controller " + op.controller);
            if (!op.controller_input.empty())
                options.push_back("--controller-input " + op.controller_input);
        }
        if (d_.tmax && d_.dt)
            options.push_back("--tmax " + mbd_number(*d_.tmax) + " --dt " + mbd_number(*d_.dt));
        // ElastoDyn's own integrator, where the deck runs it (Method 3).
        if (op.blade_elements && d_.method == 3) options.push_back("--method abm4");
        // The glue's loose coupling (ModCoupling 1): AeroDyn once per step, its loads
        // extrapolated within the next (docs/aerodynamics.md, "Coupling").
        if (op.blade_elements && d_.mod_coupling == 1) {
            std::string coupling = "--coupling loose";
            if (d_.interp_order && *d_.interp_order >= 0 && *d_.interp_order <= 2)
                coupling += " --interp-order " + std::to_string(*d_.interp_order);
            options.push_back(coupling);
        }
        if (v("BlPitch1") != 0)
            options.push_back("--u pitch=" + mbd_number(v("BlPitch1") * std::acos(-1.0) / 180));
        // One option a line, as a shell command continued with backslashes.
        out_ << "#   yamsc sim " << in_.output_file;
        for (const std::string& option : options) out_ << " \\\n#     " << option;
        out_ << "\n";
        std::string sources;
        if (op.blade_elements)
            sources += "--aero from AeroFile";
        else if (!op.table_from.empty())
            sources += "--aero from " + op.table_from;
        if (!op.wind_from.empty())
            sources += (sources.empty() ? "" : "; ") + std::string("--wind from ") + op.wind_from;
        if (!sources.empty()) out_ << "#   (" << sources << ")\n";
    }

    void operation_parameters(const Operation& op) {
        out_ << "\n# ---- the rotor block, the generator and the actuators (AeroDyn, ServoDyn)\n";
        param("rotor_radius", op.rotor_radius,
              "radius of the Cp/Ct/Cq table [m] (" + where("TipRad") + ")");
        param("air_density", op.air_density, "AirDens [kg/m^3] (" + op.air_density_from + ")");
        param("GenEff", op.gen_efficiency,
              "generator efficiency [%]" +
                  (op.gen_efficiency_from.empty() ? "" : " (" + op.gen_efficiency_from + ")"));
        param("VS_Rgn2K", op.region2_k,
              "region-2 law k w^2 added to gen_torque (w: generator speed [rad/s]) [N m s^2]" +
                  (op.region2_k_from.empty()
                       ? std::string(" (0: the controller's)")
                       : " (ServoDyn's VS_Rgn2K * (30/pi)^2, " + op.region2_k_from + ")"));
        param("pitch_actuator_tau", 0,
              "pitch actuator under `sim --controller`: first-order time constant, 0: ideal [s]");
        param("torque_actuator_tau", 0, "generator torque actuator: likewise [s]");
    }

    /// What the rotor block and the controller read (docs/cli.md), in OpenFAST's names.
    void operation_outputs() {
        if (!in_.operation) return;
        const std::string rotor = flexible_blades() ? "hub" : "rotor";
        const std::string gen_speed = on("GenDOF") ? "psi'" : "Omega0";
        std::string speed = on("GenDOF") ? "psi'" : "Omega0";
        if (on("DrTrDOF")) speed = "(" + speed + " + drtr')";
        out_ << "\n# ---- what the rotor block (`--aero`) reads: the rotor speed and the hub's\n"
                "# velocity along the shaft (downwind), which gives the tower its aerodynamic\n"
                "# damping; the generator and pitch channels a controller sees\n";
        output("rotor_speed", speed, "rad/s");
        output("hub_shaft_velocity", "velocity(" + rotor + ").x in " + rotor, "m/s");
        output("GenTq", generator_torque() + " / 1000", "kN m");
        output("GenPwr",
               "GenEff / 100 * GBRatio * " + gen_speed + " * " + generator_torque() + " / 1000",
               "kW");
        // Every blade turns with the collective pitch; BlPitchK is ElastoDyn's alias.
        for (const char* name : {"BldPitch", "BlPitch"})
            for (int k = 1; k <= d_.blades; ++k)
                output(name + std::to_string(k), "pitch * 180 / pi", "deg");
        // DISCON records 53 and 54: the tower-top accelerations, the modes' tip
        // accelerations (each mode's shape is 1 at the top) from the solved q''.
        std::string fa, ss;
        for (const char* m : {"fa1", "fa2"})
            if (tower_mode_on(m)) fa += (fa.empty() ? "q_" : " + q_") + std::string(m) + "''";
        for (const char* m : {"ss1", "ss2"})
            if (tower_mode_on(m)) ss += (ss.empty() ? "q_" : " + q_") + std::string(m) + "''";
        if (!fa.empty()) output("YawBrTAxp", fa, "m/s^2");
        if (!ss.empty()) output("YawBrTAyp", ss, "m/s^2");
    }

    /// The rotor block of `--aero` on the channels above (docs/language.md, Load blocks).
    void rotor_block() {
        if (!in_.operation) return;
        if (in_.operation->blade_elements) {
            // The blades carry their deck's pitch; the controller's pitch replaces it
            // in the aerodynamics (docs/aerodynamics.md).
            out_ << "\n# ---- AeroDyn's blade elements (`--aero AeroDyn.dat`) on the hub and "
                    "blades\n"
                    "load blade_elements aero {\n"
                    "    wind = V_wind; pitch = pitch\n"
                    "    hub = "
                 << (flexible_blades() ? "hub" : "rotor");
            for (int k = 1; k <= d_.blades; ++k) out_ << "; blade" << k << " = blade" << k;
            if (flexible_tower()) out_ << "\n    tower = tower";
            out_ << "\n}\n";
            return;
        }
        out_ << "\n# ---- the rotor block of `--aero TABLE` on these channels\n"
                "load rotor_table aero {\n"
                "    wind = V_wind; pitch = pitch; thrust = thrust; rotor_torque = aero_torque\n"
                "    speed = rotor_speed; hub_velocity = hub_shaft_velocity\n"
                "    radius = rotor_radius; density = air_density\n"
                "}\n";
    }

    void output(const std::string& name, const std::string& value, const std::string& unit) {
        out_ << pad("output " + name + " = " + value, 50) << "# [" << unit << "]\n";
    }

    const OpenFastModelInput& in_;
    const openfast::OpenFastDeck& d_;
    diag::Diagnostics& diags_;
    std::ostringstream out_;
};

} // namespace

std::string mbd_number(double v) {
    if (v == 0) return "0"; // never "-0"
    return text::shortest(v);
}

std::string mbd_string(const std::string& text) {
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        if (c == '\n' || c == '\r') continue;
        out += c;
    }
    return out + "\"";
}

std::string openfast_model_text(const OpenFastModelInput& in, diag::Diagnostics& diags) {
    return Writer(in, diags).text();
}

} // namespace yamsc::openfast
