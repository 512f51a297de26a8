// `yamsc sid`: the SID of a beam from an ElastoDyn tower or blade file.
#include "cli/commands/commands.hpp"
#include "driver/commands.hpp"

namespace yamsc::cli {

namespace {

driver::SidOptions parse_sid(const Args& a) {
    driver::SidOptions o;
    o.tower = a.get("--elastodyn-tower");
    o.blade = a.get("--elastodyn-blade");
    o.length = a.number("--length", 0);
    o.stations = static_cast<int>(a.number("--stations", 50));
    o.output = a.get("-o");
    o.modes = comma_list(a.get("--modes"));
    return o;
}

} // namespace

Command sid_command() {
    return make_command(
        "sid", "the shape integrals (SID) of an ElastoDyn tower or blade",
        R"(yamsc sid --elastodyn-tower FILE | --elastodyn-blade FILE --length L [--modes fa1,ss1,..]
          [--stations N] [-o body.sid])",
        R"(  --elastodyn-tower FILE  an ElastoDyn tower file
  --elastodyn-blade FILE  an ElastoDyn blade file
  --length L          the beam's length [m]
  --modes m,..        tower fa1 fa2 ss1 ss2 (default fa1,ss1); blade flap1 flap2 edge1 (all)
  --stations N        integration stations and SID nodes (50)
  -o FILE             the SID file (default stdout)
Details: docs/sid-format.md.
)",
        {{"--elastodyn-tower", "--elastodyn-blade", "--length", "--modes", "--stations", "-o"}, {}},
        parse_sid, driver::sid);
}

} // namespace yamsc::cli
