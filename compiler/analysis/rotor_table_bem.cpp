// `yamsc rotor-table DECK.fst -o Cp_Ct_Cq.txt`: the rotor's Cp/Ct/Cq table in
// ROSCO's format computed with AeroDyn's steady BEM on the deck's rigid rotor
// (ElastoDyn's geometry, AeroDyn's blades and airfoils), as NREL's tools make
// it with AeroDyn (yamsc/aero/rotor_table.hpp).
#include "analysis/rotor_table_bem.hpp"
#include "aerodyn_input/rotor.hpp"
#include "analysis/commands.hpp"
#include "driver/outputs.hpp"

#include "diag/errors.hpp"
#include "openfast/deck.hpp"

#include <yamsc/aero/rotor_table.hpp>
#include <yamsc/atomic_file.hpp>

#include <sstream>

namespace yamsc::analysis {

namespace {

constexpr double deg = 3.14159265358979323846 / 180;

} // namespace

bool is_openfast_deck(const std::string& path) {
    return path.size() > 4 && path.compare(path.size() - 4, 4, ".fst") == 0;
}

int rotor_table_from_deck(const driver::RotorTableOptions& o, std::ostream& out,
                          std::ostream& err) {
    driver::check_outputs({{"the deck", o.table}}, {{"-o", o.output}});
    diag::Diagnostics diags;
    const auto deck = openfast::read_openfast_deck(o.table, diags);
    if (!deck) throw diag::UserError(diags.render());
    const auto aero_file = deck->module_files.find("AeroFile");
    if (aero_file == deck->module_files.end())
        throw diag::UserError(o.table + ": the deck names no AeroFile");
    const auto rotor = aerodyn_input::read_aerodyn_rotor(aero_file->second, deck->blades, diags);
    if (!rotor) throw diag::UserError(diags.render());
    if (!diags.all().empty()) err << diags.render();

    aero::RotorGeometry g;
    const openfast::OpenFastDeck& d = *deck;
    g.hub_radius = d["HubRad"];
    g.precone = d["PreCone1"] * deg;
    g.shaft_tilt = d["ShftTilt"] * deg;
    g.overhang = d["OverHang"];
    g.twr2shft = d["Twr2Shft"];
    g.tower_height = d["TowerHt"];
    for (int k = 2; k <= deck->blades; ++k)
        if (d["PreCone" + std::to_string(k)] != d["PreCone1"])
            throw diag::UserError(o.table + ": rotor-table needs one precone for every blade");

    aero::TableRequest req;
    if (o.tsr.size() < 2 || o.pitch_deg.size() < 2)
        throw diag::UsageError("rotor-table needs two or more TSRs and pitch angles");
    req.tsr = o.tsr;
    req.pitch_deg = o.pitch_deg;
    req.wind_speed = o.wind;
    req.rotor_radius = d["TipRad"];
    req.azimuths = o.azimuths;
    const runtime::PerformanceTable t = aero::rotor_performance_table(*rotor, g, req);
    std::ostringstream text;
    aero::write_performance_table(text, t, req.wind_speed, deck->title);
    runtime::write_file_atomically(o.output, text.str());
    out << "wrote " << o.output << " (" << t.tsr.size() << " TSRs x " << t.pitch_deg.size()
        << " pitch angles, AeroDyn's steady BEM at " << req.wind_speed << " m/s)\n";
    return 0;
}

} // namespace yamsc::analysis
