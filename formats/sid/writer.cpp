#include "sid/writer.hpp"

#include "diag/diagnostics.hpp"
#include "sid/numbers.hpp"

#include <cstddef>
#include <string_view>

namespace yamsc::sid {
namespace {

/// `    key          = value`: keys padded like the files other tools write.
void key(std::string& out, std::string_view name, std::string_view value) {
    out += "    ";
    out += name;
    out.append(name.size() < 13 ? 13 - name.size() : 1, ' ');
    out += "= ";
    out += value;
    out += '\n';
}

std::string one_line(const std::string& text) {
    std::string out = text;
    for (char& c : out) {
        if (c == '\n' || c == '\r') c = ' ';
    }
    return out;
}

/// Whether every matrix of the expansion (m0 and each m1 slice) has the shape `structure`
/// promises: 0 all zero, 1 diagonal, 2 symmetric, 3 anything.
bool fits_structure(const Taylor& t) {
    if (t.structure == 3) return true;
    if (t.structure < 0 || t.structure > 3) return false;
    if (t.structure != 0 && t.nrow != t.ncol) return false;
    const int slices = t.order == 1 ? t.nq : 0;
    for (int i = 0; i < t.nrow; ++i) {
        for (int j = 0; j < t.ncol; ++j) {
            const bool must_be_zero = t.structure == 0 || (t.structure == 1 && i != j);
            for (int k = -1; k < slices; ++k) {
                const double v = k < 0 ? t.at0(i, j) : t.at1(i, j, k);
                if (must_be_zero && v != 0) return false;
                if (t.structure == 2 && v != (k < 0 ? t.at0(j, i) : t.at1(j, i, k))) return false;
            }
        }
    }
    return true;
}

void check_arrays(const Taylor& t, std::string_view name) {
    const std::size_t cells = static_cast<std::size_t>(t.nrow) * static_cast<std::size_t>(t.ncol);
    const bool ok = (t.order == 0 || t.order == 1) && t.nrow >= 0 && t.ncol >= 0 && t.nq >= 0 &&
                    t.m0.size() == cells &&
                    t.m1.size() == (t.order == 1 ? cells * static_cast<std::size_t>(t.nq) : 0);
    if (!ok) {
        throw diag::InternalError("write_sid: Taylor block '" + std::string(name) +
                                  "' has arrays that do not match order " +
                                  std::to_string(t.order) + ", " + std::to_string(t.nrow) + " x " +
                                  std::to_string(t.ncol) + ", nq " + std::to_string(t.nq));
    }
}

void write_taylor(std::string& out, std::string_view name, const Taylor& t) {
    check_arrays(t, name);
    const int structure = fits_structure(t) ? t.structure : 3;
    out += name;
    out += '\n';
    key(out, "order", std::to_string(t.order));
    key(out, "nrow", std::to_string(t.nrow));
    key(out, "ncol", std::to_string(t.ncol));
    key(out, "nq", std::to_string(t.nq));
    key(out, "nqn", std::to_string(t.nqn));
    key(out, "structure", std::to_string(structure));
    // The entries the structure lists: none for 0, i == j for 1, j <= i for 2, all for 3.
    const auto listed = [structure](int i, int j) {
        return structure == 3 || (structure == 2 && j <= i) || (structure == 1 && i == j);
    };
    for (int i = 0; i < t.nrow; ++i) {
        for (int j = 0; j < t.ncol; ++j) {
            if (!listed(i, j)) continue;
            key(out, "m0(" + std::to_string(i + 1) + ", " + std::to_string(j + 1) + ")",
                format_real(t.at0(i, j)));
        }
    }
    for (int i = 0; t.order == 1 && i < t.nrow; ++i) {
        for (int j = 0; j < t.ncol; ++j) {
            if (!listed(i, j)) continue;
            for (int k = 0; k < t.nq; ++k) {
                key(out,
                    "m1(" + std::to_string(i + 1) + ", " + std::to_string(j + 1) + ", " +
                        std::to_string(k + 1) + ")",
                    format_real(t.at1(i, j, k)));
            }
        }
    }
    out += "end ";
    out += name;
    out += '\n';
}

void write_node(std::string& out, const Node& node) {
    out += "new node = " + std::to_string(node.id) + "\n";
    out += "rframe = " + one_line(node.rframe) + "\n";
    write_taylor(out, "origin", node.origin);
    write_taylor(out, "phi", node.phi);
    write_taylor(out, "psi", node.psi);
    write_taylor(out, "AP", node.ap);
    if (node.has_sigma) write_taylor(out, "sigma", node.sigma);
    out += "end node\n";
}

} // namespace

std::string write_sid(const Sid& sid) {
    std::string out = "part\nnew modal\nrefmod\n";
    key(out, "mass", format_real(sid.mass));
    key(out, "nelastq", std::to_string(sid.nq));
    for (int k = 0; k < sid.nq; ++k) {
        const std::size_t at = static_cast<std::size_t>(k);
        key(out, "ielastq(" + std::to_string(k + 1) + ")",
            at < sid.mode_names.size() ? one_line(sid.mode_names[at]) : std::string());
    }
    out += "end refmod\nnew frame\n";
    for (const Node& node : sid.nodes) write_node(out, node);
    out += "end frame\n";
    write_taylor(out, "mdCM", sid.md_cm);
    write_taylor(out, "J", sid.J);
    write_taylor(out, "Ct", sid.Ct);
    write_taylor(out, "Cr", sid.Cr);
    write_taylor(out, "Me", sid.Me);
    write_taylor(out, "Gr", sid.Gr);
    write_taylor(out, "Ge", sid.Ge);
    write_taylor(out, "Oe", sid.Oe);
    write_taylor(out, "ksigma", sid.ksigma);
    write_taylor(out, "Ke", sid.Ke);
    write_taylor(out, "De", sid.De);
    out += "end modal\nend part\n";
    return out;
}

} // namespace yamsc::sid
