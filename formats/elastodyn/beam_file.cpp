// The one reader of ElastoDyn tower and blade files (beam_file.hpp): where each kind
// keeps its modes, adjustment factors and table, then the skeleton both follow.
#include "elastodyn/beam_file.hpp"

#include "elastodyn/file.hpp"

#include <cmath>

namespace yamsc::elastodyn {

namespace {

/// How one mode is described in its file.
struct ModeKeys {
    std::string name;    // as requested: fa1, flap1, ...
    std::string shape;   // coefficient keys: shape(2) .. shape(6)
    std::string damping; // damping ratio in percent
    std::string tuner;   // modal stiffness tuner, or "" if the file has none
    int direction = 0;   // 0: x, 1: y
};

/// Where a kind of file keeps what: its modes, its adjustment factors of the mass and
/// of the two stiffnesses, and its table (the row count's key, the columns read, the
/// first being the span fraction, and which of them is which).
struct Layout {
    std::vector<ModeKeys> modes;
    std::string adjust_mass, adjust_x, adjust_y;
    std::string count;
    std::vector<std::string> columns;
    std::size_t mass = 0, stiffness_x = 0, stiffness_y = 0;
    int twist = -1;       // no twist column
    std::string positive; // the error when mass or a stiffness is not > 0
};

const Layout& layout(BeamKind kind) {
    // Tower: fore-aft bending displaces it along x (resisted by TwFAStif), side-side along y.
    static const Layout tower{{{"fa1", "TwFAM1Sh", "TwrFADmp(1)", "FAStTunr(1)", 0},
                               {"fa2", "TwFAM2Sh", "TwrFADmp(2)", "FAStTunr(2)", 0},
                               {"ss1", "TwSSM1Sh", "TwrSSDmp(1)", "SSStTunr(1)", 1},
                               {"ss2", "TwSSM2Sh", "TwrSSDmp(2)", "SSStTunr(2)", 1}},
                              "AdjTwMa",
                              "AdjFASt",
                              "AdjSSSt",
                              "NTwInpSt",
                              {"HtFract", "TMassDen", "TwFAStif", "TwSSStif"},
                              1,
                              2,
                              3,
                              -1,
                              "tower mass and stiffness must be > 0"};
    // Blade: flap bends about the principal axis of FlpStff (displacement along x at
    // zero twist), edge about that of EdgStff (along y). The edge mode has no tuner.
    // PitchAxis (aerodynamic centre location) is read for the table's shape, not used.
    static const Layout blade{
        {{"flap1", "BldFl1Sh", "BldFlDmp(1)", "FlStTunr(1)", 0},
         {"flap2", "BldFl2Sh", "BldFlDmp(2)", "FlStTunr(2)", 0},
         {"edge1", "BldEdgSh", "BldEdDmp(1)", "", 1}},
        "AdjBlMs",
        "AdjFlSt",
        "AdjEdSt",
        "NBlInpSt",
        {"BlFract", "PitchAxis", "StrcTwst", "BMassDen", "FlpStff", "EdgStff"},
        3,
        4,
        5,
        2,
        "blade mass and stiffness must be > 0"};
    return kind == BeamKind::tower ? tower : blade;
}

/// Shape coefficients of (z/L)^2 .. (z/L)^6, normalised so that the tip value is 1.
std::optional<std::vector<double>> read_shape(const ElastoDynFile& f, const std::string& key,
                                              diag::Diagnostics& diags) {
    std::vector<double> c(2, 0.0); // no constant or linear term: clamped root
    bool ok = true;
    for (int p = 2; p <= 6; ++p) {
        auto v = f.get_double(key + "(" + std::to_string(p) + ")", diags);
        ok = ok && v;
        c.push_back(v.value_or(0));
    }
    if (!ok) return std::nullopt;
    double sum = 0;
    for (double v : c) sum += v;
    const diag::Location where = f.location(key + "(2)");
    if (std::fabs(sum) < 1e-6) {
        diags.error(diag::Kind::InvalidValue, where,
                    "the coefficients of " + key + " add up to 0: the shape cannot be normalised");
        return std::nullopt;
    }
    // ElastoDyn rejects sums off by more than 0.001 (the NREL SS2 shape is at 0.999)
    if (std::fabs(sum - 1) > 1.000001e-3)
        diags.warning(diag::Kind::InvalidValue, where,
                      "the coefficients of " + key + " add up to " + std::to_string(sum) +
                          ", not 1; the shape is scaled to 1 at the tip");
    for (double& v : c) v /= sum;
    return c;
}

/// Appends the `requested` modes to `out`; false after reporting errors.
bool read_modes(const ElastoDynFile& f, const std::vector<std::string>& requested,
                const std::vector<ModeKeys>& known, std::vector<ModeShape>& out,
                diag::Diagnostics& diags) {
    std::vector<std::string> names;
    for (const ModeKeys& k : known) names.push_back(k.name);
    bool ok = true;
    for (std::size_t r = 0; r < requested.size(); ++r) {
        const std::string& name = requested[r];
        const ModeKeys* keys = nullptr;
        for (const ModeKeys& k : known)
            if (k.name == name) keys = &k;
        if (!keys) {
            diags.error(diag::Kind::InvalidValue, {f.file(), 0, 0},
                        "'" + name + "' is not a mode of this ElastoDyn file" +
                            diag::did_you_mean(name, names));
            ok = false;
            continue;
        }
        for (std::size_t e = 0; e < r; ++e)
            if (requested[e] == name) {
                diags.error(diag::Kind::InvalidValue, {f.file(), 0, 0},
                            "the mode '" + name + "' is requested twice");
                ok = false;
            }
        ModeShape mode;
        mode.name = name;
        mode.direction = keys->direction;
        auto coeffs = read_shape(f, keys->shape, diags);
        auto damping = f.get_double(keys->damping, diags);
        std::optional<double> tuner = 1.0;
        if (!keys->tuner.empty()) tuner = f.get_double(keys->tuner, diags);
        if (!coeffs || !damping || !tuner) {
            ok = false;
            continue;
        }
        if (*damping < 0) {
            diags.error(diag::Kind::InvalidValue, f.location(keys->damping),
                        "a damping ratio must be >= 0");
            ok = false;
        }
        if (!(*tuner > 0)) {
            diags.error(diag::Kind::InvalidValue, f.location(keys->tuner),
                        "a stiffness tuner must be > 0");
            ok = false;
        }
        mode.coeffs = *coeffs;
        mode.damping_ratio = *damping / 100; // percent in the file
        mode.stiffness_tuner = *tuner;
        out.push_back(std::move(mode));
    }
    return ok;
}

/// The rows of the distributed-properties table: `count_key` rows under the header
/// row that starts with `columns[0]`; values[row][i] is the column named columns[i].
/// The first column (span fraction) must rise strictly from 0 to 1.
struct Stations {
    std::vector<std::vector<double>> values;
    std::vector<int> lines;
};
std::optional<Stations> read_stations(const ElastoDynFile& f, const std::string& count_key,
                                      const std::vector<std::string>& columns,
                                      diag::Diagnostics& diags) {
    auto count = f.get_int(count_key, diags);
    if (!count) return std::nullopt;
    if (*count < 1 || *count > 100000) {
        diags.error(diag::Kind::InvalidValue, f.location(count_key),
                    "'" + count_key + "' must be between 1 and 100000");
        return std::nullopt;
    }
    auto table = f.get_table(columns[0], *count, diags);
    if (!table) return std::nullopt;
    std::vector<int> index;
    for (const std::string& c : columns) {
        index.push_back(table->column(c));
        if (index.back() < 0) {
            diags.error(diag::Kind::MissingProperty, {f.file(), table->header_line, 1},
                        "the table of '" + columns[0] + "' has no column '" + c + "'");
            return std::nullopt;
        }
    }
    Stations out;
    out.lines = table->lines;
    for (const auto& row : table->rows) {
        std::vector<double> v;
        for (int i : index) v.push_back(row[static_cast<std::size_t>(i)]);
        out.values.push_back(std::move(v));
    }
    bool ok = true;
    const std::size_t n = out.values.size();
    for (std::size_t r = 0; r < n; ++r) {
        const double s = out.values[r][0];
        const bool bad = (r == 0 && s != 0) || (r + 1 == n && n > 1 && s != 1) ||
                         (r > 0 && !(s > out.values[r - 1][0])) || s < 0 || s > 1;
        if (bad) {
            diags.error(diag::Kind::InvalidValue, {f.file(), out.lines[r], 1},
                        "'" + columns[0] +
                            "' must rise strictly from 0 at the first row to 1 "
                            "at the last");
            ok = false;
        }
    }
    if (!ok) return std::nullopt;
    return out;
}

} // namespace

const std::vector<std::string>& mode_names(BeamKind kind) {
    static const std::vector<std::string> tower{"fa1", "fa2", "ss1", "ss2"};
    static const std::vector<std::string> blade{"flap1", "flap2", "edge1"};
    return kind == BeamKind::tower ? tower : blade;
}

std::optional<BeamFile> read_beam_file(BeamKind kind,
                                       const std::shared_ptr<const diag::SourceFile>& file,
                                       const std::vector<std::string>& modes,
                                       diag::Diagnostics& diags) {
    const Layout& l = layout(kind);
    const ElastoDynFile f(file);
    const int errors = diags.error_count();
    BeamFile out;
    read_modes(f, modes, l.modes, out.modes, diags);
    auto mass_factor = f.get_double(l.adjust_mass, diags);
    auto x_factor = f.get_double(l.adjust_x, diags);
    auto y_factor = f.get_double(l.adjust_y, diags);
    auto table = read_stations(f, l.count, l.columns, diags);
    if (!mass_factor || !x_factor || !y_factor || !table) return std::nullopt;
    for (const std::string& key : {l.adjust_mass, l.adjust_x, l.adjust_y})
        if (!(*f.get_double(key, diags) > 0))
            diags.error(diag::Kind::InvalidValue, f.location(key),
                        "an adjustment factor must be > 0");
    for (std::size_t r = 0; r < table->values.size(); ++r) {
        const std::vector<double>& v = table->values[r];
        if (!(v[l.mass] > 0 && v[l.stiffness_x] > 0 && v[l.stiffness_y] > 0))
            diags.error(diag::Kind::InvalidValue, {file, table->lines[r], 1}, l.positive);
        Section s;
        s.fraction = v[0];
        s.mass_per_length = *mass_factor * v[l.mass];
        s.stiffness_x = *x_factor * v[l.stiffness_x];
        s.stiffness_y = *y_factor * v[l.stiffness_y];
        if (l.twist >= 0) s.twist_deg = v[static_cast<std::size_t>(l.twist)];
        out.sections.push_back(s);
    }
    if (diags.error_count() > errors) return std::nullopt;
    return out;
}

} // namespace yamsc::elastodyn
