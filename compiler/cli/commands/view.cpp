// `yamsc view`: a run of `sim --vtk` as one self-contained HTML page.
#include "analysis/commands.hpp"
#include "cli/commands/commands.hpp"

namespace yamsc::cli {

namespace {

driver::ViewOptions parse_view(const Args& a) {
    driver::ViewOptions o;
    if (a.positionals().size() != 1)
        throw UsageError("view takes one RUN: the folder `sim --vtk` wrote, or its .pvd");
    o.run = a.positionals().front();
    o.output = a.get("-o");
    if (a.has("--channels")) {
        const std::string list = a.get("--channels");
        if (list == "none")
            o.no_channels = true;
        else
            o.channels = comma_list(list);
    }
    o.title = a.get("--title");
    if (a.has("--fps")) {
        o.frame_rate = a.number("--fps", 0);
        if (!(o.frame_rate > 0 && o.frame_rate <= 1e6))
            throw UsageError("--fps must be a positive number of frames per second of the run");
    }
    return o;
}

} // namespace

Command view_command() {
    return make_command(
        "view", "a run of `sim --vtk` as one HTML page: the 3-D motion and channels (three.js)",
        "yamsc view RUN [-o page.html] [--channels a,b,..|none] [--title TEXT] [--fps N]",
        R"(  RUN                 the folder `yamsc sim --vtk DIR` wrote, or its .pvd; the run's CSV
                      beside it (<model>.csv) gives the channels
  -o page.html        the page (default: <model>.html beside the .pvd); never an input
  --channels a,b      the channels plotted under the scene, in sync with it (default: a
                      few of RotSpeed, GenPwr, BldPitch1, TTDspFA, OoPDefl1 that move,
                      else the first three that move); none: the scene alone
  --title TEXT        the page's title (default: the model's name)
  --fps N             at most N frames kept per second of the run (default 30)
The page needs no network: three.js is inside it. It prints its size.
Details: docs/viewer.md.
)",
        {{"-o", "--channels", "--title", "--fps"}, {}}, parse_view, analysis::view);
}

} // namespace yamsc::cli
