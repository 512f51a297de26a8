#include "beam/elastodyn_beam.hpp"

#include <cmath>

namespace yamsc::beam {

namespace {

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

} // namespace

bool read_ed_modes(const ElastoDynFile& f, const std::vector<std::string>& requested,
                   const std::vector<EdModeKeys>& known, Beam& beam, diag::Diagnostics& diags) {
    std::vector<std::string> names;
    for (const EdModeKeys& k : known) names.push_back(k.name);
    bool ok = true;
    for (std::size_t r = 0; r < requested.size(); ++r) {
        const std::string& name = requested[r];
        const EdModeKeys* keys = nullptr;
        for (const EdModeKeys& k : known)
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
        Mode mode;
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
        beam.modes.push_back(std::move(mode));
    }
    return ok;
}

std::optional<EdStations> read_ed_stations(const ElastoDynFile& f, const std::string& count_key,
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
    EdStations out;
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

bool check_ed_length(const ElastoDynFile& f, double length, diag::Diagnostics& diags) {
    if (length > 0 && std::isfinite(length)) return true;
    diags.error(diag::Kind::InvalidValue, {f.file(), 0, 0},
                "the length of a beam from an ElastoDyn file must be > 0");
    return false;
}

} // namespace yamsc::beam
