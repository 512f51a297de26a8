#pragma once
// MAP++'s input file (the mooring file of an OpenFAST deck's MooringFile with
// CompMooring = 1): four sections, each a line starting with '-', a row of
// column names and a row of units, then its rows until the next '-' line, as
// MAP++'s map_read_input_file_contents reads them:
//   LINE DICTIONARY  LineType Diam MassDenInAir EA CB CIntDamp Ca Cdn Cdt
//   NODE PROPERTIES  Node Type X Y Z M B FX FY FZ   (Type Fix|Vessel|Connect; Z of a
//                    Fix node may be `depth`; `#` before a value marks a guess)
//   LINE PROPERTIES  Line LineType UnstrLen NodeAnch NodeFair Flags...
//   SOLVER OPTIONS   one option per line; lines starting with '!' are comments
// Values as in the file (SI units). Bad input: located errors and nullopt.
#include "diag/diagnostics.hpp"

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace yamsc::map {

/// The largest number of rows a section may hold.
inline constexpr int max_rows = 10000;
/// The most copies REPEAT may make of the lines.
inline constexpr std::size_t max_repeat_angles = 360;

struct LineType {
    std::string label;
    double diameter = 0;        // Diam [m]
    double mass_density = 0;    // MassDenInAir [kg/m]
    double axial_stiffness = 0; // EA [N]
    double seabed_friction = 0; // CB [-]
    diag::Location at;
};

enum class NodeKind { fix, vessel, connect };

/// A coordinate, a force or a mass of a node: a number, a guess (`#value`,
/// what MAP++ iterates on), or for a Fix node's Z the water depth (`depth`).
struct NodeValue {
    double value = 0;
    bool guess = false;
    bool depth = false;
};

struct Node {
    int number = 0;
    NodeKind kind = NodeKind::fix;
    NodeValue x, y, z;                   // [m]: inertial for Fix, in the body's axes for Vessel
    NodeValue mass, buoyancy;            // M [kg], B [m^3]
    NodeValue force_x, force_y, force_z; // [N]
    diag::Location at;
};

struct LineRow {
    int number = 0;
    std::string type;               // a LineType's label
    double unstretched_length = 0;  // UnstrLen [m]
    int anchor_node = 0;            // NodeAnch
    int fairlead_node = 0;          // NodeFair
    std::vector<std::string> flags; // output and model flags as written
    diag::Location at, type_at, anchor_at, fairlead_at;
};

struct SolverOption {
    std::string name; // upper case
    std::vector<std::string> values;
    diag::Location at;
};

struct MapInput {
    std::shared_ptr<const diag::SourceFile> file;
    std::vector<LineType> line_types;
    std::vector<Node> nodes;
    std::vector<LineRow> lines;
    std::vector<SolverOption> options;
    /// The REPEAT option's angles [deg], in order.
    std::vector<double> repeat_angles;
    diag::Location repeat_at;
};

/// Reads a MAP++ input file. Errors: a missing section, a row with too few
/// values or a value that is not a number, an unknown node type, `depth` off a
/// Fix node's Z, a line naming an unknown line type or node, node and line
/// numbers not 1, 2, ... in order. Unknown solver options are warnings.
std::optional<MapInput> read_map_input(const std::shared_ptr<const diag::SourceFile>& file,
                                       diag::Diagnostics& diags);

} // namespace yamsc::map
