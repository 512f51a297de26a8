// formats/vtk: the scene's .vtp and .pvd written and read back, and the
// reader's located errors. VTK's own reader reads the same files in
// vtk_read_back.py.
#include "vtk/scene.hpp"

#include "diag/errors.hpp"

#include <doctest/doctest.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

using namespace yamsc;

namespace {

vtk::Topology small_topology() {
    vtk::Topology t;
    t.part_names = {"link1", "tête"}; // a non-ASCII name: its bytes as numbers
    t.points = 4;
    t.verts = {{3}, {1}, {1}, {vtk::CellKind::point_marker}};
    t.lines = {{0, 1, 1, 2, 3}, {2, 5}, {0, 1}, {vtk::CellKind::line, vtk::CellKind::line}};
    t.polys = {{0, 1, 2}, {3}, {1}, {vtk::CellKind::box}};
    return t;
}

const std::vector<double> points{0.1,
                                 0.0,
                                 -1.0,
                                 1e-300,
                                 2.5,
                                 3.0,
                                 -0.3333333333333333,
                                 1.0 / 3.0,
                                 7e22,
                                 0.0,
                                 -0.0,
                                 12345.678901234567};

std::string error_of(const std::string& text) {
    try {
        vtk::parse_vtp(text, "s.vtp");
    } catch (const diag::UserError& e) {
        return e.what();
    }
    return "";
}

void write(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

} // namespace

TEST_CASE("a .vtp read back gives the very numbers, cells and names written") {
    const vtk::Topology t = small_topology();
    const vtk::PolyData p = vtk::parse_vtp(vtk::write_vtp(t, points), "s.vtp");
    CHECK(p.points == points); // exact: the shortest text reads back as the same double
    CHECK(p.topology.part_names == t.part_names);
    CHECK(p.topology.points == 4);
    CHECK(p.topology.lines.connectivity == t.lines.connectivity);
    CHECK(p.topology.lines.offsets == t.lines.offsets);
    CHECK(p.topology.polys.kind == t.polys.kind);
    CHECK(p.topology.verts.part == t.verts.part);
}

TEST_CASE("the writer refuses what the format cannot say") {
    vtk::Topology t = small_topology();
    CHECK_THROWS_AS(vtk::write_vtp(t, {1.0, 2.0}), std::invalid_argument);
    t.lines.connectivity[0] = 9; // no point 9
    CHECK_THROWS_AS(vtk::write_vtp(t, points), std::invalid_argument);
}

TEST_CASE("the .vtp reader's errors are located") {
    const std::string good = vtk::write_vtp(small_topology(), points);
    // A number that is not one: at its line and column.
    std::string bad = good;
    const std::size_t at = bad.find("1e-300");
    bad.replace(at, 6, "1x-300");
    int line = 1;
    for (std::size_t i = 0; i < at; ++i) line += bad[i] == '\n';
    CHECK(error_of(bad).rfind("s.vtp:" + std::to_string(line) + ":11: not a number", 0) == 0);
    // A missing closing tag, a wrong root, fewer numbers than announced.
    CHECK(error_of(good.substr(0, good.size() - 12)).find("without its end") != std::string::npos);
    CHECK(error_of("<?xml version=\"1.0\"?>\n<Foo/>\n") ==
          "s.vtp:2:1: expected <VTKFile>, found <Foo>");
    std::string fewer = good;
    fewer.replace(fewer.find("NumberOfPoints=\"4\""), 18, "NumberOfPoints=\"5\"");
    CHECK(error_of(fewer).find("numbers where 15 were announced") != std::string::npos);
    // A kind outside 0..4, a part that does not exist.
    std::string kind = good;
    const std::size_t k = kind.find("Name=\"kind\"");
    kind.replace(kind.find("3", k + 30), 1, "9");
    CHECK(error_of(kind).find("has kind 9") != std::string::npos);
    // Nesting beyond the limit.
    std::string deep = "<VTKFile type=\"PolyData\">";
    for (int i = 0; i < 40; ++i) deep += "<a>";
    CHECK(error_of(deep).find("nested deeper than 16") != std::string::npos);
}

TEST_CASE("read_run: a folder's collection, its steps, one topology") {
    char tmpl[] = "/tmp/yamsc_scene_XXXXXX";
    REQUIRE(::mkdtemp(tmpl));
    const std::string dir = tmpl;
    const vtk::Topology t = small_topology();
    std::vector<vtk::Entry> entries;
    for (std::size_t row = 0; row < 3; ++row) {
        std::vector<double> p = points;
        p[0] = static_cast<double>(row);
        write(dir + "/" + vtk::vtp_name("m", row), vtk::write_vtp(t, p));
        entries.push_back({0.5 * static_cast<double>(row), vtk::vtp_name("m", row)});
    }
    write(dir + "/m.pvd", vtk::write_pvd(entries));
    const vtk::Run run = vtk::read_run(dir);
    CHECK(run.model == "m");
    CHECK(run.csv.empty());
    REQUIRE(run.steps.size() == 3);
    CHECK(run.steps[2].time == 1.0);
    CHECK(run.steps[2].points[0] == 2.0);
    CHECK(run.topology.part_names == t.part_names);

    // A step with other cells: refused, naming its file.
    vtk::Topology other = t;
    other.lines.part[0] = 1;
    write(dir + "/" + vtk::vtp_name("m", 1), vtk::write_vtp(other, points));
    try {
        vtk::read_run(dir + "/m.pvd");
        FAIL("read");
    } catch (const diag::UserError& e) {
        CHECK(std::string(e.what()).find("m_000001.vtp: its cells or parts differ") !=
              std::string::npos);
    }
    // Times that do not rise, a file outside the folder.
    write(dir + "/m.pvd", vtk::write_pvd({{1.0, "m_000000.vtp"}, {1.0, "m_000002.vtp"}}));
    CHECK_THROWS_WITH_AS(vtk::read_run(dir),
                         doctest::Contains("m.pvd:5:5: timestep 1 does not rise"), diag::UserError);
    write(dir + "/m.pvd", vtk::write_pvd({{0.0, "../x.vtp"}}));
    CHECK_THROWS_WITH_AS(vtk::read_run(dir), doctest::Contains("is not the name of a file beside"),
                         diag::UserError);
    for (std::size_t row = 0; row < 3; ++row)
        std::remove((dir + "/" + vtk::vtp_name("m", row)).c_str());
    std::remove((dir + "/m.pvd").c_str());
    ::rmdir(dir.c_str());
}
