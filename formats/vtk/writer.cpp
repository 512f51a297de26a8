#include "vtk/scene.hpp"

#include "text/number.hpp"
#include "text/xml.hpp"

#include <cstdio>
#include <stdexcept>

namespace yamsc::vtk {

namespace {

void numbers(std::string& out, const std::vector<std::int64_t>& v) {
    for (std::size_t i = 0; i < v.size(); ++i) {
        out += i % 16 ? " " : i ? "\n          " : "          ";
        out += std::to_string(v[i]);
    }
    out += '\n';
}

void array(std::string& out, const char* type, const char* name,
           const std::vector<std::int64_t>& v) {
    out += "        <DataArray type=\"";
    out += type;
    out += "\" Name=\"";
    out += name;
    out += "\" format=\"ascii\">\n";
    numbers(out, v);
    out += "        </DataArray>\n";
}

void check_cells(const Cells& c, const Topology& t) {
    if (c.part.size() != c.size() || c.kind.size() != c.size())
        throw std::invalid_argument("vtk: a cell without its part or kind");
    std::int64_t end = 0;
    for (std::int64_t o : c.offsets) {
        if (o <= end) throw std::invalid_argument("vtk: a cell without points");
        end = o;
    }
    if (static_cast<std::size_t>(end) != c.connectivity.size())
        throw std::invalid_argument("vtk: the last offset is not the connectivity's size");
    for (std::int64_t p : c.connectivity)
        if (p < 0 || static_cast<std::size_t>(p) >= t.points)
            throw std::invalid_argument("vtk: a cell names a point that does not exist");
    for (std::int32_t p : c.part)
        if (p < 0 || static_cast<std::size_t>(p) >= t.part_names.size())
            throw std::invalid_argument("vtk: a cell names a part that does not exist");
}

void cells(std::string& out, const char* tag, const Cells& c) {
    out += "      <";
    out += tag;
    out += ">\n";
    array(out, "Int64", "connectivity", c.connectivity);
    array(out, "Int64", "offsets", c.offsets);
    out += "      </";
    out += tag;
    out += ">\n";
}

std::string numbered(std::size_t row) {
    char digits[32];
    std::snprintf(digits, sizeof digits, "%06zu", row);
    return digits;
}

} // namespace

std::string pvd_name(const std::string& model) {
    return model + ".pvd";
}
std::string vtp_name(const std::string& model, std::size_t row) {
    return model + "_" + numbered(row) + ".vtp";
}
std::string csv_name(const std::string& model) {
    return model + ".csv";
}

std::string write_vtp(const Topology& t, const std::vector<double>& points) {
    if (points.size() != 3 * t.points)
        throw std::invalid_argument("vtk: " + std::to_string(points.size()) + " coordinates for " +
                                    std::to_string(t.points) + " points");
    for (const Cells* c : {&t.verts, &t.lines, &t.polys}) check_cells(*c, t);
    std::string out;
    out.reserve(64 * points.size() + 1024);
    out += "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
           "header_type=\"UInt64\">\n"
           "  <PolyData>\n"
           "    <FieldData>\n";
    out += "      <Array type=\"String\" Name=\"part_names\" NumberOfTuples=\"" +
           std::to_string(t.part_names.size()) + "\" format=\"ascii\">\n";
    for (const std::string& name : t.part_names) {
        out += "        ";
        for (unsigned char ch : name) out += std::to_string(static_cast<int>(ch)) + " ";
        out += "0\n";
    }
    out += "      </Array>\n"
           "    </FieldData>\n";
    out += "    <Piece NumberOfPoints=\"" + std::to_string(t.points) + "\" NumberOfVerts=\"" +
           std::to_string(t.verts.size()) + "\" NumberOfLines=\"" + std::to_string(t.lines.size()) +
           "\" NumberOfStrips=\"0\" NumberOfPolys=\"" + std::to_string(t.polys.size()) + "\">\n";
    out += "      <Points>\n"
           "        <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" "
           "format=\"ascii\">\n";
    for (std::size_t i = 0; i < points.size(); i += 3) {
        out += "          ";
        out += text::shortest(points[i]) + " " + text::shortest(points[i + 1]) + " " +
               text::shortest(points[i + 2]) + "\n";
    }
    out += "        </DataArray>\n"
           "      </Points>\n"
           "      <CellData Scalars=\"part\">\n";
    std::vector<std::int64_t> part, kind;
    for (const Cells* c : {&t.verts, &t.lines, &t.polys}) {
        for (std::int32_t p : c->part) part.push_back(p);
        for (CellKind k : c->kind) kind.push_back(static_cast<std::int64_t>(k));
    }
    array(out, "Int32", "part", part);
    array(out, "Int32", "kind", kind);
    out += "      </CellData>\n";
    cells(out, "Verts", t.verts);
    cells(out, "Lines", t.lines);
    cells(out, "Polys", t.polys);
    out += "    </Piece>\n"
           "  </PolyData>\n"
           "</VTKFile>\n";
    return out;
}

std::string write_pvd(const std::vector<Entry>& entries) {
    std::string out = "<?xml version=\"1.0\"?>\n"
                      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                      "  <Collection>\n";
    for (const Entry& e : entries)
        out += "    <DataSet timestep=\"" + text::shortest(e.time) +
               "\" group=\"\" part=\"0\" file=\"" + text::xml_escaped(e.file) + "\"/>\n";
    out += "  </Collection>\n"
           "</VTKFile>\n";
    return out;
}

} // namespace yamsc::vtk
