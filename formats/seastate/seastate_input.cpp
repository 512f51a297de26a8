#include "seastate/seastate_input.hpp"

#include "text/ascii.hpp"

#include "diag/read_text.hpp"
#include "elastodyn/file.hpp"
#include "hydrodyn/entries.hpp"

#include <cmath>

namespace yamsc::seastate {

using aerodyn::Entry;
using diag::Kind;
using hydrodyn::EntryReader;

diag::Location Input::location(const std::string& key) const {
    return hydrodyn::entry_location(entries, file, key);
}

namespace {

class Reader {
public:
    Reader(aerodyn::Cursor& c, Input& out)
        : r_(c, out.entries), d_(c.diags()), out_(out), errors_at_start_(d_.error_count()) {}

    void read() {
        r_.cursor().skip_header(2);
        r_.need("Echo");
        hydrodyn::read_sections(*this,
                                {&Reader::environment, &Reader::grid, &Reader::waves,
                                 &Reader::second_order, &Reader::constrained, &Reader::current,
                                 &Reader::maccamy_fuchs, &Reader::outputs},
                                d_, errors_at_start_);
    }

private:
    void environment() {
        r_.set_or_default(r_.need("WtrDens"), out_.water_density);
        r_.set_or_default(r_.need("WtrDpth"), out_.water_depth);
        r_.set_or_default(r_.need("MSL2SWL"), out_.msl2swl);
    }

    void grid() {
        r_.set(r_.need("X_HalfWidth"), out_.x_half_width);
        r_.set(r_.need("Y_HalfWidth"), out_.y_half_width);
        r_.set_or_default(r_.need("Z_Depth"), out_.z_depth);
        if (auto n = r_.count("NX", 2, max_grid_nodes)) out_.nx = *n;
        if (auto n = r_.count("NY", 2, max_grid_nodes)) out_.ny = *n;
        if (auto n = r_.count("NZ", 2, max_grid_nodes)) out_.nz = *n;
    }

    void waves() {
        if (auto e = r_.need("WaveMod")) wave_mod(*e);
        if (auto e = r_.need("WaveStMod")) {
            int v = 0;
            r_.set(e, v);
            if (v < 0 || v > 3) d_.error(Kind::InvalidValue, e->at(), "'WaveStMod' must be 0 to 3");
            out_.stretching = static_cast<Stretching>(std::clamp(v, 0, 3));
        }
        if (auto e = r_.maybe("WvCrntMod")) {
            r_.set(e, out_.wave_current_mod);
            if (out_.wave_current_mod != 0)
                r_.unsupported(e->at(), "WvCrntMod (wave-current interaction)");
        }
        r_.set(r_.need("WaveTMax"), out_.wave_tmax);
        r_.set(r_.need("WaveDT"), out_.wave_dt);
        r_.set(r_.need("WaveHs"), out_.wave_hs);
        r_.set(r_.need("WaveTp"), out_.wave_tp);
        r_.set_or_default(r_.need("WavePkShp"), out_.peak_shape);
        r_.set(r_.need("WvLowCOff"), out_.low_cutoff);
        r_.set(r_.need("WvHiCOff"), out_.high_cutoff);
        r_.set(r_.need("WaveDir"), out_.wave_dir_deg);
        if (auto e = r_.need("WaveDirMod")) {
            r_.set(e, out_.wave_dir_mod);
            if (out_.wave_dir_mod != 0 && irregular())
                r_.unsupported(e->at(), "WaveDirMod 1 (directional spreading)");
        }
        r_.set(r_.need("WaveDirSpread"), out_.wave_dir_spread);
        r_.set(r_.need("WaveNDir"), out_.wave_n_dir);
        r_.set(r_.need("WaveDirRange"), out_.wave_dir_range);
        out_.wave_dir_range = std::fabs(out_.wave_dir_range); // as SeaState
        if (auto e = r_.need("WaveSeed(1)")) {
            if (auto n = seed(*e, elastodyn::parse_number(e->value()))) out_.seed1 = *n;
        }
        if (auto e = r_.need("WaveSeed(2)")) seed2(*e);
        r_.set(r_.need("WaveNDAmp"), out_.normal_amplitudes);
        r_.set(r_.need("WvKinFile"), out_.wave_kin_file);
    }

    /// 0 to 7, or "1P#": regular waves whose phase is # degrees.
    void wave_mod(const Entry& e) {
        const std::string v = text::ascii_upper(e.value());
        if (v.size() > 2 && v.compare(0, 2, "1P") == 0) {
            auto phase = elastodyn::parse_number(v.substr(2));
            if (!phase) {
                d_.error(Kind::InvalidValue, e.at(),
                         "'WaveMod' 1P# needs the phase in degrees after 1P, not '" + e.value() +
                             "'");
                return;
            }
            out_.wave_mod = WaveKind::regular;
            out_.regular_user_phase = true;
            out_.wave_phase_deg = *phase;
            return;
        }
        auto n = elastodyn::parse_number(v);
        if (!n || *n != std::floor(*n) || *n < 0 || *n > 7) {
            d_.error(Kind::InvalidValue, e.at(),
                     "'WaveMod' must be 0 to 7 or 1P# (regular waves of phase # degrees), not '" +
                         e.value() + "'");
            return;
        }
        out_.wave_mod = static_cast<WaveKind>(static_cast<int>(*n));
        if (*n >= 3)
            r_.unsupported(e.at(),
                           "WaveMod " + std::to_string(static_cast<int>(*n)) +
                               " (only still water, regular and JONSWAP waves are modelled)");
    }

    /// A seed: a 32-bit integer, as SeaState's INTEGER(IntKi) reads it.
    std::optional<int> seed(const Entry& e, std::optional<double> n) {
        if (!n || *n != std::floor(*n) || *n < -2147483648.0 || *n > 2147483647.0) {
            d_.error(Kind::InvalidValue, e.at(),
                     "'" + e.key + "' must be a 32-bit integer, not '" + e.value() + "'");
            return std::nullopt;
        }
        return static_cast<int>(*n);
    }

    /// A number (the intrinsic generator's second seed) or RANLUX.
    void seed2(const Entry& e) {
        const std::string v = text::ascii_upper(e.value());
        if (!v.empty() && (v[0] == 'T' || v[0] == 'F')) {
            d_.error(Kind::InvalidValue, e.at(),
                     "'WaveSeed(2)': invalid generator '" + e.value() + "'");
            return;
        }
        if (auto number = elastodyn::parse_number(v)) {
            if (auto n = seed(e, number)) {
                out_.seed2 = *n;
                out_.generator = RandomGenerator::intrinsic;
            }
            return;
        }
        if (v != "RANLUX") {
            d_.error(Kind::InvalidValue, e.at(),
                     "'WaveSeed(2)' must be an integer or RANLUX, not '" + e.value() + "'");
            return;
        }
        out_.generator = RandomGenerator::ranlux;
    }

    bool irregular() const {
        return out_.wave_mod == WaveKind::irregular || out_.wave_mod == WaveKind::white_noise ||
               out_.wave_mod == WaveKind::user_spectrum;
    }

    double warn_if_nonzero(const char* key, const std::string& what) {
        double v = 0;
        auto e = r_.need(key);
        r_.set(e, v);
        if (e && v != 0) r_.unsupported(e->at(), what);
        return v;
    }

    void second_order() {
        for (auto [key, field] :
             {std::pair{"WvDiffQTF", &out_.diff_qtf}, std::pair{"WvSumQTF", &out_.sum_qtf}}) {
            auto e = r_.need(key);
            r_.set(e, *field);
            if (e && *field) r_.unsupported(e->at(), std::string(key) + " (second-order waves)");
        }
        r_.set(r_.need("WvLowCOffD"), out_.low_cutoff_diff);
        r_.set(r_.need("WvHiCOffD"), out_.high_cutoff_diff);
        r_.set(r_.need("WvLowCOffS"), out_.low_cutoff_sum);
        r_.set(r_.need("WvHiCOffS"), out_.high_cutoff_sum);
    }

    void constrained() {
        out_.const_wave_mod =
            static_cast<int>(warn_if_nonzero("ConstWaveMod", "ConstWaveMod (constrained waves)"));
        r_.set(r_.need("CrestHmax"), out_.crest_hmax);
        r_.set(r_.need("CrestTime"), out_.crest_time);
        r_.set(r_.need("CrestXi"), out_.crest_xi);
        r_.set(r_.need("CrestYi"), out_.crest_yi);
    }

    void current() {
        out_.curr_mod = static_cast<int>(warn_if_nonzero("CurrMod", "CurrMod (current)"));
        r_.set(r_.need("CurrSSV0"), out_.curr_ssv0);
        r_.set_or_default(r_.need("CurrSSDir"), out_.curr_ss_dir_deg);
        r_.set(r_.need("CurrNSRef"), out_.curr_ns_ref);
        r_.set(r_.need("CurrNSV0"), out_.curr_nsv0);
        r_.set(r_.need("CurrNSDir"), out_.curr_ns_dir_deg);
        r_.set(r_.need("CurrDIV"), out_.curr_div);
        r_.set(r_.need("CurrDIDir"), out_.curr_di_dir_deg);
    }

    void points(const char* count_key,
                std::initializer_list<std::pair<const char*, std::vector<double>*>> lists) {
        if (d_.error_count() != errors_at_start_) return;
        const auto n = r_.count(count_key, 0, max_points);
        if (!n) return;
        for (auto [key, into] : lists) {
            if (d_.error_count() != errors_at_start_) return;
            if (*n == 0) {
                r_.skip(1, std::string("the line of ") + key);
                continue;
            }
            if (auto v = r_.numbers(key, static_cast<std::size_t>(*n), key)) *into = *v;
        }
    }

    void maccamy_fuchs() {
        out_.mcfd = warn_if_nonzero("MCFD", "MacCamy-Fuchs diffraction (MCFD > 0)");
    }

    void outputs() {
        r_.set(r_.need("SeaStSum"), out_.sum_file);
        r_.set(r_.need("OutSwtch"), out_.out_switch);
        r_.set(r_.need("OutFmt"), out_.out_fmt);
        r_.set(r_.need("OutSFmt"), out_.out_sfmt);
        points("NWaveElev", {{"WaveElevxi", &out_.wave_elev_x}, {"WaveElevyi", &out_.wave_elev_y}});
        points("NWaveKin", {{"WaveKinxi", &out_.wave_kin_x},
                            {"WaveKinyi", &out_.wave_kin_y},
                            {"WaveKinzi", &out_.wave_kin_z}});
        if (d_.error_count() != errors_at_start_) return;
        r_.out_channels(out_.out_channels, out_.out_channel_lines);
    }

    EntryReader r_;
    diag::Diagnostics& d_;
    Input& out_;
    int errors_at_start_ = 0;
};

} // namespace

std::optional<Input> read_seastate_input(const std::shared_ptr<const diag::SourceFile>& file,
                                         diag::Diagnostics& diags,
                                         const aerodyn::IncludeReader& includes) {
    return hydrodyn::read_entries<Input, Reader>(file, diags, includes);
}

std::optional<Input> read_seastate_input(const std::filesystem::path& path,
                                         diag::Diagnostics& diags) {
    auto file = diag::read_text_file(path.string(), diags);
    if (!file) return std::nullopt;
    return read_seastate_input(file, diags);
}

} // namespace yamsc::seastate
