#pragma once
// MoorDyn's input file (the mooring file of an OpenFAST deck with CompMooring = 3),
// in MoorDyn v2's layout as OpenFAST v4/v5 reads it (MD_Init in MoorDyn.f90, on
// the lines of ProcessComFile: lines starting with '!', '#' or '%' and blank
// lines dropped). A line holding "---" starts a section, recognised by the words
// MoorDyn looks for, in its order:
//   LINE TYPES (LINE DICTIONARY)  Name Diam MassDen EA BA/-zeta EI Cd Ca CdAx CaAx [Cl [dF cF]]
//   ROD TYPES, BODIES, RODS       kept as rows (their objects are not modelled)
//   POINTS (CONNECTION/NODE/POINT PROPERTIES, POINT LIST)
//                                 ID Attachment X Y Z M V CdA Ca
//   LINES (LINE PROPERTIES, LINE LIST)
//                                 ID LineType AttachA AttachB UnstrLen NumSegs Outputs
//   EXTERNAL LOADS, CONTROL, FAILURE   warned at their header and skipped
//   OPTIONS                       value name [comment], one per line
//   OUTPUT(S)                     channel names until END or the next "---"
// The tables skip two lines after their header (column names and units). Values
// as in the file (SI units). Bad input: located errors and nullopt.
//
// MoorDyn v1's layout (OpenFAST v2/v3) is read too, told apart by the count line
// after each table's header (`3 NLines`): LINE TYPES `Name Diam MassDen EA BA/-zeta
// Can Cat Cdn Cdt`, CONNECTION PROPERTIES `Node Type X Y Z M V FX FY FZ CdA CA`,
// LINE PROPERTIES `Line LineType UnstrLen NumSegs NodeAnch NodeFair Flags/Outputs`,
// each table as long as its count.
#include "diag/diagnostics.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace yamsc::moordyn {

/// The largest number of rows a section may hold (and of output channels).
inline constexpr int max_rows = 10000;

struct LineType {
    std::string name;
    double diameter = 0;          // Diam [m]
    double mass_density = 0;      // MassDen [kg/m], in air
    double axial_stiffness = 0;   // EA [N]: the static value (the first of EA|EA_D|...)
    int stiffness_values = 1;     // bar-separated values of EA: 2 or 3 is visco-elastic
    double internal_damping = 0;  // BA [N s], or minus the damping ratio (-zeta)
    double bending_stiffness = 0; // EI [N m^2]
    double drag_normal = 0;       // Cd
    double added_mass_normal = 0; // Ca
    double drag_axial = 0;        // CdAx
    double added_mass_axial = 0;  // CaAx
    double lift = 0;              // Cl (VIV), 0 when absent
    diag::Location at;
};

/// A row of ROD TYPES, BODIES or RODS: not modelled, kept so that its user
/// can refuse it at its line.
struct OtherRow {
    std::string name; // the row's first word
    diag::Location at;
};

enum class Attachment {
    fixed,   // Fixed, Fix, Anchor: on the ground
    coupled, // Vessel, Ves, Coupled, Cpld: moved by the body it is coupled to
    free,    // Free, Point, P, Connect: a node of a line network
    body,    // Body<n>
    turbine, // Turbine<n>, T<n> (FAST.Farm)
};

struct Point {
    int id = 0;
    Attachment attachment = Attachment::fixed;
    int attached_to = 0;         // n of Body<n> or Turbine<n>
    double x = 0, y = 0, z = 0;  // [m]: ground for fixed, the body's axes for coupled
    bool on_seabed = false;      // Z written as seabed/ground/floor: z is minus the depth
    double mass = 0, volume = 0; // M [kg], V [m^3]
    double drag_area = 0;        // CdA [m^2]
    double added_mass = 0;       // Ca
    double force[3] = {0, 0, 0}; // FX FY FZ [N] of v1's connections
    diag::Location at, attachment_at, z_at;
};

/// A line's end: a point (`3`, `P3`, `Point3`) or a rod's end (`R2A`, `Rod2B`).
struct End {
    bool rod = false;
    int number = 0;
    char rod_end = 0; // 'A' or 'B' for a rod
    diag::Location at;
};

struct LineRow {
    int id = 0;
    std::string type; // a LineType's name, matched exactly as MoorDyn does
    End end_a, end_b;
    double unstretched_length = 0; // UnstrLen [m]
    int segments = 0;              // NumSegs
    std::string outputs;           // the output flags as written ("-": none)
    diag::Location at, type_at;
};

struct Option {
    std::string name; // upper case
    std::string value;
    diag::Location at;
};

struct MoorDynInput {
    std::shared_ptr<const diag::SourceFile> file;
    int layout = 2; // MoorDyn's version of the file's tables: 2, or 1 (count lines)
    std::vector<LineType> line_types;
    std::vector<OtherRow> rod_types, bodies, rods;
    std::vector<Point> points;
    std::vector<LineRow> lines;
    std::vector<Option> options;
    std::vector<std::string> outputs;
    diag::Location options_at; // the OPTIONS header (file:0 when there is none)

    // Options MoorDyn's lines use, when the file sets them (else the glue code's).
    std::optional<double> gravity, water_density; // g, rhoW
    std::optional<double> water_depth;            // WtrDpth (depth, WaterDepth)
    diag::Location water_depth_at;
    std::optional<double> time_step; // dtM [s]
    double seabed_stiffness = 3.0e6; // kBot [Pa/m], MoorDyn's default
    double seabed_damping = 3.0e5;   // cBot [Pa s/m], MoorDyn's default
};

/// Reads a MoorDyn input file. Errors: a table row with too few values (points:
/// exactly 9) or a value that is not a number, an unknown attachment, a line type
/// or point named twice, IDs not 1, 2, ... in order, a line naming an unknown line
/// type, point or rod, an option's value that is not a number (a bathymetry file
/// as WtrDpth is refused). Unknown options and the sections not read are warnings.
std::optional<MoorDynInput> read_moordyn_input(const std::shared_ptr<const diag::SourceFile>& file,
                                               diag::Diagnostics& diags);

} // namespace yamsc::moordyn
