// InflowWind, AeroDyn and ServoDyn of a full deck as the rotor block, the wind and
// the controller hookup of a yamsc model (see operation.hpp).
#include "openfast/operation.hpp"

#include "driver/files.hpp"
#include "elastodyn/file.hpp"
#include "openfast/model.hpp"

#include <cmath>
#include <filesystem>

namespace yamsc::openfast {

using driver::read_source;

namespace fs = std::filesystem;
using diag::Kind;

namespace {

std::string file_line(const elastodyn::ElastoDynFile& f, const std::string& key) {
    const diag::Location at = f.location(key);
    return fs::path(f.file()->path()).filename().string() + ":" + std::to_string(at.line);
}

std::string resolve(const std::string& name, const diag::SourceFile& from) {
    const fs::path p(name);
    if (p.is_absolute()) return p.lexically_normal().string();
    return (fs::path(from.path()).parent_path() / p).lexically_normal().string();
}

/// A module file the `.fst` names, read; nullptr (and an error) when it cannot be.
std::optional<elastodyn::ElastoDynFile>
module_file(const openfast::OpenFastDeck& deck, const std::string& key, diag::Diagnostics& diags) {
    auto it = deck.module_files.find(key);
    if (it == deck.module_files.end()) {
        diags.error(Kind::MissingProperty, {deck.fst, 0, 0},
                    "the .fst switches its module on but names no " + key);
        return std::nullopt;
    }
    auto source = read_source(it->second, diags);
    if (!source) return std::nullopt;
    return elastodyn::ElastoDynFile(source);
}

/// `PerfFileName` of a ROSCO controller input (`"file"  ! PerfFileName - ...`), resolved.
std::string rosco_performance_file(const std::string& discon_in, diag::Diagnostics& diags) {
    diag::Diagnostics quiet; // a missing or foreign controller input is not an error here
    auto source = read_source(discon_in, quiet);
    if (!source) return {};
    for (int line = 1; line <= source->line_count(); ++line) {
        const std::string text(source->line(line));
        const auto bang = text.find('!');
        if (bang == std::string::npos) continue;
        const auto key = elastodyn::tokenize(text.substr(bang + 1));
        const auto value = elastodyn::tokenize(text.substr(0, bang));
        if (key.empty() || value.empty() || key[0].text != "PerfFileName") continue;
        const std::string path = resolve(value[0].text, *source);
        if (!fs::exists(path))
            diags.warning(Kind::Io, {source, line, value[0].col},
                          "the performance table '" + value[0].text +
                              "' does not exist: give --cp-table FILE");
        return path;
    }
    return {};
}

class OperationReader {
public:
    OperationReader(const openfast::OpenFastDeck& deck, diag::Diagnostics& diags)
        : deck_(deck), diags_(diags) {}

    std::optional<Operation> read(const std::string& cp_table, bool blade_elements) {
        if (!deck_.fst || switch_of("CompAero") == "0" || switch_of("CompAero").empty())
            return std::nullopt;
        op_.rotor_radius = deck_["TipRad"];
        op_.blade_elements = blade_elements;
        aerodyn();
        if (switch_of("CompInflow") == "1") inflow_wind();
        if (switch_of("CompServo") == "1") servodyn();
        if (!cp_table.empty()) {
            op_.table = fs::absolute(cp_table).lexically_normal().string();
            op_.table_from = "--cp-table";
        } else if (!op_.controller_input.empty()) {
            op_.table = rosco_performance_file(op_.controller_input, diags_);
            if (!op_.table.empty())
                op_.table_from =
                    "PerfFileName, " + fs::path(op_.controller_input).filename().string();
        }
        if (op_.table.empty() && !op_.blade_elements)
            diags_.warning(Kind::MissingProperty, at("CompAero"),
                           "no Cp/Ct/Cq table: give --cp-table FILE (the model's header names "
                           "TABLE in the command for its rotor block)");
        return op_;
    }

private:
    std::string switch_of(const std::string& name) const {
        auto it = deck_.modules.find(name);
        return it == deck_.modules.end() ? "" : it->second.value;
    }
    diag::Location at(const std::string& name) const {
        auto it = deck_.modules.find(name);
        if (it == deck_.modules.end()) return {deck_.fst, 0, 0};
        return {deck_.fst, it->second.line, it->second.col};
    }

    void aerodyn() {
        if (op_.blade_elements) {
            if (auto it = deck_.module_files.find("AeroFile"); it != deck_.module_files.end())
                op_.aerodyn = it->second;
            diags_.warning(Kind::NotSupported, at("CompAero"),
                           "CompAero = " + switch_of("CompAero") +
                               ": AeroDyn's blade elements become the `blade_elements` block "
                               "(`sim --aero` the AeroDyn file): BEM on the blades, with the "
                               "file's dynamic inflow, unsteady airfoils and tower influence "
                               "(docs/aerodynamics.md)");
        } else {
            diags_.warning(Kind::NotSupported, at("CompAero"),
                           "CompAero = " + switch_of("CompAero") +
                               ": AeroDyn's blade elements (induction, dynamic inflow, unsteady "
                               "aerodynamics, tower influence) become the quasi-steady rotor "
                               "block of a Cp/Ct/Cq table: thrust and torque on the rotor (`sim "
                               "--aero`)");
        }
        if (deck_.fst_air_density) {
            op_.air_density = *deck_.fst_air_density;
            op_.air_density_from = deck_.fst_air_density_at;
            return;
        }
        auto ad = module_file(deck_, "AeroFile", diags_);
        if (!ad) return;
        if (auto rho = ad->get_double("AirDens", diags_)) {
            op_.air_density = *rho;
            op_.air_density_from = file_line(*ad, "AirDens");
        }
    }

    void inflow_wind() {
        auto iw = module_file(deck_, "InflowFile", diags_);
        if (!iw) return;
        const auto type = iw->get_int("WindType", diags_);
        if (!type) return;
        // The blade elements take InflowWind's field itself (`--wind` the InflowWind
        // file: shear, direction, upflow, a uniform wind file's columns at every node).
        // A full field (TurbSim 3, HAWC 5) is named the same way; a rotor table then
        // reads its hub-height wind (its reference speed, full_field.hpp).
        const bool full_field = *type == 3 || *type == 5;
        if ((op_.blade_elements && (*type == 1 || *type == 2)) || full_field) {
            if (auto it = deck_.module_files.find("InflowFile"); it != deck_.module_files.end())
                op_.wind = it->second;
            op_.wind_from = file_line(*iw, "WindType");
            if (full_field && !op_.blade_elements)
                diags_.warning(Kind::NotSupported, iw->location("WindType"),
                               "WindType = " + std::to_string(*type) +
                                   ": the rotor block of a Cp/Ct/Cq table takes the full "
                                   "field's hub-height wind; the field across the rotor needs "
                                   "AeroDyn's blade elements");
            return;
        }
        if (*type == 1) {
            const auto speed = iw->get_double("HWindSpeed", diags_);
            const auto ref = iw->get_double("RefHt", diags_);
            const auto exponent = iw->get_double("PLexp", diags_);
            if (!speed || !ref || !exponent) return;
            // The block reads the wind at the hub; InflowWind gives it at RefHt. The apex
            // sits OverHang along the shaft, tilted by ShftTilt (both < 0 upwind: higher).
            const double hub = deck_["TowerHt"] + deck_["Twr2Shft"] +
                               deck_["OverHang"] * std::sin(deck_["ShftTilt"] * M_PI / 180);
            const double at_hub =
                *exponent == 0 ? *speed : *speed * std::pow(hub / *ref, *exponent);
            op_.wind_speed = at_hub;
            op_.wind = mbd_number(at_hub);
            op_.wind_from = file_line(*iw, "HWindSpeed");
            if (*exponent != 0)
                diags_.warning(Kind::NotSupported, iw->location("PLexp"),
                               "PLexp = " + mbd_number(*exponent) +
                                   ": the rotor block takes the hub-height wind, " +
                                   mbd_number(at_hub) +
                                   " m/s; the shear across the rotor is "
                                   "not converted");
        } else if (*type == 2) {
            const auto file = iw->get_string("Filename_Uni", diags_);
            if (!file) return;
            op_.wind = resolve(*file, *iw->file());
            op_.wind_from = file_line(*iw, "Filename_Uni");
            diags_.warning(Kind::NotSupported, iw->location("Filename_Uni"),
                           "WindType = 2: the uniform wind file's time and speed columns drive "
                           "the hub-height wind; its direction, shear and gust columns are not "
                           "converted");
        } else {
            diags_.warning(Kind::NotSupported, iw->location("WindType"),
                           "WindType = " + std::to_string(*type) +
                               ": only steady (1), uniform (2), TurbSim (3) and HAWC (5) wind "
                               "are converted; give `--wind` (a speed, a step or a time "
                               "series)");
        }
    }

    void servodyn() {
        auto sd = module_file(deck_, "ServoFile", diags_);
        if (!sd) return;
        if (auto eff = sd->get_double("GenEff", diags_)) {
            op_.gen_efficiency = *eff;
            op_.gen_efficiency_from = file_line(*sd, "GenEff");
        }
        const auto pc = sd->get_int("PCMode", diags_);
        const auto vs = sd->get_int("VSContrl", diags_);
        if (vs && *vs == 1) {
            if (auto k = sd->get_double("VS_Rgn2K", diags_)) {
                op_.region2_k = *k * (30 / M_PI) * (30 / M_PI); // N m/rpm^2 -> N m s^2
                op_.region2_k_from = file_line(*sd, "VS_Rgn2K");
            }
            diags_.warning(Kind::NotSupported, sd->location("VSContrl"),
                           "VSContrl = 1: the region-2 law k w^2 (VS_Rgn2K) is converted; "
                           "ServoDyn's rated torque and slip region (VS_RtGnSp, VS_RtTq, "
                           "VS_SlPc) are not");
        } else if (vs && *vs != 5) {
            diags_.warning(Kind::NotSupported, sd->location("VSContrl"),
                           "VSContrl = " + std::to_string(*vs) +
                               ": the generator model is not converted; the generator torque "
                               "is the input gen_torque");
        }
        if (pc && *pc != 0 && *pc != 5)
            diags_.warning(Kind::NotSupported, sd->location("PCMode"),
                           "PCMode = " + std::to_string(*pc) +
                               ": only a Bladed-style controller (5) is converted");
        if ((pc && *pc == 5) || (vs && *vs == 5)) {
            const auto lib = sd->get_string("DLL_FileName", diags_);
            const auto input = sd->get_string("DLL_InFile", diags_);
            if (lib) op_.controller = resolve(*lib, *sd->file());
            if (input) op_.controller_input = resolve(*input, *sd->file());
            if (lib && !fs::exists(op_.controller))
                diags_.warning(Kind::Io, sd->location("DLL_FileName"),
                               "the controller library '" + *lib +
                                   "' does not exist (yet): build it, or give `sim --controller` "
                                   "another one");
        }
    }

    const openfast::OpenFastDeck& deck_;
    diag::Diagnostics& diags_;
    Operation op_;
};

} // namespace

std::optional<YawSpring> read_yaw_spring(const openfast::OpenFastDeck& deck,
                                         diag::Diagnostics& diags) {
    auto switch_of = [&](const std::string& name) {
        auto it = deck.modules.find(name);
        return it == deck.modules.end() ? std::string() : it->second.value;
    };
    if (!deck.fst || switch_of("CompServo") != "1") return std::nullopt;
    // With AeroDyn on, read_operation reads the same file and reports why it cannot.
    diag::Diagnostics quiet;
    const bool reported = !switch_of("CompAero").empty() && switch_of("CompAero") != "0";
    auto sd = module_file(deck, "ServoFile", reported ? quiet : diags);
    if (!sd) return std::nullopt;
    const auto mode = sd->get_int("YCMode", diags);
    const auto neutral = sd->get_double("YawNeut", diags);
    const auto stiffness = sd->get_double("YawSpr", diags);
    const auto damping = sd->get_double("YawDamp", diags);
    if (!mode || !neutral || !stiffness || !damping) return std::nullopt;
    bool ok = true;
    for (const auto& [key, value] : {std::pair{"YawSpr", *stiffness}, {"YawDamp", *damping}})
        if (value < 0) {
            diags.error(Kind::InvalidValue, sd->location(key),
                        std::string(key) + " must not be negative");
            ok = false;
        }
    if (*neutral <= -180 || *neutral > 180) {
        diags.error(Kind::InvalidValue, sd->location("YawNeut"),
                    "YawNeut must be in (-180, 180] degrees");
        ok = false;
    }
    if (!ok) return std::nullopt;
    if (*mode != 0)
        diags.warning(Kind::NotSupported, sd->location("YCMode"),
                      "YCMode = " + std::to_string(*mode) +
                          ": the yaw commands are not converted; the yaw spring and damper "
                          "(YawSpr, YawDamp) hold YawNeut, as ServoDyn's do before TYCOn and "
                          "under a controller that commands no yaw rate");
    if (const auto start = sd->get_double("TYawManS", diags);
        start && (!deck.tmax || *start < *deck.tmax))
        diags.warning(Kind::NotSupported, sd->location("TYawManS"),
                      "TYawManS = " + mbd_number(*start) +
                          ": the override yaw maneuver is not converted; the yaw spring and "
                          "damper hold YawNeut");
    YawSpring y;
    y.stiffness = *stiffness;
    y.damping = *damping;
    y.neutral_deg = *neutral;
    y.stiffness_from = file_line(*sd, "YawSpr");
    y.damping_from = file_line(*sd, "YawDamp");
    y.neutral_from = file_line(*sd, "YawNeut");
    return y;
}

std::optional<Operation> read_operation(const openfast::OpenFastDeck& deck,
                                        const std::string& cp_table, bool blade_elements,
                                        diag::Diagnostics& diags) {
    return OperationReader(deck, diags).read(cp_table, blade_elements);
}

} // namespace yamsc::openfast
