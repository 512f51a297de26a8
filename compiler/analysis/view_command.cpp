// `yamsc view RUN`: the run `sim --vtk` wrote (its .pvd, .vtp and CSV) as one
// HTML page (view_page.hpp, docs/viewer.md).
#include "analysis/commands.hpp"
#include "analysis/view_page.hpp"
#include "diag/diagnostics.hpp"
#include "diag/errors.hpp"
#include "driver/outputs.hpp"
#include "table/table.hpp"
#include "vtk/scene.hpp"
#include "yamsc/atomic_file.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <ostream>
#include <vector>

namespace yamsc::analysis {

namespace {

// Shown when --channels is not given, in this order, where the run has them and
// they move: what a turbine's run is looked at for first, each by its OpenFAST
// name or yamsc's (one of each group). Otherwise the first few that move.
const std::vector<std::vector<std::string>> preferred_channels = {
    {"RotSpeed", "rotor_speed"}, {"GenPwr"},   {"BldPitch1"},
    {"TTDspFA", "tt_fa"},        {"OoPDefl1"}, {"aero_v_rel"}};
constexpr std::size_t default_channel_count = 4;

// A column as read_table names it, `NAME_[unit]`, or as sim writes it, `NAME`.
std::pair<std::string, std::string> name_and_unit(const std::string& column) {
    const auto at = column.rfind("_[");
    if (at != std::string::npos && column.back() == ']')
        return {column.substr(0, at), column.substr(at + 2, column.size() - at - 3)};
    return {column, ""};
}

bool varies(const std::vector<double>& v) {
    return !v.empty() &&
           *std::max_element(v.begin(), v.end()) > *std::min_element(v.begin(), v.end());
}

std::vector<std::size_t> chosen_columns(const driver::ViewOptions& o, const table::Table& t,
                                        const std::string& csv) {
    std::vector<std::string> names;
    for (const std::string& c : t.columns) names.push_back(name_and_unit(c).first);
    const auto find = [&](const std::string& name) {
        for (std::size_t j = 1; j < names.size(); ++j)
            if (names[j] == name || t.columns[j] == name) return j;
        return std::size_t{0};
    };
    std::vector<std::size_t> columns;
    if (!o.channels.empty()) {
        for (const std::string& name : o.channels) {
            const std::size_t j = find(name);
            if (j == 0)
                throw diag::UserError(csv + ": no channel '" + name + "'" +
                                      diag::did_you_mean(name, names));
            columns.push_back(j);
        }
        return columns;
    }
    for (const std::vector<std::string>& group : preferred_channels)
        for (const std::string& name : group)
            if (const std::size_t j = find(name);
                j && varies(t.data[j]) && columns.size() < default_channel_count) {
                columns.push_back(j);
                break;
            }
    if (!columns.empty()) return columns;
    for (std::size_t j = 1; j < t.columns.size() && columns.size() < 3; ++j)
        if (varies(t.data[j])) columns.push_back(j);
    return columns;
}

// The steps kept: at most `rate` per second of the run, the first and the last always.
std::vector<std::size_t> kept_steps(const std::vector<vtk::Step>& steps, double rate) {
    std::vector<std::size_t> kept;
    const double spacing = 1.0 / rate;
    // A tolerance of a thousandth of the spacing keeps steps 1/rate apart exactly.
    for (std::size_t i = 0; i < steps.size(); ++i)
        if (kept.empty() || steps[i].time - steps[kept.back()].time >= spacing * (1 - 1e-3))
            kept.push_back(i);
    if (!steps.empty() && kept.back() + 1 != steps.size()) kept.push_back(steps.size() - 1);
    return kept;
}

std::int32_t index32(std::size_t v, const std::string& what) {
    if (v > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
        throw diag::UserError(what + ": too many for the page (more than 2^31)");
    return static_cast<std::int32_t>(v);
}

ViewScene scene_of(const vtk::Run& run, const std::vector<std::size_t>& steps) {
    const vtk::Topology& topo = run.topology;
    ViewScene s;
    s.part_names = topo.part_names;
    s.point_count = topo.points;
    const std::pair<const vtk::Cells*, ViewCellType> groups[] = {
        {&topo.verts, ViewCellType::vertex},
        {&topo.lines, ViewCellType::polyline},
        {&topo.polys, ViewCellType::polygon}};
    for (const auto& [cells, type] : groups) {
        const std::size_t base = s.connectivity.size();
        for (const std::int64_t id : cells->connectivity)
            s.connectivity.push_back(index32(static_cast<std::size_t>(id), run.pvd + ": points"));
        for (std::size_t c = 0; c < cells->size(); ++c) {
            s.cell_type.push_back(type);
            s.offsets.push_back(
                index32(base + static_cast<std::size_t>(cells->offsets[c]), run.pvd + ": cells"));
            s.part.push_back(cells->part[c]);
            s.kind.push_back(static_cast<std::uint8_t>(cells->kind[c]));
        }
    }
    s.positions.reserve(steps.size() * topo.points * 3);
    for (const std::size_t i : steps) {
        s.times.push_back(run.steps[i].time);
        for (const double x : run.steps[i].points) s.positions.push_back(static_cast<float>(x));
    }
    return s;
}

std::string default_output(const vtk::Run& run) {
    const auto slash = run.pvd.find_last_of('/');
    return (slash == std::string::npos ? "" : run.pvd.substr(0, slash + 1)) + run.model + ".html";
}

bool has_html_extension(const std::string& path) {
    const auto dot = path.find_last_of('.');
    if (dot == std::string::npos || path.find('/', dot) != std::string::npos) return false;
    std::string ext = path.substr(dot + 1);
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == "html" || ext == "htm";
}

std::string megabytes(std::size_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f MB", static_cast<double>(bytes) / 1e6);
    return text;
}

} // namespace

int view(const driver::ViewOptions& o, std::ostream& out, std::ostream&) {
    // A page never replaces a .pvd, .vtp or .csv of a run: only .html is written.
    if (!o.output.empty() && !has_html_extension(o.output) && o.output.rfind("/dev/", 0) != 0)
        throw diag::UsageError("-o " + o.output + ": the page's name must end in .html");
    if (!view_page_available()) view_page_html({}); // says why, before reading the run
    const vtk::Run run = vtk::read_run(o.run);
    const std::string output = o.output.empty() ? default_output(run) : o.output;
    driver::check_outputs({{"the run's .pvd", run.pvd}, {"the run's CSV", run.csv}},
                          {{"-o", output}});

    ViewPage page;
    page.title = o.title.empty() ? run.model : o.title;
    const std::vector<std::size_t> steps = kept_steps(run.steps, o.frame_rate);
    page.scene = scene_of(run, steps);
    if (!o.no_channels && (!o.channels.empty() || !run.csv.empty())) {
        if (run.csv.empty())
            throw diag::UserError(run.pvd + ": --channels needs the run's CSV beside it (" +
                                  vtk::csv_name(run.model) + ")");
        const table::Table t = table::read_table(run.csv);
        page.channel_times = t.data[0];
        for (const std::size_t j : chosen_columns(o, t, run.csv)) {
            auto [name, unit] = name_and_unit(t.columns[j]);
            page.channels.push_back({name, unit, {t.data[j].begin(), t.data[j].end()}});
        }
    }
    const std::string html = view_page_html(page);
    runtime::write_file_atomically(output, html);
    const std::size_t scene_bytes = page.scene.positions.size() * 4 * 4 / 3;
    out << "wrote " << output << ": " << megabytes(html.size()) << " (" << steps.size() << " of "
        << run.steps.size() << " steps, " << page.scene.point_count << " points, the motion "
        << megabytes(scene_bytes) << "; " << page.channels.size() << " channels";
    for (std::size_t i = 0; i < page.channels.size(); ++i)
        out << (i ? ", " : ": ") << page.channels[i].name;
    out << ")\n";
    return 0;
}

} // namespace yamsc::analysis
