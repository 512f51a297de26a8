#include "aerodyn/airfoil_file.hpp"

#include <algorithm>
#include <cmath>

namespace yamsc::aerodyn {

using diag::Kind;

namespace {

struct UnsteadyKey {
    const char* name;
    std::optional<double> UnsteadyEntries::*value;
};

// ReadAFfile's order of the unsteady entries.
const UnsteadyKey unsteady_keys[] = {
    {"alpha0", &UnsteadyEntries::alpha0},
    {"alpha1", &UnsteadyEntries::alpha1},
    {"alpha2", &UnsteadyEntries::alpha2},
    {"alphaUpper", &UnsteadyEntries::alphaUpper},
    {"alphaLower", &UnsteadyEntries::alphaLower},
    {"eta_e", &UnsteadyEntries::eta_e},
    {"C_nalpha", &UnsteadyEntries::C_nalpha},
    {"C_lalpha", &UnsteadyEntries::C_lalpha},
    {"T_f0", &UnsteadyEntries::T_f0},
    {"T_V0", &UnsteadyEntries::T_V0},
    {"T_p", &UnsteadyEntries::T_p},
    {"T_VL", &UnsteadyEntries::T_VL},
    {"b1", &UnsteadyEntries::b1},
    {"b2", &UnsteadyEntries::b2},
    {"b5", &UnsteadyEntries::b5},
    {"A1", &UnsteadyEntries::A1},
    {"A2", &UnsteadyEntries::A2},
    {"A5", &UnsteadyEntries::A5},
    {"S1", &UnsteadyEntries::S1},
    {"S2", &UnsteadyEntries::S2},
    {"S3", &UnsteadyEntries::S3},
    {"S4", &UnsteadyEntries::S4},
    {"Cn1", &UnsteadyEntries::Cn1},
    {"Cn2", &UnsteadyEntries::Cn2},
    {"St_sh", &UnsteadyEntries::St_sh},
    {"Cd0", &UnsteadyEntries::Cd0},
    {"Cm0", &UnsteadyEntries::Cm0},
    {"k0", &UnsteadyEntries::k0},
    {"k1", &UnsteadyEntries::k1},
    {"k2", &UnsteadyEntries::k2},
    {"k3", &UnsteadyEntries::k3},
    {"k1_hat", &UnsteadyEntries::k1_hat},
    {"x_cp_bar", &UnsteadyEntries::x_cp_bar},
    {"UACutout", &UnsteadyEntries::UACutout},
    {"UACutout_delta", &UnsteadyEntries::UACutout_delta},
    {"filtCutOff", &UnsteadyEntries::filtCutOff},
};

/// OpenFAST's EqualRealNos in double precision (its default build).
bool nearly_equal(double a, double b) {
    const double tol = 100 * 2.220446049250313e-16 / 2;
    return std::fabs(a - b) <= std::max(std::fabs(a + b), 1.0) * tol;
}

class Reader {
public:
    Reader(Cursor& c, const AirfoilColumns& columns) : c_(c), columns_(columns) {}

    bool read(AirfoilFile& out) {
        bool bad = false;
        if (auto e = c_.expect("InterpOrd")) {
            if (auto v = c_.number_or_default(*e, bad)) {
                if (*v != 1 && *v != 3) {
                    c_.diags().error(Kind::InvalidValue, e->at(),
                                     "InterpOrd must be 1 (linear) or 3 (cubic spline)");
                    bad = true;
                } else {
                    out.interp_order = static_cast<int>(*v);
                    if (*v == 3)
                        c_.diags().warning(Kind::NotSupported, e->at(),
                                           "InterpOrd = 3: the polars are interpolated "
                                           "linearly (InterpOrd 1), not with cubic splines");
                }
            }
        } else {
            return false;
        }
        if (auto e = c_.take("RelThickness"))
            out.relative_thickness = c_.number_or_default(*e, bad);
        if (auto v = c_.expect_number("NonDimArea"))
            out.non_dimensional_area = *v;
        else
            bad = true;
        auto coords = c_.expect("NumCoords");
        if (!coords) return false;
        auto ncoords = count(c_, *coords, 0);
        if (!ncoords) return false;
        for (int r = 0; r < *ncoords; ++r) {
            auto row = numbers(2, "coordinate " + std::to_string(r + 1) + " of " +
                                      std::to_string(*ncoords) + " (NumCoords)");
            if (!row) return false;
            out.coords.emplace_back((*row)[0], (*row)[1]);
        }
        c_.take("BL_file"); // used by the aeroacoustics module only
        auto tables = c_.expect("NumTabs");
        if (!tables) return false;
        auto ntables = count(c_, *tables, 1);
        if (!ntables) return false;
        for (int t = 0; t < *ntables; ++t) {
            AirfoilTable table;
            if (!read_table(table)) return false;
            out.tables.push_back(std::move(table));
        }
        return !bad;
    }

private:
    bool read_table(AirfoilTable& table) {
        bool bad = false;
        auto re = c_.expect("Re");
        if (!re) return false;
        if (auto v = c_.number(*re)) {
            table.reynolds = *v;
            if (*v <= 0)
                c_.diags().warning(Kind::InvalidValue, re->at(),
                                   "Re must be positive (AeroDyn reports an error when it "
                                   "interpolates between tables by Re)");
        } else {
            bad = true;
        }
        auto prop = c_.take("UserProp");
        if (!prop) prop = c_.take("Ctrl"); // older files
        if (!prop) prop = c_.expect("UserProp");
        if (!prop) return false;
        if (auto v = c_.number(*prop))
            table.user_prop = *v;
        else
            bad = true;
        // Without InclUAdata (or with False) every constant is computed.
        if (auto e = c_.take("InclUAdata")) {
            if (auto v = c_.flag(*e))
                table.has_unsteady = *v;
            else
                bad = true;
        }
        if (table.has_unsteady)
            for (const UnsteadyKey& key : unsteady_keys)
                if (auto e = c_.take(key.name))
                    table.unsteady.*(key.value) = c_.number_or_default(*e, bad);
        auto rows = c_.expect("NumAlf");
        if (!rows) return false;
        table.at = rows->at();
        auto n = count(c_, *rows, 1);
        if (!n) return false;
        const int width =
            std::max({columns_.alpha, columns_.cl, columns_.cd, columns_.cm, columns_.cpmin});
        for (int r = 0; r < *n; ++r) {
            auto row = numbers(width, "row " + std::to_string(r + 1) + " of " + std::to_string(*n) +
                                          " of the table (NumAlf)");
            if (!row) return false;
            auto col = [&](int k) { return (*row)[static_cast<std::size_t>(k - 1)]; };
            if (!table.alpha.empty() && !(col(columns_.alpha) > table.alpha.back())) {
                c_.diags().error(Kind::InvalidValue, last_->at(columns_.alpha - 1),
                                 "the angles of attack must rise from row to row");
                return false;
            }
            table.alpha.push_back(col(columns_.alpha));
            table.cl.push_back(col(columns_.cl));
            table.cd.push_back(col(columns_.cd));
            if (columns_.cm > 0) table.cm.push_back(col(columns_.cm));
            if (columns_.cpmin > 0) table.cpmin.push_back(col(columns_.cpmin));
        }
        check_ends(table);
        return !bad;
    }

    /// AirfoilInfo: a table goes from -180 to 180 deg with equal coefficients at both
    /// ends; a warning when it does not, an error for a constant table whose ends differ.
    void check_ends(const AirfoilTable& t) {
        const std::size_t n = t.alpha.size();
        if (n < 2) return;
        const std::vector<const std::vector<double>*> coefs{&t.cl, &t.cd, &t.cm, &t.cpmin};
        bool constant = n < 3;
        if (!constant) {
            constant = true;
            for (const auto* c : coefs)
                for (std::size_t r = 0; r + 1 < c->size(); ++r)
                    if (!nearly_equal((*c)[r], (*c)[r + 1])) constant = false;
        }
        bool ends = true;
        for (const auto* c : coefs)
            if (!c->empty() && !nearly_equal(c->front(), c->back())) ends = false;
        if (!constant &&
            (!nearly_equal(t.alpha.front(), -180) || !nearly_equal(t.alpha.back(), 180)))
            ends = false;
        if (ends) return;
        const std::string message = "the table should go from -180 to 180 deg with the same "
                                    "coefficients at both ends";
        if (constant)
            c_.diags().error(Kind::InvalidValue, t.at, message);
        else
            c_.diags().warning(Kind::InvalidValue, t.at, message);
    }

    /// The first `width` numbers of the next line.
    std::optional<std::vector<double>> numbers(int width, const std::string& what) {
        last_ = c_.next(what);
        if (!last_) return std::nullopt;
        std::vector<double> out;
        for (int k = 0; k < width; ++k) {
            if (k >= static_cast<int>(last_->tokens.size())) {
                c_.diags().error(Kind::InvalidValue, last_->at(),
                                 "expected " + what + " here: " + std::to_string(width) +
                                     " numbers, found " + std::to_string(last_->tokens.size()));
                return std::nullopt;
            }
            const auto& token = last_->tokens[static_cast<std::size_t>(k)];
            auto v = elastodyn::parse_number(token.text);
            if (!v) {
                c_.diags().error(Kind::InvalidValue, last_->at(k),
                                 "expected " + what + " here: '" + token.text +
                                     "' is not a number");
                return std::nullopt;
            }
            out.push_back(*v);
        }
        return out;
    }

    Cursor& c_;
    const AirfoilColumns& columns_;
    const Line* last_ = nullptr;
};

} // namespace

std::optional<AirfoilFile> read_airfoil_file(const std::shared_ptr<const diag::SourceFile>& file,
                                             const AirfoilColumns& columns,
                                             diag::Diagnostics& diags,
                                             const IncludeReader& includes) {
    const int errors = diags.error_count();
    for (const auto& [name, value] : {std::pair{"InCol_Alfa", columns.alpha},
                                      {"InCol_Cl", columns.cl},
                                      {"InCol_Cd", columns.cd}})
        if (value < 1 || value > 1000) {
            diags.error(Kind::InvalidValue, {file, 0, 0},
                        std::string(name) + " must be a column from 1 to 1000");
            return std::nullopt;
        }
    if (columns.cm < 0 || columns.cm > 1000 || columns.cpmin < 0 || columns.cpmin > 1000) {
        diags.error(Kind::InvalidValue, {file, 0, 0},
                    "InCol_Cm and InCol_Cpmin must be 0 (no column) or a column from 1 to 1000");
        return std::nullopt;
    }
    Cursor c(logical_lines(file, &includes, diags), file, diags);
    AirfoilFile out;
    out.file = file;
    Reader reader(c, columns);
    const bool ok = reader.read(out);
    if (!ok || diags.error_count() != errors) return std::nullopt;
    return out;
}

} // namespace yamsc::aerodyn
