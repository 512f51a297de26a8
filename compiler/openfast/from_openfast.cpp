// `yamsc from-openfast`: a model from an OpenFAST ElastoDyn deck (docs/openfast.md).
#include "openfast/from_openfast.hpp"
#include "data/file_source.hpp"
#include "driver/bindings.hpp"
#include "driver/outputs.hpp"
#include "model/names.hpp"
#include "openfast/deck.hpp"
#include "openfast/model.hpp"
#include "openfast/operation.hpp"
#include "openfast/rotor.hpp"
#include "parse/parser.hpp"

#include <yamsc/atomic_file.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <ostream>

namespace yamsc::openfast {

using diag::UsageError;
using driver::check_outputs;
using driver::data_files_of;
using driver::FromOpenFastOptions;
using driver::NamedFile;

namespace fs = std::filesystem;

namespace {

/// The model's name from the output file: `land_3dof.mbd` -> `land_3dof`.
std::string model_name(const std::string& output) {
    std::string name;
    for (char c : fs::path(output).stem().string())
        name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0]))) name = "turbine_" + name;
    while (name.size() > 1 && name[0] == '_') name.erase(0, 1);
    if (!model::reserved_reason(name).empty()) name = "turbine_" + name;
    return name;
}

/// `path` as the model names it: relative to the model's folder when both share their
/// top folder (a project), else absolute.
std::string path_from(const fs::path& folder, const std::string& path) {
    const fs::path absolute = fs::absolute(path).lexically_normal();
    const fs::path relative = absolute.lexically_relative(folder);
    auto top = [](const fs::path& p) {
        auto it = p.begin();
        if (it != p.end() && p.has_root_directory()) ++it;
        return it == p.end() ? fs::path() : *it;
    };
    if (relative.empty() || top(absolute) != top(folder)) return absolute.generic_string();
    return relative.generic_string();
}

} // namespace

int from_openfast(const FromOpenFastOptions& o, std::ostream& out, std::ostream& err) {
    const std::vector<NamedFile> output{{"-o", o.output}};
    check_outputs({{"the deck", o.deck}}, output);
    diag::Diagnostics diags;
    auto deck = openfast::read_openfast_deck(o.deck, diags);
    if (!deck) {
        err << diags.render();
        return 1;
    }
    std::vector<NamedFile> deck_files{{"the tower file of the deck", deck->tower_file}};
    if (deck->fst) deck_files.push_back({"the deck's .fst file", deck->fst->path()});
    if (deck->ed) deck_files.push_back({"the deck's ElastoDyn file", deck->ed->path()});
    for (const std::string& blade : deck->blade_files)
        deck_files.push_back({"a blade file of the deck", blade});
    check_outputs(deck_files, output);
    const fs::path folder = fs::absolute(o.output).lexically_normal().parent_path();
    OpenFastModelInput in;
    in.deck = &*deck;
    in.dofs = deck->dofs;
    in.source = o.deck;
    std::string switched; // the --dofs given, as the model's comment quotes them
    for (const auto& [name, enabled] : o.dofs) {
        std::string flag;
        for (const std::string& f : openfast::elastodyn_dof_flags())
            if (f.size() == name.size() &&
                std::equal(f.begin(), f.end(), name.begin(), [](char a, char b) {
                    return std::tolower(static_cast<unsigned char>(a)) ==
                           std::tolower(static_cast<unsigned char>(b));
                }))
                flag = f;
        if (flag.empty())
            throw UsageError("--dofs: unknown ElastoDyn DOF '" + name + "'" +
                             diag::did_you_mean(name, openfast::elastodyn_dof_flags()));
        if (flag == "TeetDOF") {
            if (enabled)
                diags.warning(diag::Kind::NotSupported, {},
                              "--dofs TeetDOF=on: the teeter DOF is not converted");
            continue;
        }
        in.dofs[flag] = enabled;
        switched += (switched.empty() ? " --dofs " : ",") + flag + "=" + (enabled ? "on" : "off");
    }
    in.source += switched + " -o " + fs::path(o.output).filename().string();
    in.name = model_name(o.output);
    in.tower_path = path_from(folder, deck->tower_file);
    for (const std::string& b : deck->blade_files) in.blade_paths.push_back(path_from(folder, b));
    const bool blades_rigid = !openfast::flexible_blades(in.dofs);
    const bool tower_rigid = !openfast::flexible_tower(in.dofs);
    // Every DOF off (the motion all prescribed): a body per blade, whose root loads are
    // reactions. With DOFs the rigid rotor stays one lumped body: four bodies on constant
    // joints double the generated code, as the derivation sums each body's terms.
    const bool prescribed = std::none_of(in.dofs.begin(), in.dofs.end(), [](const auto& flag) {
        return flag.second && flag.first != "TeetDOF";
    });
    if (blades_rigid && prescribed) {
        for (int k = 1; k <= deck->blades; ++k)
            if (auto blade = rigid_blade(*deck, k, diags)) in.blades.push_back(*blade);
    } else if (blades_rigid) {
        in.rotor = rigid_rotor(*deck, diags);
    } else if (auto tips = blade_tip_shapes(*deck, diags))
        in.blade_tips = *tips;
    if (tower_rigid) in.tower = rigid_tower(*deck, diags);
    // The blade elements need the blades as bodies: a rotor without blade DOFs but with
    // other DOFs is one rigid body, whose aerodynamics is the table's.
    in.operation = read_operation(*deck, o.cp_table,
                                  o.aero == driver::RotorAero::blade_elements &&
                                      (!blades_rigid || !in.blades.empty()),
                                  diags);
    if (auto yaw = in.dofs.find("YawDOF"); yaw != in.dofs.end() && yaw->second)
        in.yaw_spring = read_yaw_spring(*deck, diags);
    in.output_file = fs::path(o.output).filename().string();
    if (in.operation) {
        // The run's files as the model's folder sees them; none may be the output.
        Operation& op = *in.operation;
        std::vector<NamedFile> run_files;
        for (auto [path, what] : {std::pair{&op.table, "the Cp/Ct/Cq table"},
                                  {&op.aerodyn, "the AeroDyn file"},
                                  {&op.controller, "the controller library"},
                                  {&op.controller_input, "the controller input"},
                                  {&op.wind, "the wind file"}}) {
            if (path->empty() || (path == &op.wind && op.wind_speed)) continue;
            run_files.push_back({what, *path});
            *path = path_from(folder, *path);
        }
        check_outputs(run_files, output);
        if (op.wind_speed) op.wind = mbd_number(*op.wind_speed);
    }
    if (diags.has_errors()) {
        err << diags.render();
        return 1;
    }
    const std::string text = openfast_model_text(in, diags);

    // The model must check where it will live (its data paths are relative to it).
    diag::Diagnostics check;
    auto source = std::make_shared<const diag::SourceFile>(o.output, text);
    auto ast = parse::parse_model(source, check);
    std::optional<model::Model> m;
    if (ast && !check.has_errors()) m = data::check_model(*ast, check);
    err << diags.render();
    if (!m || check.has_errors()) {
        err << check.render()
            << "yamsc: error: the model written from the deck does not check (above); nothing "
               "written\n";
        return 1;
    }
    check_outputs(data_files_of(*m), output);
    runtime::write_file_atomically(o.output, text);
    out << "wrote " << o.output << ": " << m->dofs.size() << " DOFs (";
    for (std::size_t i = 0; i < m->dofs.size(); ++i) out << (i ? ", " : "") << m->dofs[i].name;
    out << "), " << m->bodies.size() << " bodies, " << m->inputs.size() << " inputs, "
        << m->outputs.size() << " OpenFAST channels\n";
    int warnings = 0;
    for (const auto& d : diags.all()) warnings += d.severity == diag::Severity::warning;
    if (warnings) out << warnings << " warning(s) about entries not converted (on stderr)\n";
    return 0;
}

} // namespace yamsc::openfast
