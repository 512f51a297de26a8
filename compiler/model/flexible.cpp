#include "model/flexible.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace yamsc::model {

using diag::Kind;

namespace {

/// A SID of nq modes whose order-0 entries are all unknown (NaN): the shape of a
/// symbolic body given without data.
sid::Sid unknown_sid(int nq) {
    const double unknown = std::nan("");
    auto block = [&](int nrow, int ncol, double v = std::nan("")) {
        sid::Taylor t = sid::Taylor::zeros(0, nrow, ncol, nq);
        for (double& x : t.m0) x = v;
        return t;
    };
    sid::Sid s;
    s.mass = unknown;
    s.nq = nq;
    for (int k = 0; k < nq; ++k) s.mode_names.push_back("mode " + std::to_string(k + 1));
    s.md_cm = block(3, 1);
    s.J = block(3, 3);
    s.Ct = block(nq, 3);
    s.Cr = block(nq, 3);
    s.Me = block(nq, nq);
    s.Gr = block(3, 3 * nq);
    s.Ge = block(nq, 3 * nq);
    s.Oe = block(nq, 6);
    s.ksigma = block(nq, 1, 0.0);
    s.Ke = block(nq, nq);
    s.De = block(nq, nq);
    return s;
}

class FlexibleChecker {
public:
    FlexibleChecker(const ast::FlexibleBody& body, FlexibleInputs& in) : b_(body), in_(in) {}

    std::optional<CheckedFlexible> run() {
        std::vector<ast::ModeEntry> modes;
        std::optional<sid::Sid> data;
        std::optional<beam::Beam> beam_made_of;
        int taylor = 1;
        const ast::Property* sid_file = nullptr;
        for (const auto& p : b_.properties) {
            if (p.key == "sid" && p.value.kind == ast::Value::Kind::string) {
                sid_file = &p;
            } else if (p.key == "modes" && p.value.kind == ast::Value::Kind::modes) {
                modes = p.value.modes;
            } else if (p.key == "taylor" && p.value.kind == ast::Value::Kind::expr) {
                auto v = number(p.value.expr, "taylor");
                if (v && (*v == 0 || *v == 1))
                    taylor = static_cast<int>(*v);
                else if (v)
                    error(Kind::InvalidValue, p.value.loc, "taylor must be 0 or 1");
            } else if (p.key == "sid" || p.key == "modes" || p.key == "taylor") {
                error(Kind::InvalidValue, p.value.loc,
                      "property '" + p.key + "' of a flexible body takes " +
                          (p.key == "sid"     ? "a file name in quotes"
                           : p.key == "modes" ? "a list of DOFs: (q1, _, q2)"
                                              : "0 or 1"));
            } else {
                error(Kind::UnknownProperty, p.loc,
                      "flexible bodies have no property '" + p.key + "'" +
                          diag::did_you_mean(p.key, {"sid", "modes", "taylor"}));
            }
        }
        int sources = (sid_file ? 1 : 0) + (b_.beam ? 1 : 0);
        Flexible flex;
        flex.taylor = taylor;
        flex.symbolic = b_.symbolic;
        if (b_.symbolic && sources == 0) {
            // No data: every order-0 shape integral is a parameter without a default.
            data = unknown_sid(static_cast<int>(modes.size()));
            flex.description = "symbolic shape integrals";
            if (!modes_of_sid(modes, b_.loc, *data, flex)) return std::nullopt;
            flex.sid = std::make_shared<const sid::Sid>(std::move(*data));
            return CheckedFlexible{std::move(flex), std::nullopt};
        }
        if (sources != 1) {
            error(sources ? Kind::InvalidValue : Kind::MissingProperty, b_.loc,
                  "flexible body '" + b_.name + "' needs exactly one of `sid = \"file\"` and " +
                      "a `beam` block");
            return std::nullopt;
        }
        if (sid_file) {
            const std::size_t reported = in_.diags.all().size();
            data = in_.data.sid_file(sid_file->value.str, sid_file->value.loc, in_.diags);
            if (!data) {
                note_way_back(reported, sid_file->value.loc,
                              "in the SID of flexible body '" + b_.name + "'");
                return std::nullopt;
            }
            flex.description = "SID file " + sid_file->value.str;
            if (!modes_of_sid(modes, sid_file->loc, *data, flex)) return std::nullopt;
        } else {
            if (!modes.empty())
                error(Kind::InvalidValue, b_.loc,
                      "give the modes of a beam inside its block: `modes = (fa1 -> q)`");
            auto beam = beam_of_block(*b_.beam, flex);
            if (!beam) return std::nullopt;
            data = in_.data.beam_sid(*beam, b_.name, b_.beam->loc, in_.diags);
            if (!data) return std::nullopt;
            beam_made_of = std::move(beam);
            flex.dofs.clear();
            for (const auto& m : beam_modes_) {
                flex.sid_modes.push_back(static_cast<int>(flex.dofs.size()));
                flex.dofs.push_back(dof_index(m));
            }
            if (std::count(flex.dofs.begin(), flex.dofs.end(), -1)) return std::nullopt;
        }
        flex.sid = std::make_shared<const sid::Sid>(std::move(*data));
        return CheckedFlexible{std::move(flex), std::move(beam_made_of)};
    }

private:
    void error(Kind kind, const Loc& loc, const std::string& message) {
        in_.diags.error(kind, loc, message);
    }

    /// Errors the data stage reported inside a data file (since diagnostic number
    /// `reported`) get a note at `loc`, the place in the model that named the file.
    /// Errors already at a place in the model (the file cannot be read, an unknown
    /// format) need none.
    void note_way_back(std::size_t reported, const Loc& loc, const std::string& message) {
        const auto& all = in_.diags.all();
        for (std::size_t i = reported; i < all.size(); ++i)
            if (all[i].severity == diag::Severity::error && all[i].loc.file != loc.file) {
                in_.diags.note(loc, message);
                return;
            }
    }

    std::optional<double> number(const Expr& e, const std::string& what) {
        std::string why;
        auto v = evaluate_with(e, in_.param_values, why);
        if (!v)
            error(Kind::NotConstant, e.loc,
                  what + " of flexible body '" + b_.name + "' must be a constant: it " + why);
        return v;
    }

    int dof_index(const ast::ModeEntry& m) {
        auto it = in_.names.find(m.dof);
        if (it != in_.names.end() && it->second.kind == NameKind::dof) return it->second.index;
        std::vector<std::string> dofs;
        for (const auto& [name, info] : in_.names)
            if (info.kind == NameKind::dof) dofs.push_back(name);
        error(it == in_.names.end() ? Kind::UnknownName : Kind::WrongKind, m.loc,
              "a mode needs a DOF, '" + m.dof + "' is " +
                  (it == in_.names.end() ? "not declared" : "not a DOF") +
                  diag::did_you_mean(m.dof, dofs));
        return -1;
    }

    /// `modes = (q1, _, q2)`: one entry per SID mode, `_` drops the mode.
    bool modes_of_sid(const std::vector<ast::ModeEntry>& modes, const Loc& loc, sid::Sid& data,
                      Flexible& flex) {
        if (static_cast<int>(modes.size()) != data.nq) {
            error(Kind::InvalidValue, modes.empty() ? loc : modes.front().loc,
                  "the SID of flexible body '" + b_.name + "' has " + std::to_string(data.nq) +
                      " modes: give `modes = (...)` with one DOF or `_` for each, not " +
                      std::to_string(modes.size()));
            return false;
        }
        std::vector<int> keep;
        bool ok = true;
        for (std::size_t k = 0; k < modes.size(); ++k) {
            if (modes[k].dof == "_") continue;
            if (!modes[k].mode.empty())
                error(Kind::InvalidValue, modes[k].loc,
                      "SID modes are given in order, without names: `modes = (q1, _, q2)`");
            int d = dof_index(modes[k]);
            ok = d >= 0 && ok;
            keep.push_back(static_cast<int>(k));
            flex.sid_modes.push_back(static_cast<int>(k));
            flex.dofs.push_back(d);
        }
        if (ok) data = select_modes(data, keep);
        return ok;
    }

    std::optional<beam::Beam> beam_of_block(const ast::Beam& block, Flexible& flex);
    std::optional<std::vector<std::pair<double, double>>> table(const ast::Property& p);
    std::optional<beam::Beam> inline_beam(const ast::Beam& block, double length, int stations);

    const ast::FlexibleBody& b_;
    FlexibleInputs& in_;
    std::vector<ast::ModeEntry> beam_modes_;
};

std::optional<std::vector<std::pair<double, double>>>
FlexibleChecker::table(const ast::Property& p) {
    std::vector<std::pair<double, double>> t;
    if (p.value.kind == ast::Value::Kind::expr) { // uniform
        auto v = number(p.value.expr, p.key);
        if (!v) return std::nullopt;
        return std::vector<std::pair<double, double>>{{0.0, *v}, {1.0, *v}};
    }
    if (p.value.kind != ast::Value::Kind::table) {
        error(Kind::InvalidValue, p.value.loc,
              p.key + " takes a value or a table `(0: a, 1: b)` of station fractions");
        return std::nullopt;
    }
    for (const auto& point : p.value.table) {
        auto s = number(point.station, "a station of " + p.key);
        auto v = number(point.value, p.key);
        if (!s || !v) return std::nullopt;
        if (*s < 0 || *s > 1 || (!t.empty() && *s <= t.back().first)) {
            error(Kind::InvalidValue, point.station.loc,
                  "stations of " + p.key + " must increase from 0 to 1");
            return std::nullopt;
        }
        t.emplace_back(*s, *v);
    }
    if (t.empty() || t.front().first != 0.0 || t.back().first != 1.0) {
        error(Kind::InvalidValue, p.value.loc, p.key + " must give values at stations 0 and 1");
        return std::nullopt;
    }
    return t;
}

double interpolate(const std::vector<std::pair<double, double>>& t, double s) {
    for (std::size_t i = 1; i < t.size(); ++i)
        if (s <= t[i].first) {
            double w = (s - t[i - 1].first) / (t[i].first - t[i - 1].first);
            return t[i - 1].second + w * (t[i].second - t[i - 1].second);
        }
    return t.back().second;
}

std::optional<beam::Beam> FlexibleChecker::beam_of_block(const ast::Beam& block, Flexible& flex) {
    std::optional<double> length;
    int stations = 50;
    int elements = 0;
    const ast::Property* modes = nullptr;
    for (const auto& p : block.properties) {
        if (p.key == "length" && p.value.kind == ast::Value::Kind::expr) {
            length = number(p.value.expr, "the beam length");
            if (length && *length <= 0) {
                error(Kind::InvalidValue, p.value.loc, "the beam length must be positive");
                return std::nullopt;
            }
        } else if (p.key == "stations" && p.value.kind == ast::Value::Kind::expr) {
            auto n = number(p.value.expr, "the number of stations");
            if (!n || *n < 3 || *n > 10000 || *n != std::floor(*n)) {
                if (n) error(Kind::InvalidValue, p.value.loc, "stations must be 3 to 10000");
                return std::nullopt;
            }
            stations = static_cast<int>(*n);
        } else if (p.key == "elements" && p.value.kind == ast::Value::Kind::expr) {
            // ElastoDyn's discretization (BldNodes, TwrNodes): docs/beam-preprocessing.md
            auto n = number(p.value.expr, "the number of elements");
            if (!n || *n < 1 || *n > 10000 || *n != std::floor(*n)) {
                if (n) error(Kind::InvalidValue, p.value.loc, "elements must be 1 to 10000");
                return std::nullopt;
            }
            elements = static_cast<int>(*n);
        } else if (p.key == "modes" && p.value.kind == ast::Value::Kind::modes) {
            modes = &p;
        }
    }
    if (!length) {
        error(Kind::MissingProperty, block.loc, "the beam of '" + b_.name + "' needs `length`");
        return std::nullopt;
    }
    if (!modes || modes->value.modes.empty()) {
        error(Kind::MissingProperty, block.loc,
              "the beam of '" + b_.name + "' needs `modes = (mode -> dof, ...)`");
        return std::nullopt;
    }
    std::vector<std::string> names;
    for (const auto& m : modes->value.modes) {
        if (m.mode.empty() || m.dof == "_") {
            error(Kind::InvalidValue, m.loc, "beam modes are written `mode -> dof`");
            return std::nullopt;
        }
        names.push_back(m.mode);
    }
    beam_modes_ = modes->value.modes;
    std::optional<beam::Beam> beam;
    if (block.file) {
        for (const auto& p : block.properties)
            if (p.key != "length" && p.key != "stations" && p.key != "modes" && p.key != "elements")
                error(Kind::UnknownProperty, p.loc,
                      "a beam read from a file has no property '" + p.key + "'" +
                          diag::did_you_mean(p.key, {"length", "stations", "modes", "elements"}));
        if (!block.mode_shapes.empty())
            error(Kind::InvalidValue, block.mode_shapes.front().loc,
                  "mode shapes come from the file; define them only in inline beams");
        const std::size_t reported = in_.diags.all().size();
        beam = in_.data.beam_file(block.format, *block.file, *length, names, block.loc, in_.diags);
        if (!beam) {
            note_way_back(reported, block.loc, "in the beam of flexible body '" + b_.name + "'");
            return std::nullopt;
        }
        beam->integration_stations = stations;
        beam->elements = elements;
        flex.description = block.format + " file " + *block.file;
    } else {
        beam = inline_beam(block, *length, stations);
        if (!beam) return std::nullopt;
        beam->elements = elements;
        flex.description = "inline beam";
    }
    return beam;
}

std::optional<beam::Beam> FlexibleChecker::inline_beam(const ast::Beam& block, double length,
                                                       int stations) {
    std::map<std::string, std::vector<std::pair<double, double>>> tables;
    double damping = 0;
    bool ok = true;
    const std::set<std::string> table_keys{"mass_per_length", "EI_x", "EI_y", "twist"};
    for (const auto& p : block.properties) {
        if (table_keys.count(p.key)) {
            auto t = table(p);
            ok = t.has_value() && ok;
            if (t) tables[p.key] = *t;
        } else if (p.key == "damping_ratio" && p.value.kind == ast::Value::Kind::expr) {
            auto v = number(p.value.expr, "the damping ratio");
            ok = v.has_value() && ok;
            if (v && (*v < 0 || *v >= 1)) {
                error(Kind::InvalidValue, p.value.loc,
                      "the damping ratio is a fraction of critical, from 0 to 1");
                ok = false;
            }
            if (v) damping = *v;
        } else if (p.key != "length" && p.key != "stations" && p.key != "modes" &&
                   p.key != "elements") {
            error(Kind::UnknownProperty, p.loc,
                  "beams have no property '" + p.key + "'" +
                      diag::did_you_mean(p.key, {"length", "stations", "elements", "modes",
                                                 "mass_per_length", "EI_x", "EI_y", "twist",
                                                 "damping_ratio"}));
            ok = false;
        }
    }
    for (const char* key : {"mass_per_length", "EI_x", "EI_y"})
        if (!tables.count(key) && ok) {
            error(Kind::MissingProperty, block.loc,
                  std::string("the beam of '") + b_.name + "' needs `" + key + " = ...`");
            ok = false;
        }
    if (!ok) return std::nullopt;
    beam::Beam beam;
    beam.length = length;
    beam.integration_stations = stations;
    std::set<double> fractions;
    for (const auto& [key, t] : tables)
        for (const auto& point : t) fractions.insert(point.first);
    for (double s : fractions) {
        beam::Station st;
        st.s = s;
        st.mass_per_length = interpolate(tables["mass_per_length"], s);
        st.EI_x = interpolate(tables["EI_x"], s);
        st.EI_y = interpolate(tables["EI_y"], s);
        if (tables.count("twist")) st.twist = interpolate(tables["twist"], s);
        beam.stations.push_back(st);
    }
    for (const auto& entry : beam_modes_) {
        auto shape = std::find_if(block.mode_shapes.begin(), block.mode_shapes.end(),
                                  [&](const ast::ModeShape& m) { return m.name == entry.mode; });
        if (shape == block.mode_shapes.end()) {
            std::vector<std::string> names;
            for (const auto& m : block.mode_shapes) names.push_back(m.name);
            error(Kind::UnknownName, entry.loc,
                  "unknown mode '" + entry.mode + "'" + diag::did_you_mean(entry.mode, names) +
                      " (define it with `mode " + entry.mode + " x = ...`)");
            return std::nullopt;
        }
        if (shape->direction != "x" && shape->direction != "y") {
            error(Kind::InvalidValue, shape->loc, "beam mode shapes bend along x or y");
            return std::nullopt;
        }
        std::string why;
        auto poly = polynomial_in_z(shape->shape, in_.param_values, why);
        if (!poly) {
            error(Kind::InvalidValue, shape->shape.loc,
                  "mode shape '" + shape->name + "' must be a polynomial in z: it " + why);
            return std::nullopt;
        }
        double tip = 0;
        for (double c : *poly) tip += c;
        if (std::fabs(tip) < 1e-12) {
            error(Kind::InvalidValue, shape->shape.loc,
                  "mode shape '" + shape->name + "' is zero at the tip: it cannot be normalised");
            return std::nullopt;
        }
        beam::Mode m;
        m.name = shape->name;
        m.direction = shape->direction == "x" ? 0 : 1;
        for (double c : *poly) m.coeffs.push_back(c / tip);
        m.damping_ratio = damping;
        beam.modes.push_back(m);
    }
    return beam;
}

} // namespace

std::optional<CheckedFlexible> check_flexible(const ast::FlexibleBody& body, FlexibleInputs& in) {
    return FlexibleChecker(body, in).run();
}

} // namespace yamsc::model
