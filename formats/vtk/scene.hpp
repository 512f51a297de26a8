#pragma once
// A run's scene as ParaView reads it: VTK XML PolyData (.vtp), one file per output
// row, and a VTK Collection (.pvd) that lists them with their times
// (docs/visualization.md). The subset written and read here: one Piece; Points
// Float64 x3 (ground axes, metres); Verts, Lines and Polys with Int64
// connectivity and offsets; CellData Int32 `part` and `kind`; FieldData String
// `part_names`, encoded as VTK's own writer encodes a vtkStringArray in ASCII
// (each string's bytes as decimal numbers, each string ended by 0). All arrays
// are ASCII, numbers in their shortest text that reads back as the same double,
// so a file read back gives the very numbers written.
//
// The topology (cells, their parts and kinds, the number of points) is the same
// in every step of a run; only the points move.
#include <cstdint>
#include <string>
#include <vector>

namespace yamsc::vtk {

/// What a cell draws (CellData `kind`).
enum class CellKind : std::int32_t {
    frame_axis = 0,   // one of the three axis segments of a rigid body's frame
    line = 1,         // a rigid body's skeleton or a flexible body's deflected line
    surface = 2,      // a blade's or the tower's surface
    point_marker = 3, // a declared point (a vertex)
    box = 4,          // a face of a rigid body's box of inertia
};

/// One group of cells (VTK's cell array): connectivity and offsets (the end of
/// each cell in `connectivity`, as VTK's XML files store them), and per cell its
/// part (index into Topology::part_names) and kind.
struct Cells {
    std::vector<std::int64_t> connectivity, offsets;
    std::vector<std::int32_t> part;
    std::vector<CellKind> kind;
    std::size_t size() const { return offsets.size(); }
};

/// What stays fixed through a run.
struct Topology {
    std::vector<std::string> part_names; // one per body (its name), or a body's part
    std::size_t points = 0;
    Cells verts, lines, polys; // VTK's cell order: verts, lines, polys
};

/// A step: its time and the points' coordinates, x y z per point (3 * points).
struct Step {
    double time = 0.0;
    std::vector<double> points;
};

/// A run read back (read_run).
struct Run {
    std::string pvd;   // the collection's path
    std::string csv;   // the run's channels beside it (<model>.csv; empty if absent)
    std::string model; // the collection's name without .pvd
    Topology topology;
    std::vector<Step> steps; // in the collection's order, times rising
};

/// Limits of the reader (beyond them: a located error).
struct Limits {
    std::size_t file_bytes = std::size_t{1} << 30; // one .vtp or .pvd
    std::size_t points = 10'000'000;
    std::size_t cells = 10'000'000;
    std::size_t parts = 100'000;
    std::size_t steps = 1'000'000;
    std::size_t depth = 16; // XML nesting
};

/// The file names of a run of model `model` in its folder: <model>.pvd,
/// <model>_<NNNNNN>.vtp (row from 0, six digits or more), <model>.csv.
std::string pvd_name(const std::string& model);
std::string vtp_name(const std::string& model, std::size_t row);
std::string csv_name(const std::string& model);

/// The text of one step's .vtp. Throws std::invalid_argument when `points`
/// holds not 3 * topology.points numbers or a cell names a point or part that
/// does not exist.
std::string write_vtp(const Topology& topology, const std::vector<double>& points);

/// The text of the .pvd: one DataSet per (time, file name relative to the .pvd).
struct Entry {
    double time = 0.0;
    std::string file;
};
std::string write_pvd(const std::vector<Entry>& entries);

/// Parses a .vtp's text; `name` is the file named in errors. Throws
/// diag::UserError("name:line:col: message") on anything outside the subset.
struct PolyData {
    Topology topology;
    std::vector<double> points;
};
PolyData parse_vtp(const std::string& text, const std::string& name, const Limits& limits = {});

/// Parses a .pvd's text (errors as parse_vtp's).
std::vector<Entry> parse_pvd(const std::string& text, const std::string& name,
                             const Limits& limits = {});

/// Reads a run: `path` is a .pvd or the folder that holds exactly one. Every step's
/// .vtp must have the first one's topology; times must rise. Errors as parse_vtp's.
Run read_run(const std::string& path, const Limits& limits = {});

} // namespace yamsc::vtk
