#include "vtk/scene.hpp"
#include "vtk/xml.hpp"

#include "diag/errors.hpp"

#include <charconv>
#include <cmath>
#include <dirent.h>
#include <fstream>
#include <limits>
#include <sstream>
#include <sys/stat.h>

namespace yamsc::vtk {

namespace {

using xml::Element;

class Reader {
public:
    Reader(const std::string& text, const std::string& name, const Limits& limits)
        : text_(text), name_(name), limits_(limits) {
        if (text.size() > limits.file_bytes)
            throw diag::UserError(name + ": larger than " + std::to_string(limits.file_bytes) +
                                  " bytes");
    }

    [[noreturn]] void fail(std::size_t at, const std::string& message) const {
        throw diag::UserError(xml::where(text_, name_, at) + ": " + message);
    }

    Element root(const char* type) const {
        Element r = xml::parse(text_, name_, limits_.depth);
        if (r.name != "VTKFile") fail(r.offset, "expected <VTKFile>, found <" + r.name + ">");
        const std::string* t = r.attribute("type");
        if (!t || *t != type)
            fail(r.offset, std::string("expected a VTKFile of type \"") + type + "\"");
        return r;
    }

    const Element& only(const Element& parent, const char* name) const {
        const Element* found = nullptr;
        for (const Element& c : parent.children)
            if (c.name == name) {
                if (found) fail(c.offset, std::string("a second <") + name + ">");
                found = &c;
            }
        if (!found) fail(parent.offset, "<" + parent.name + "> without <" + name + ">");
        return *found;
    }

    const std::string& attribute(const Element& e, const char* key) const {
        const std::string* v = e.attribute(key);
        if (!v) fail(e.offset, "<" + e.name + "> without " + key + "=");
        return *v;
    }

    std::size_t count(const Element& e, const char* key, std::size_t limit) const {
        const std::string& v = attribute(e, key);
        std::size_t n = 0;
        const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), n);
        if (ec != std::errc() || end != v.data() + v.size())
            fail(e.offset, std::string(key) + "=\"" + v + "\" is not a count");
        if (n > limit)
            fail(e.offset,
                 std::string(key) + " " + v + " is above the limit " + std::to_string(limit));
        return n;
    }

    /// The numbers of an element's text, exactly `n` of them.
    template <class T> std::vector<T> numbers(const Element& e, std::size_t n) const {
        std::vector<T> out;
        out.reserve(n);
        const std::string& s = e.text;
        std::size_t i = 0;
        for (;;) {
            while (i < s.size() && (s[i] == ' ' || s[i] == '\n' || s[i] == '\t' || s[i] == '\r'))
                ++i;
            if (i == s.size()) break;
            // The element's text is the file's own between its tags (no entity
            // in numbers), so an offset into it is an offset into the file.
            const std::size_t at = e.text_offset + i;
            if (out.size() == n)
                fail(at, "more than the " + std::to_string(n) + " numbers announced");
            T v{};
            const auto [end, ec] = std::from_chars(s.data() + i, s.data() + s.size(), v);
            if (ec != std::errc() || (end < s.data() + s.size() && *end != ' ' && *end != '\n' &&
                                      *end != '\t' && *end != '\r'))
                fail(at, "not a number of type " + std::string(type_name<T>()));
            if constexpr (std::is_floating_point_v<T>)
                if (!std::isfinite(v)) fail(at, "not a finite number");
            out.push_back(v);
            i = static_cast<std::size_t>(end - s.data());
        }
        if (out.size() != n)
            fail(e.text_offset, std::to_string(out.size()) + " numbers where " + std::to_string(n) +
                                    " were announced");
        return out;
    }

    template <class T> static const char* type_name() {
        if constexpr (std::is_same_v<T, double>) return "Float64";
        if constexpr (std::is_same_v<T, std::int64_t>) return "Int64";
        if constexpr (std::is_same_v<T, std::int32_t>) return "Int32";
        return "UInt8";
    }

    /// The <DataArray> named `name` of `parent`, checked to be ASCII of `type`.
    const Element& data_array(const Element& parent, const char* name, const char* type) const {
        const Element* found = nullptr;
        for (const Element& c : parent.children) {
            if (c.name != "DataArray") fail(c.offset, "unexpected <" + c.name + ">");
            const std::string* n = c.attribute("Name");
            if (n && *n == name) found = &c;
        }
        if (!found) fail(parent.offset, "<" + parent.name + "> without the array " + name);
        if (attribute(*found, "type") != type)
            fail(found->offset, std::string("the array ") + name + " is not of type " + type);
        const std::string* format = found->attribute("format");
        if (!format || *format != "ascii")
            fail(found->offset,
                 std::string("the array ") + name +
                     " is not ASCII (this reader reads the ASCII files yamsc writes)");
        return *found;
    }

    Cells cells(const Element& piece, const char* tag, std::size_t n, std::size_t points) const {
        Cells c;
        const Element* e = nullptr;
        for (const Element& child : piece.children)
            if (child.name == tag) e = &child;
        if (!e) {
            if (n != 0)
                fail(piece.offset, "<Piece> announces cells but has no <" + std::string(tag) + ">");
            return c;
        }
        c.offsets = numbers<std::int64_t>(data_array(*e, "offsets", "Int64"), n);
        std::int64_t end = 0;
        for (std::int64_t o : c.offsets) {
            if (o <= end)
                fail(e->offset, std::string("<") + tag + "> offsets not rising from above 0");
            end = o;
        }
        if (static_cast<std::uint64_t>(end) > limits_.cells * 64)
            fail(e->offset, "too many connectivity entries");
        const Element& conn = data_array(*e, "connectivity", "Int64");
        c.connectivity = numbers<std::int64_t>(conn, static_cast<std::size_t>(end));
        for (std::int64_t p : c.connectivity)
            if (p < 0 || static_cast<std::size_t>(p) >= points)
                fail(conn.text_offset,
                     "a cell names point " + std::to_string(p) + " of " + std::to_string(points));
        return c;
    }

    PolyData polydata() const {
        const Element r = root("PolyData");
        const Element& poly = only(r, "PolyData");
        PolyData out;
        Topology& t = out.topology;
        for (const Element& c : poly.children)
            if (c.name == "FieldData") t.part_names = part_names(c);
        const Element& piece = only(poly, "Piece");
        t.points = count(piece, "NumberOfPoints", limits_.points);
        const std::size_t nv = count(piece, "NumberOfVerts", limits_.cells);
        const std::size_t nl = count(piece, "NumberOfLines", limits_.cells);
        const std::size_t np = count(piece, "NumberOfPolys", limits_.cells);
        if (const std::string* strips = piece.attribute("NumberOfStrips"); strips && *strips != "0")
            fail(piece.offset, "triangle strips (not in this subset)");
        const Element& pts = only(piece, "Points");
        out.points = numbers<double>(data_array(pts, "Points", "Float64"), 3 * t.points);
        t.verts = cells(piece, "Verts", nv, t.points);
        t.lines = cells(piece, "Lines", nl, t.points);
        t.polys = cells(piece, "Polys", np, t.points);
        const Element& cd = only(piece, "CellData");
        const std::size_t n = nv + nl + np;
        const std::vector<std::int32_t> part =
            numbers<std::int32_t>(data_array(cd, "part", "Int32"), n);
        const Element& kind_array = data_array(cd, "kind", "Int32");
        const std::vector<std::int32_t> kind = numbers<std::int32_t>(kind_array, n);
        std::size_t k = 0;
        for (Cells* c : {&t.verts, &t.lines, &t.polys})
            for (std::size_t i = 0; i < c->size(); ++i, ++k) {
                if (part[k] < 0 || static_cast<std::size_t>(part[k]) >= t.part_names.size())
                    fail(cd.offset, "cell " + std::to_string(k) + " names part " +
                                        std::to_string(part[k]) + " of " +
                                        std::to_string(t.part_names.size()));
                if (kind[k] < 0 || kind[k] > static_cast<std::int32_t>(CellKind::box))
                    fail(kind_array.text_offset, "cell " + std::to_string(k) + " has kind " +
                                                     std::to_string(kind[k]) + " (0 to 4)");
                c->part.push_back(part[k]);
                c->kind.push_back(static_cast<CellKind>(kind[k]));
            }
        return out;
    }

    std::vector<std::string> part_names(const Element& field) const {
        for (const Element& a : field.children) {
            const std::string* n = a.attribute("Name");
            if (a.name != "Array" || !n || *n != "part_names") continue;
            if (attribute(a, "type") != "String")
                fail(a.offset, "part_names is not a String array");
            const std::size_t tuples = count(a, "NumberOfTuples", limits_.parts);
            std::vector<std::string> names(1);
            std::size_t bytes = 0;
            for (const char* p = a.text.data(); p < a.text.data() + a.text.size();) {
                while (p < a.text.data() + a.text.size() &&
                       (*p == ' ' || *p == '\n' || *p == '\t' || *p == '\r'))
                    ++p;
                if (p == a.text.data() + a.text.size()) break;
                int c = 0;
                const auto [end, ec] = std::from_chars(p, a.text.data() + a.text.size(), c);
                const std::size_t at = a.text_offset + static_cast<std::size_t>(p - a.text.data());
                if (ec != std::errc() || c < 0 || c > 255) fail(at, "not a byte (0 to 255)");
                if (++bytes > limits_.file_bytes) fail(at, "too many bytes");
                if (c == 0) {
                    if (names.size() > tuples) fail(at, "more strings than NumberOfTuples");
                    names.emplace_back();
                } else {
                    names.back() += static_cast<char>(c);
                }
                p = end;
            }
            if (!names.back().empty()) fail(a.offset, "the last string is not ended by 0");
            names.pop_back();
            if (names.size() != tuples)
                fail(a.offset, std::to_string(names.size()) + " strings where NumberOfTuples is " +
                                   std::to_string(tuples));
            return names;
        }
        fail(field.offset, "<FieldData> without the String array part_names");
    }

    std::vector<Entry> collection() const {
        const Element r = root("Collection");
        const Element& c = only(r, "Collection");
        std::vector<Entry> entries;
        for (const Element& d : c.children) {
            if (d.name != "DataSet") fail(d.offset, "unexpected <" + d.name + "> in <Collection>");
            if (entries.size() == limits_.steps)
                fail(d.offset, "more than " + std::to_string(limits_.steps) + " data sets");
            Entry e;
            const std::string& t = attribute(d, "timestep");
            const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), e.time);
            if (ec != std::errc() || end != t.data() + t.size() || !std::isfinite(e.time))
                fail(d.offset, "timestep=\"" + t + "\" is not a number");
            if (!entries.empty() && !(e.time > entries.back().time))
                fail(d.offset, "timestep " + t + " does not rise");
            e.file = attribute(d, "file");
            if (e.file.empty() || e.file.find('/') != std::string::npos || e.file == "." ||
                e.file == "..")
                fail(d.offset,
                     "file=\"" + e.file + "\" is not the name of a file beside the collection");
            entries.push_back(std::move(e));
        }
        return entries;
    }

private:
    const std::string& text_;
    const std::string& name_;
    const Limits& limits_;
};

std::string read_text(const std::string& path, const Limits& limits) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw diag::UserError("cannot open '" + path + "'");
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (size < 0 || static_cast<std::uint64_t>(size) > limits.file_bytes)
        throw diag::UserError(path + ": larger than " + std::to_string(limits.file_bytes) +
                              " bytes");
    in.seekg(0);
    std::string text(static_cast<std::size_t>(size), '\0');
    in.read(text.data(), size);
    if (!in) throw diag::UserError("cannot read '" + path + "'");
    return text;
}

bool is_folder(const std::string& path) {
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

bool is_file(const std::string& path) {
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

bool same_topology(const Topology& a, const Topology& b) {
    auto same = [](const Cells& x, const Cells& y) {
        return x.connectivity == y.connectivity && x.offsets == y.offsets && x.part == y.part &&
               x.kind == y.kind;
    };
    return a.part_names == b.part_names && a.points == b.points && same(a.verts, b.verts) &&
           same(a.lines, b.lines) && same(a.polys, b.polys);
}

/// The one .pvd of a folder.
std::string collection_in(const std::string& folder) {
    DIR* d = ::opendir(folder.c_str());
    if (!d) throw diag::UserError("cannot open the folder '" + folder + "'");
    std::vector<std::string> found;
    while (const dirent* e = ::readdir(d)) {
        const std::string n = e->d_name;
        if (n.size() > 4 && n.compare(n.size() - 4, 4, ".pvd") == 0) found.push_back(n);
    }
    ::closedir(d);
    if (found.size() != 1)
        throw diag::UserError("'" + folder + "' holds " + std::to_string(found.size()) +
                              " .pvd files (a run's folder holds one)");
    return folder + (folder.back() == '/' ? "" : "/") + found.front();
}

} // namespace

PolyData parse_vtp(const std::string& text, const std::string& name, const Limits& limits) {
    return Reader(text, name, limits).polydata();
}

std::vector<Entry> parse_pvd(const std::string& text, const std::string& name,
                             const Limits& limits) {
    return Reader(text, name, limits).collection();
}

Run read_run(const std::string& path, const Limits& limits) {
    Run run;
    run.pvd = is_folder(path) ? collection_in(path) : path;
    const std::size_t slash = run.pvd.find_last_of('/');
    const std::string folder = slash == std::string::npos ? "" : run.pvd.substr(0, slash + 1);
    std::string base = run.pvd.substr(folder.size());
    if (base.size() <= 4 || base.compare(base.size() - 4, 4, ".pvd") != 0)
        throw diag::UserError("'" + run.pvd + "' is not a .pvd file or a folder holding one");
    run.model = base.substr(0, base.size() - 4);
    if (is_file(folder + csv_name(run.model))) run.csv = folder + csv_name(run.model);
    const std::vector<Entry> entries = parse_pvd(read_text(run.pvd, limits), run.pvd, limits);
    if (entries.empty()) throw diag::UserError(run.pvd + ": the collection lists no data set");
    for (const Entry& e : entries) {
        const std::string file = folder + e.file;
        PolyData p = parse_vtp(read_text(file, limits), file, limits);
        if (run.steps.empty())
            run.topology = std::move(p.topology);
        else if (!same_topology(p.topology, run.topology))
            throw diag::UserError(file + ": its cells or parts differ from those of " + folder +
                                  entries.front().file + " (a run's topology is fixed)");
        run.steps.push_back(Step{e.time, std::move(p.points)});
    }
    return run;
}

} // namespace yamsc::vtk
