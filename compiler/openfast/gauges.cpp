#include "openfast/gauges.hpp"

#include "beam/elastodyn.hpp"
#include "driver/files.hpp"
#include "openfast/gauge_nodes.hpp"
#include "openfast/model.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

namespace yamsc::openfast {

using driver::read_source;

namespace {

/// A station property, linear in the span fraction (as ElastoDyn interpolates).
double twist_at(const beam::Beam& b, double s) {
    const auto& st = b.stations;
    if (s <= st.front().s) return st.front().twist;
    for (std::size_t i = 1; i < st.size(); ++i)
        if (s <= st[i].s) {
            const double t = (s - st[i - 1].s) / (st[i].s - st[i - 1].s);
            return (1 - t) * st[i - 1].twist + t * st[i].twist;
        }
    return st.back().twist;
}

std::string line(const std::string& name, const std::string& value) {
    std::string text = "output " + name + " = " + value;
    text.resize(std::max<std::size_t>(text.size() + 1, 50), ' ');
    return text + "# [kN m]\n";
}

/// "a x + b y" in the model's syntax, the signs written once.
std::string combination(double a, const std::string& x, double b, const std::string& y) {
    std::string out = (a < 0 ? "-" : "") + mbd_number(std::fabs(a)) + " * " + x;
    return out + (b < 0 ? " - " : " + ") + mbd_number(std::fabs(b)) + " * " + y;
}

} // namespace

std::string gauge_outputs(const openfast::OpenFastDeck& deck, bool flexible_tower,
                          bool flexible_blades, diag::Diagnostics& diags) {
    if (!deck.ed) return "";
    const openfast::GaugeNodes nodes = openfast::read_gauge_nodes(*deck.ed);
    if (nodes.tower.empty() && nodes.blade.empty()) return "";
    std::string out =
        "\n# ---- ElastoDyn's strain gauges: the load the part beyond the gauge puts on it\n"
        "# (-reaction of the section, half the gauge element beyond it), deflected axes\n";
    // ElastoDyn's element J is the SID node J + 1 of the `elements` beam (node 1 is
    // the root).
    if (!nodes.tower.empty() && !flexible_tower)
        diags.warning(diag::Kind::NotSupported, {deck.ed, 0, 0},
                      "the tower gauges (NTwGages) need a flexible tower: left out");
    for (std::size_t k = 0; flexible_tower && k < nodes.tower.size(); ++k) {
        const int J = nodes.tower[k];
        if (J < 1 || J > deck.tower_nodes) {
            diags.warning(diag::Kind::InvalidValue, {deck.ed, 0, 0},
                          "TwrGagNd " + std::to_string(J) + " is not a tower node: left out");
            continue;
        }
        const std::string node = "tower.node(" + std::to_string(J + 1) + ")";
        for (const char* c : {"x", "y", "z"})
            out += line("TwHt" + std::to_string(k + 1) + "ML" + c + "t",
                        "-reaction_moment(" + node + ")." + c + " / 1000 in " + node);
    }
    if (!nodes.blade.empty() && !flexible_blades)
        diags.warning(diag::Kind::NotSupported, {deck.ed, 0, 0},
                      "the blade gauges (NBlGages) need flexible blades: left out");
    if (nodes.blade.empty() || !flexible_blades || deck.blade_files.empty()) return out;
    // The blade channels are in the local structural axes: the deflected node's
    // turned by the structural twist about z (ElastoDyn's n1, n2, n3).
    auto source = read_source(deck.blade_files.front(), diags);
    if (!source) return out;
    auto blade = beam::read_elastodyn_blade(source, deck["TipRad"] - deck["HubRad"], {}, diags);
    if (!blade) return out;
    for (std::size_t k = 0; k < nodes.blade.size(); ++k) {
        const int J = nodes.blade[k];
        if (J < 1 || J > deck.blade_nodes) {
            diags.warning(diag::Kind::InvalidValue, {deck.ed, 0, 0},
                          "BldGagNd " + std::to_string(J) + " is not a blade node: left out");
            continue;
        }
        // ElastoDyn's ThetaS: StrcTwst, about -z (the beam's twist is about +z).
        const double theta = -twist_at(*blade, (J - 0.5) / deck.blade_nodes);
        const std::string node = "blade1.node(" + std::to_string(J + 1) + ")";
        const std::string m = "reaction_moment(" + node + ")";
        const double c = std::cos(theta), s = std::sin(theta);
        const std::string name = "Spn" + std::to_string(k + 1) + "ML", in = ") / 1000 in ";
        // n1 = cos j1 - sin j2, n2 = sin j1 + cos j2; the channel is minus the section's.
        out += line(name + "xb1", "(" + combination(-c, m + ".x", s, m + ".y") + in + node);
        out += line(name + "yb1", "(" + combination(-s, m + ".x", -c, m + ".y") + in + node);
        out += line(name + "zb1", "-" + m + ".z / 1000 in " + node);
    }
    return out;
}

} // namespace yamsc::openfast
