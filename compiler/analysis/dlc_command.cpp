#include "analysis/batch_files.hpp"
#include "analysis/dlc.hpp"
#include "analysis/dlc_files.hpp"
#include "diag/errors.hpp"

#include <yamsc/atomic_file.hpp>

#include <cstdio>
#include <filesystem>
#include <ostream>
#include <set>
#include <unistd.h>

namespace yamsc::analysis {

namespace {

namespace fs = std::filesystem;

/// `file` relative to `folder` (both made absolute), so that the folder can be
/// moved with the files beside it; "" stays "".
std::string relative_to(const std::string& folder, const std::string& file) {
    if (file.empty()) return "";
    if (::access(file.c_str(), R_OK) != 0) throw diag::UserError("cannot read '" + file + "'");
    return fs::weakly_canonical(fs::absolute(file))
        .lexically_relative(fs::weakly_canonical(fs::absolute(folder)))
        .generic_string();
}

/// Writes `text` to `path` unless the file holds it already: true when written.
bool write_if_changed(const std::string& path, const std::string& text) {
    if (::access(path.c_str(), R_OK) == 0 && read_all(path) == text) return false;
    runtime::write_file_atomically(path, text);
    return true;
}

} // namespace

int dlc(const DlcOptions& o, std::ostream& out, std::ostream& err) {
    if (o.output_dir.empty()) throw diag::UsageError("dlc needs -o FOLDER");
    if (!o.controller_input.empty() && o.controller.empty())
        throw diag::UsageError("--controller-input needs --controller");
    const DlcTable t = dlc_table(o);
    make_dirs(o.output_dir + "/wind");
    DlcPaths paths;
    paths.model = relative_to(o.output_dir, o.model);
    paths.parked_model =
        o.parked_model.empty() ? paths.model : relative_to(o.output_dir, o.parked_model);
    paths.controller = relative_to(o.output_dir, o.controller);
    paths.controller_input = relative_to(o.output_dir, o.controller_input);
    paths.aero = relative_to(o.output_dir, o.aero);
    // No file written may replace an input.
    std::set<std::string> inputs;
    for (const std::string& f : {o.model, o.parked_model, o.controller, o.controller_input, o.aero})
        if (!f.empty()) inputs.insert(real_path(f));
    auto output = [&](const std::string& path) {
        if (inputs.count(real_path(path)))
            throw diag::UsageError("dlc: " + path + " would replace an input");
        return path;
    };

    // A field whose input changed is removed before the input is written: a
    // run stopped in between leaves no field that another input made.
    std::vector<WindFile> to_make;
    for (const DlcWind& w : t.winds) {
        const std::string stem = o.output_dir + "/wind/" + w.name;
        const std::string text = turbsim_input_text(o, w);
        const bool changed =
            ::access((stem + ".inp").c_str(), R_OK) != 0 || read_all(stem + ".inp") != text;
        if (changed) {
            std::remove(output(stem + ".bts").c_str());
            runtime::write_file_atomically(output(stem + ".inp"), text);
        }
        if (o.write_bts && ::access((stem + ".bts").c_str(), R_OK) != 0)
            to_make.push_back({stem + ".inp", output(stem + ".bts")});
    }
    generate_winds(to_make, o.threads, err);
    const std::size_t generated = to_make.size();
    std::set<std::string> inflows;
    for (const DlcCase& c : t.cases)
        if (inflows.insert(c.inflow).second)
            write_if_changed(output(o.output_dir + "/wind/" + c.inflow + ".dat"),
                             inflowwind_text(t.winds[c.wind], c.yaw, o.hub_height,
                                             t.winds[c.wind].name + ".bts"));
    runtime::write_file_atomically(output(o.output_dir + "/cases.csv"), manifest_text(o, t, paths));
    runtime::write_file_atomically(output(o.output_dir + "/table.csv"), table_text(o, t));

    out << "dlc: " << t.cases.size() << " cases of " << t.winds.size() << " winds (class "
        << class_name(o) << "); wrote " << o.output_dir << "/cases.csv, table.csv, wind/";
    if (o.write_bts)
        out << " (" << generated << " .bts generated, " << t.winds.size() - generated
            << " unchanged)\n";
    else
        out << " (TurbSim inputs only: yamsc turbulence " << o.output_dir << "/wind/NAME.inp -o "
            << o.output_dir << "/wind/NAME.bts for each)\n";
    out << "run: yamsc batch " << o.output_dir << "/cases.csv; reduce: yamsc loads --batch "
        << o.output_dir << "/cases.out --speeds " << o.output_dir << "/table.csv --from "
        << o.transient << "\n";
    return 0;
}

} // namespace yamsc::analysis
