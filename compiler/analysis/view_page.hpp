#pragma once
// The page `yamsc view` writes (docs/viewer.md): one HTML file holding the
// run's scene and channels as JSON with base64 arrays, and the script bundled
// at build time (viewer/). This file builds the page from plain data; reading
// a run into that data is view_command.cpp's.
#include <cstdint>
#include <string>
#include <vector>

namespace yamsc::analysis {

/// The scene's cells in one list: each cell a vertex, a polyline or a polygon.
enum class ViewCellType : std::uint8_t { vertex = 0, polyline = 1, polygon = 2 };

/// What the page draws: the topology once, the points per frame.
struct ViewScene {
    std::vector<std::string> part_names;
    std::size_t point_count = 0;
    std::vector<double> times;    // one per frame, rising
    std::vector<float> positions; // frame by frame, point by point, x y z [m]
    std::vector<ViewCellType> cell_type;
    std::vector<std::int32_t> offsets; // the end of each cell in `connectivity`
    std::vector<std::int32_t> connectivity, part;
    std::vector<std::uint8_t> kind; // the scene's cell kind (vtk::CellKind)
};

/// A channel plotted under the scene, sampled at ViewPage::channel_times.
struct ViewChannel {
    std::string name, unit;
    std::vector<float> values;
};

struct ViewPage {
    std::string title;
    ViewScene scene;
    std::vector<double> channel_times;
    std::vector<ViewChannel> channels;
};

/// True when this yamsc was built with the page's script (node and npm at build time).
bool view_page_available();

/// The JSON the page's script decodes (viewer/src/data.js), safe inside <script>.
std::string view_page_data(const ViewPage& page);

/// The page's HTML. Throws diag::UserError when the script was not built.
std::string view_page_html(const ViewPage& page);

/// RFC 4648 base64 of `size` bytes.
std::string base64(const void* data, std::size_t size);

} // namespace yamsc::analysis
