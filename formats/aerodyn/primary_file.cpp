#include "aerodyn/primary_file.hpp"

#include <cctype>
#include <cmath>
#include <filesystem>

namespace yamsc::aerodyn {

namespace fs = std::filesystem;
using diag::Kind;

diag::Location PrimaryFile::location(const std::string& key) const {
    for (const auto& [k, at] : where)
        if (elastodyn::same_key(k, key)) return at;
    return {file, 0, 0};
}

namespace {

std::string resolve(const std::string& name, const diag::SourceFile& from) {
    fs::path p(name);
    if (p.is_relative()) p = fs::path(from.path()).parent_path() / p;
    return p.lexically_normal().string();
}

std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

class Reader {
public:
    Reader(Cursor& c, PrimaryFile& out) : c_(c), d_(c.diags()), out_(out) {}

    void read(int blades) {
        general();
        environment();
        bem();
        unsteady();
        airfoils();
        rotor(blades);
        hub_nacelle_tail();
        tower();
        outputs();
        legacy();
        check();
    }

private:
    // ---- entries, each remembered with its place -----------------------------------
    std::optional<Entry> seen(std::optional<Entry> e) {
        if (e) out_.where.emplace_back(e->key, e->at());
        return e;
    }
    std::optional<Entry> need(const char* key) { return seen(c_.expect(key)); }
    std::optional<Entry> maybe(const char* key) { return seen(c_.take(key)); }

    void set(std::optional<Entry> e, bool& v) {
        if (e)
            if (auto x = c_.flag(*e)) v = *x;
    }
    void set(std::optional<Entry> e, int& v) {
        if (e)
            if (auto x = c_.integer(*e)) v = *x;
    }
    void set(std::optional<Entry> e, double& v) {
        if (e)
            if (auto x = c_.number(*e)) v = *x;
    }
    void set_or_default(std::optional<Entry> e, std::optional<double>& v) {
        bool bad = false;
        if (e) v = c_.number_or_default(*e, bad);
    }

    /// An integer switch that older files give under `older` just before: the older
    /// value (mapped later, in legacy()) and the newer one read; both is an error.
    /// Returns whether the newer key is present.
    bool switch_pair(const char* older, const char* newer, std::optional<int>& old_value,
                     int& value) {
        if (auto e = maybe(older)) old_value = c_.integer(*e);
        auto e = maybe(newer);
        if (!e) return false;
        set(e, value);
        if (old_value)
            d_.error(Kind::InvalidValue, e->at(),
                     std::string("the file has both ") + newer + " and the older " + older +
                         ": keep " + newer);
        return true;
    }

    void unsupported(const std::string& key, const std::string& message) {
        d_.warning(Kind::NotSupported, out_.location(key), message);
    }

    // ---- sections ------------------------------------------------------------------
    void general() {
        c_.skip_header(2); // the banner and the title
        need("Echo");
        set_or_default(need("DTAero"), out_.dt_aero);
        switch_pair("WakeMod", "Wake_Mod", legacy_wake_, out_.wake_mod); // neither: 1
        if (auto e = maybe("AFAeroMod")) legacy_afaero_ = c_.integer(*e);
        set(need("TwrPotent"), out_.twr_potent);
        if (auto e = need("TwrShadow")) {
            // Older files give a flag.
            const std::string v = lower(e->value());
            if (v == "true" || v == "t" || v == "false" || v == "f")
                out_.twr_shadow = v[0] == 't' ? 1 : 0;
            else
                set(e, out_.twr_shadow);
        }
        set(need("TwrAero"), out_.twr_aero);
        if (auto e = maybe("FrozenWake")) legacy_frozen_ = c_.flag(*e);
        set(need("CavitCheck"), out_.cavit_check);
        set(maybe("NacelleDrag"), out_.nacelle_drag);
        set(need("CompAA"), out_.comp_aa);
        need("AA_InputFile");
    }

    void environment() {
        set_or_default(need("AirDens"), out_.air_density);
        set_or_default(need("KinVisc"), out_.kinematic_viscosity);
        set_or_default(need("SpdSound"), out_.speed_of_sound);
        set_or_default(need("Patm"), out_.patm);
        set_or_default(need("Pvap"), out_.pvap);
    }

    void bem() {
        set(maybe("BEM_Mod"), out_.bem_mod);
        switch_pair("SkewMod", "Skew_Mod", legacy_skew_, out_.skew_mod); // neither: 1
        set(maybe("SkewMomCorr"), out_.skew_mom_corr);
        if (auto e = maybe("SkewRedistr_Mod"))
            if (!is_default(e->value())) set(e, out_.skew_redistr_mod);
        auto factor = maybe("SkewModFactor");
        if (!factor) factor = need("SkewRedistrFactor");
        if (factor && !is_default(factor->value())) set(factor, out_.skew_redistr_factor);
        set(need("TipLoss"), out_.tip_loss);
        set(need("HubLoss"), out_.hub_loss);
        set(need("TanInd"), out_.tan_ind);
        set(need("AIDrag"), out_.ai_drag);
        set(need("TIDrag"), out_.ti_drag);
        set_or_default(need("IndToler"), out_.ind_toler);
        set(need("MaxIter"), out_.max_iter);
        if (auto e = maybe("SectAvg")) {
            set(e, out_.sect_avg);
            for (const char* key :
                 {"SectAvgWeighting", "SectAvgNPoints", "SectAvgPsiBwd", "SectAvgPsiFwd"})
                need(key);
        }
        set(need("DBEMT_Mod"), out_.dbemt_mod);
        set(need("tau1_const"), out_.tau1_const);
        need("OLAFInputFileName");
    }

    void unsteady() {
        auto aoa34 = maybe("AoA34");
        set(aoa34, out_.aoa34);
        aoa34_missing_ = !aoa34;
        if (!switch_pair("UAMod", "UA_Mod", legacy_ua_, out_.ua_mod)) {
            if (legacy_ua_)
                out_.ua_mod = *legacy_ua_;
            else
                set(need("UA_Mod"), out_.ua_mod);
        }
        set(need("FLookup"), out_.flookup);
        set(maybe("IntegrationMethod"), out_.integration_method);
        set(maybe("UAStartRad"), out_.ua_start_rad);
        set(maybe("UAEndRad"), out_.ua_end_rad);
    }

    void airfoils() {
        set(need("AFTabMod"), out_.af_tab_mod);
        set(need("InCol_Alfa"), out_.in_col_alfa);
        set(need("InCol_Cl"), out_.in_col_cl);
        set(need("InCol_Cd"), out_.in_col_cd);
        set(need("InCol_Cm"), out_.in_col_cm);
        set(need("InCol_Cpmin"), out_.in_col_cpmin);
        auto e = need("NumAFfiles");
        if (!e) return;
        auto n = count(c_, *e, 1);
        if (!n) return;
        for (int k = 0; k < *n; ++k)
            if (!file_line("airfoil file " + std::to_string(k + 1) + " of " + std::to_string(*n) +
                               " (NumAFfiles)",
                           out_.airfoils))
                return;
    }

    void rotor(int blades) {
        set(need("UseBlCm"), out_.use_bl_cm);
        const int lines = std::max(3, blades);
        for (int k = 0; k < lines; ++k)
            if (!file_line("ADBlFile(" + std::to_string(k + 1) + ")", out_.blade_files)) return;
    }

    /// A line whose first token is a file name (AFNames, ADBlFile), resolved.
    bool file_line(const std::string& what, std::vector<FileName>& into) {
        const Line* l = c_.next(what);
        if (!l) return false;
        into.push_back({resolve(l->tokens[0].text, *l->file), l->at()});
        return true;
    }

    void hub_nacelle_tail() {
        if (auto e = maybe("VolHub")) {
            set(e, out_.vol_hub);
            need("HubCenBx");
        }
        if (auto e = maybe("VolNac")) {
            set(e, out_.vol_nac);
            need("NacCenB");
        }
        for (const char* key : {"NacArea", "NacCd", "NacDragAC"}) maybe(key);
        if (auto e = maybe("TFinAero")) {
            set(e, out_.tfin_aero);
            need("TFinFile");
        }
    }

    void tower() {
        auto e = need("NumTwrNds");
        if (!e) return;
        auto n = count(c_, *e, 0);
        if (!n) return;
        const Line* header = c_.next("the header of the tower table");
        if (!header || !c_.next("the units row of the tower table")) return;
        static const char* names[] = {"TwrElev", "TwrDiam", "TwrCd", "TwrTI",
                                      "TwrCb",   "TwrCp",   "TwrCa"};
        double TowerRow::*fields[] = {&TowerRow::elevation, &TowerRow::diameter, &TowerRow::cd,
                                      &TowerRow::ti,        &TowerRow::cb,       &TowerRow::cp,
                                      &TowerRow::ca};
        int index[7];
        int width = 0;
        for (int k = 0; k < 7; ++k) {
            index[k] = -1;
            for (std::size_t j = 0; j < header->tokens.size(); ++j)
                if (elastodyn::same_key(header->tokens[j].text, names[k])) {
                    index[k] = static_cast<int>(j);
                    break;
                }
            if (index[k] < 0 && k < 3) {
                d_.error(Kind::MissingProperty, header->at(),
                         std::string("the tower table has no column '") + names[k] + "'");
                return;
            }
            width = std::max(width, index[k] + 1);
        }
        bool marine = false;
        for (int r = 0; r < *n; ++r) {
            const Line* l = c_.next("row " + std::to_string(r + 1) + " of " + std::to_string(*n) +
                                    " of the tower table (NumTwrNds)");
            if (!l) return;
            if (static_cast<int>(l->tokens.size()) < width) {
                d_.error(Kind::InvalidValue, l->at(),
                         "this row of the tower table has " + std::to_string(l->tokens.size()) +
                             " values, expected " + std::to_string(width));
                return;
            }
            TowerRow row;
            row.at = l->at();
            for (int k = 0; k < 7; ++k) {
                if (index[k] < 0) continue;
                const auto& token = l->tokens[static_cast<std::size_t>(index[k])];
                auto v = elastodyn::parse_number(token.text);
                if (!v) {
                    d_.error(Kind::InvalidValue, l->at(index[k]),
                             "'" + token.text + "' in column '" + names[k] + "' is not a number");
                    return;
                }
                row.*fields[k] = *v;
                if (k >= 4 && *v != 0 && !marine) {
                    marine = true;
                    d_.warning(Kind::NotSupported, l->at(index[k]),
                               std::string(names[k]) +
                                   " is not zero: buoyancy and marine (MHK) loads are not "
                                   "converted");
                }
            }
            out_.tower.push_back(row);
        }
    }

    void outputs() {
        need("SumPrint");
        out_.blade_out_nodes = nodes("NBlOuts", "BlOutNd");
        out_.tower_out_nodes = nodes("NTwOuts", "TwOutNd");
        if (!need("OutList")) return;
        // Channel names, quoted or not, until a line starting with END.
        while (const Line* l = c_.peek()) {
            const std::string first = lower(l->tokens[0].text);
            c_.next("OutList");
            if (!l->tokens[0].quoted && first.rfind("end", 0) == 0) break;
            for (const auto& t : l->tokens)
                if (!t.text.empty() && t.text != "-") out_.out_list.push_back(t.text);
        }
    }

    std::vector<int> nodes(const char* count_key, const char* list_key) {
        std::vector<int> out;
        auto n_entry = need(count_key);
        if (!n_entry) return out;
        auto n = c_.integer(*n_entry);
        auto list = need(list_key);
        if (!n || !list) return out;
        if (*n < 0 || *n > 9) {
            d_.error(Kind::InvalidValue, n_entry->at(), std::string(count_key) + " must be 0 to 9");
            return out;
        }
        if (static_cast<int>(list->values.size()) < *n) {
            d_.error(Kind::InvalidValue, list->at(),
                     std::string(list_key) + " must list " + std::to_string(*n) + " nodes");
            return out;
        }
        for (int k = 0; k < *n; ++k) {
            const auto& token = list->values[static_cast<std::size_t>(k)];
            auto v = elastodyn::parse_number(token.text);
            if (!v || *v < 1 || *v > max_count || *v != std::floor(*v)) {
                d_.error(Kind::InvalidValue, {list->line->file, list->line->number, token.col},
                         std::string(list_key) + " must list node numbers from 1");
                return {};
            }
            out.push_back(static_cast<int>(*v));
        }
        return out;
    }

    // ---- the older entries, as ParsePrimaryFileInfo maps them -------------------------
    void legacy() {
        if (legacy_frozen_ && *legacy_frozen_) out_.dbemt_mod = -1;
        if (legacy_wake_) {
            out_.wake_mod = *legacy_wake_;
            if (*legacy_wake_ == 1) out_.dbemt_mod = 0;
            if (*legacy_wake_ == 2) {
                out_.wake_mod = 1;
                if (out_.dbemt_mod < 0)
                    d_.error(Kind::InvalidValue, out_.location("DBEMT_Mod"),
                             "DBEMT_Mod must be 1, 2 or 3 with the older WakeMod = 2");
            }
            if (*legacy_wake_ < 0 || *legacy_wake_ > 3)
                d_.error(Kind::InvalidValue, out_.location("WakeMod"),
                         "WakeMod must be 0, 1, 2 or 3");
        }
        if (legacy_afaero_) {
            if (*legacy_afaero_ == 1) {
                out_.ua_mod = 0;
                if (aoa34_missing_) out_.aoa34 = false;
            } else if (*legacy_afaero_ == 2) {
                if (out_.ua_mod == 0)
                    d_.error(Kind::InvalidValue, out_.location("AFAeroMod"),
                             "AFAeroMod = 2 (unsteady) needs UA_Mod (or UAMod) other than 0");
            } else {
                d_.error(Kind::InvalidValue, out_.location("AFAeroMod"),
                         "AFAeroMod must be 1 or 2");
            }
        }
        if (legacy_skew_) {
            if (*legacy_skew_ == 0)
                out_.skew_mod = -1;
            else if (*legacy_skew_ == 1)
                out_.skew_mod = 0;
            else if (*legacy_skew_ == 2)
                out_.skew_mod = 1;
            else
                d_.error(Kind::InvalidValue, out_.location("SkewMod"), "SkewMod must be 0, 1 or 2");
        }
    }

    // ---- what AeroDyn's ValidateInputData refuses, and what yamsc does not convert ----
    void check() {
        auto error = [&](const char* key, const std::string& message) {
            d_.error(Kind::InvalidValue, out_.location(key), message);
        };
        const char* wake_key = legacy_wake_ ? "WakeMod" : "Wake_Mod";
        if (out_.wake_mod != 0 && out_.wake_mod != 1 && out_.wake_mod != 3)
            error(wake_key, "Wake_Mod must be 0 (none), 1 (BEMT) or 3 (free vortex wake)");
        if (out_.wake_mod == 3)
            unsupported(wake_key, std::string(wake_key) +
                                      " = 3: the free vortex wake (OLAF) is not converted; "
                                      "yamsc uses the blade-element momentum theory (1)");
        if (out_.twr_potent < 0 || out_.twr_potent > 2)
            error("TwrPotent", "TwrPotent must be 0, 1 or 2");
        if (out_.twr_shadow < 0 || out_.twr_shadow > 2)
            error("TwrShadow", "TwrShadow must be 0, 1 or 2");
        for (auto [key, value] : {std::pair{"AirDens", out_.air_density},
                                  {"KinVisc", out_.kinematic_viscosity},
                                  {"SpdSound", out_.speed_of_sound}})
            if (value && !(*value > 0)) error(key, std::string(key) + " must be positive");
        if (out_.bem_mod != 1 && out_.bem_mod != 2) error("BEM_Mod", "BEM_Mod must be 1 or 2");
        if (out_.bem_mod == 2)
            unsupported("BEM_Mod", "BEM_Mod = 2: the polar BEM projection is not converted; "
                                   "yamsc solves the legacy BEM (1)");
        if (out_.wake_mod == 1) {
            if (out_.max_iter < 1) error("MaxIter", "MaxIter must be at least 1");
            if (out_.ind_toler && !(*out_.ind_toler > 0))
                error("IndToler", "IndToler must be positive");
            if (out_.skew_mod < -1 || out_.skew_mod > 1)
                error(legacy_skew_ ? "SkewMod" : "Skew_Mod", "Skew_Mod must be -1, 0 or 1");
            if (out_.skew_redistr_mod != 0 && out_.skew_redistr_mod != 1)
                error("SkewRedistr_Mod", "SkewRedistr_Mod must be 0 or 1");
        }
        if (out_.dbemt_mod < -1 || out_.dbemt_mod > 3)
            error("DBEMT_Mod", "DBEMT_Mod must be -1, 0, 1, 2 or 3");
        if (out_.dbemt_mod == -1)
            unsupported(legacy_frozen_ ? "FrozenWake" : "DBEMT_Mod",
                        "the frozen wake (DBEMT_Mod = -1, FrozenWake = True) is how AeroDyn "
                        "linearizes: yamsc's `lin` freezes the wake itself; simulations run "
                        "without dynamic inflow");
        if (out_.ua_mod < 0 || out_.ua_mod > 7 || out_.ua_mod == 1)
            error(legacy_ua_ ? "UAMod" : "UA_Mod", "UA_Mod must be 0 or 2 to 7");
        else if (out_.ua_mod != 0 && out_.ua_mod != 3 && out_.ua_mod != 6)
            unsupported(legacy_ua_ ? "UAMod" : "UA_Mod",
                        "UA_Mod = " + std::to_string(out_.ua_mod) +
                            ": only the Beddoes-Leishman model of Minnema/Pierce (3) and Oye's "
                            "(6) are converted; this rotor runs quasi-steady airfoils");
        if (out_.ua_start_rad < 0 || out_.ua_start_rad > 1 || out_.ua_end_rad < 0 ||
            out_.ua_end_rad > 1)
            error("UAStartRad", "UAStartRad and UAEndRad must be fractions of the radius, 0 to 1");
        if (out_.af_tab_mod < 1 || out_.af_tab_mod > 3)
            error("AFTabMod", "AFTabMod must be 1, 2 or 3");
        else if (out_.af_tab_mod != 1)
            unsupported("AFTabMod", "AFTabMod = " + std::to_string(out_.af_tab_mod) +
                                        ": interpolation between tables is not converted; "
                                        "each airfoil uses its first table (AFTabMod 1)");
        for (auto [key, value] : {std::pair{"InCol_Alfa", out_.in_col_alfa},
                                  {"InCol_Cl", out_.in_col_cl},
                                  {"InCol_Cd", out_.in_col_cd}})
            if (value < 1 || value > 1000) error(key, std::string(key) + " must be 1 to 1000");
        for (auto [key, value] :
             {std::pair{"InCol_Cm", out_.in_col_cm}, {"InCol_Cpmin", out_.in_col_cpmin}})
            if (value < 0 || value > 1000) error(key, std::string(key) + " must be 0 to 1000");
        for (auto [key, on] : {std::pair{"CavitCheck", out_.cavit_check},
                               {"NacelleDrag", out_.nacelle_drag},
                               {"CompAA", out_.comp_aa},
                               {"SectAvg", out_.sect_avg},
                               {"TFinAero", out_.tfin_aero}})
            if (on) unsupported(key, std::string(key) + " = True: " + not_converted(key));
        if (out_.vol_hub != 0)
            unsupported("VolHub", "VolHub is not zero: buoyancy is not converted");
        if (out_.vol_nac != 0)
            unsupported("VolNac", "VolNac is not zero: buoyancy is not converted");
        const bool tower_used = out_.twr_potent != 0 || out_.twr_shadow != 0 || out_.twr_aero;
        if (tower_used) {
            if (out_.tower.size() < 2)
                error("NumTwrNds", "the tower influence and drag need 2 tower nodes or more");
            for (std::size_t k = 0; k < out_.tower.size(); ++k) {
                if (!(out_.tower[k].diameter > 0))
                    d_.error(Kind::InvalidValue, out_.tower[k].at, "TwrDiam must be positive");
                if (k > 0 && !(out_.tower[k].elevation > out_.tower[k - 1].elevation))
                    d_.error(Kind::InvalidValue, out_.tower[k].at, "TwrElev must rise");
            }
        }
        for (int node : out_.tower_out_nodes)
            if (node > static_cast<int>(out_.tower.size()))
                error("TwOutNd", "TwOutNd must be tower nodes, 1 to NumTwrNds");
    }

    static std::string not_converted(const std::string& key) {
        if (key == "CavitCheck") return "the cavitation check (MHK) is not converted";
        if (key == "NacelleDrag") return "the nacelle drag is not converted";
        if (key == "CompAA") return "the aeroacoustics are not converted";
        if (key == "SectAvg") return "sector averaging of the inflow is not converted";
        return "the tail fin aerodynamics are not converted";
    }

    Cursor& c_;
    diag::Diagnostics& d_;
    PrimaryFile& out_;
    std::optional<int> legacy_wake_, legacy_afaero_, legacy_skew_, legacy_ua_;
    std::optional<bool> legacy_frozen_;
    bool aoa34_missing_ = false;
};

} // namespace

std::optional<PrimaryFile> read_primary_file(const std::shared_ptr<const diag::SourceFile>& file,
                                             int blades, diag::Diagnostics& diags,
                                             const IncludeReader& includes) {
    const int errors = diags.error_count();
    Cursor c(logical_lines(file, &includes, diags), file, diags);
    PrimaryFile out;
    out.file = file;
    Reader(c, out).read(std::clamp(blades, 1, 100));
    if (diags.error_count() != errors) return std::nullopt;
    return out;
}

} // namespace yamsc::aerodyn
