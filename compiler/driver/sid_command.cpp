// `yamsc sid`: the SID of a beam from an ElastoDyn tower or blade file.
#include "beam/elastodyn.hpp"
#include "beam/make_sid.hpp"
#include "driver/commands.hpp"
#include "driver/files.hpp"
#include "driver/outputs.hpp"
#include "sid/writer.hpp"

#include <yamsc/atomic_file.hpp>

#include <ostream>

namespace yamsc::driver {

int sid(const SidOptions& o, std::ostream& out, std::ostream& err) {
    if (o.tower.empty() == o.blade.empty())
        throw UsageError("give one of --elastodyn-tower FILE and --elastodyn-blade FILE");
    if (!(o.length > 0)) throw UsageError("--length L (the beam length in m) is required");
    if (o.stations < 3 || o.stations > 10000) throw UsageError("--stations must be 3 to 10000");
    const bool tower = !o.tower.empty();
    const bool to_stdout = o.output.empty() || o.output == "-";
    check_outputs({{"--elastodyn-tower", o.tower}, {"--elastodyn-blade", o.blade}},
                  {{"-o", to_stdout ? "" : o.output}});
    std::vector<std::string> modes = o.modes;
    if (modes.empty())
        modes = tower ? std::vector<std::string>{"fa1", "ss1"}
                      : std::vector<std::string>{"flap1", "edge1", "flap2"};
    diag::Diagnostics diags;
    auto file = read_source(tower ? o.tower : o.blade, diags);
    std::optional<beam::Beam> b;
    if (file)
        b = tower ? beam::read_elastodyn_tower(file, o.length, modes, diags)
                  : beam::read_elastodyn_blade(file, o.length, modes, diags);
    err << diags.render();
    if (!b || diags.has_errors()) return 1;
    b->integration_stations = o.stations;
    sid::Sid data = beam::make_sid(*b);
    std::string text = sid::write_sid(data);
    if (to_stdout)
        out << text;
    else
        runtime::write_file_atomically(o.output, text);
    return 0;
}

} // namespace yamsc::driver
