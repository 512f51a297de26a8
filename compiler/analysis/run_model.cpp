// `yamsc sim` and `yamsc lin` (`trim`: trim_command.cpp): the model's generated code, compiled on
// the fly, driven by the runtime.
#include "analysis/campbell.hpp"
#include "analysis/channels.hpp"
#include "analysis/commands.hpp"
#include "analysis/compare.hpp"
#include "analysis/constrained_model.hpp"
#include "analysis/controller_loop.hpp"
#include "analysis/linear_report.hpp"
#include "analysis/load_blocks.hpp"
#include "analysis/loaded_model.hpp"
#include "analysis/openfast_lin_model.hpp"
#include "analysis/rao_report.hpp"
#include "analysis/rotor_campbell.hpp"
#include "analysis/rotor_modes.hpp"
#include "analysis/scene_files.hpp"
#include "analysis/scene_surfaces.hpp"
#include "analysis/sim_case.hpp"
#include "analysis/svg_plot.hpp"
#include "analysis/sweep_point.hpp"
#include "analysis/trim_point.hpp"
#include "analysis/wind_input.hpp"
#include "driver/bindings.hpp"
#include "driver/json.hpp"
#include "driver/outputs.hpp"
#include "driver/pipeline.hpp"

#include <yamsc/atomic_file.hpp>
#include <yamsc/csv.hpp>
#include <yamsc/linear_view.hpp>
#include <yamsc/modal.hpp>
#include <yamsc/second_order.hpp>
#include <yamsc/simulation.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ostream>

namespace yamsc::analysis {

using diag::UsageError;
using driver::Channels;
using driver::check_outputs;
using driver::LinFormat;
using driver::LinOptions;
using driver::NamedFile;
using driver::sid_files_of;
using driver::SimOptions;
using driver::Sweep;
namespace json = driver::json;

namespace {

double max_abs(const std::vector<double>& v) {
    double m = 0;
    for (double x : v) m = std::max(m, std::fabs(x));
    return m;
}

/// `lin --sweep NAME=FROM:STEP:TO`: the modes at the operating point for each
/// value of a parameter (the point follows the parameter when it uses it).
int campbell(const Loaded& l, const LinOptions& o, std::ostream& out) {
    if (o.mbc3) return rotor_campbell(l, o, out);
    const Sweep& sweep = *o.sweep;
    const SweepPoints points(l, o);
    std::vector<CampbellRow> rows;
    for (double value : sweep.values) {
        SweepPoint p = points.at(value);
        p.q.insert(p.q.end(), p.qd.begin(), p.qd.end());
        const std::vector<double> A = runtime::state_matrix_from_view(p.view, p.q, p.u, 0.0);
        rows.push_back({value, runtime::modal_analysis(A, p.view.nq)});
    }
    const std::string csv = campbell_csv(sweep.name, rows);
    if (o.output.empty()) {
        out << csv;
    } else {
        runtime::write_file_atomically(o.output, csv);
        out << "wrote " << rows.size() << " rows to " << o.output << "\n";
    }
    if (!o.plot.empty()) {
        const std::string title = l.front.model->name + ": modes against " + sweep.name;
        runtime::write_file_atomically(o.plot, campbell_svg(title, sweep.name, rows));
        out << "wrote " << o.plot << "\n";
    }
    return 0;
}

/// The channels to plot: --plot-channels, else those compared, else every column.
std::vector<PlotPanel> plot_panels(const Table& sim, const Table* reference,
                                   const std::optional<Comparison>& comparison,
                                   const SimOptions& o) {
    std::vector<std::string> names = o.plot_channels;
    if (names.empty() && comparison)
        for (const ChannelScore& c : comparison->channels) names.push_back(c.matched);
    const Table chosen = select_columns(sim, names);
    const std::string label = o.linear ? "yamsc (linear)" : "yamsc";
    std::vector<PlotPanel> panels;
    for (std::size_t j = 1; j < chosen.columns.size(); ++j) {
        PlotPanel p;
        p.y_label = chosen.columns[j];
        p.series.push_back({label, chosen.data.front(), chosen.data[j], false});
        if (reference) {
            int r = reference->find(chosen.columns[j]);
            for (std::size_t k = 1; r < 0 && k < reference->columns.size(); ++k)
                if (base_name(reference->columns[k]) == base_name(chosen.columns[j]))
                    r = static_cast<int>(k);
            if (r > 0) {
                std::string name = o.compare.substr(o.compare.find_last_of('/') + 1);
                p.series.push_back({"reference (" + name + ")", reference->data.front(),
                                    reference->data[static_cast<std::size_t>(r)], true});
            }
        }
        panels.push_back(std::move(p));
    }
    return panels;
}

/// --wind names a file (not a speed, not step:..).
bool wind_file(const std::string& spec) {
    char* end = nullptr;
    std::strtod(spec.c_str(), &end);
    return !spec.empty() && *end != '\0' && spec.rfind("step:", 0) != 0;
}

} // namespace

int sim(const SimOptions& o, std::ostream& out, std::ostream& err) {
    if (!o.at.empty() && !o.linear) throw UsageError("--at needs --linear");
    if (o.linear && any_blocks(block_options(o)))
        throw UsageError("--linear does not take load blocks (--aero, --mooring, --hydro: use "
                         "yamsc lin with them)");
    std::vector<NamedFile> outputs{{"-o", o.output}, {"--plot", o.plot}};
    // The controller writes its own files from the run's root (ROSCO: a log).
    if (!o.controller.empty())
        outputs.push_back({"the controller's log", output_root_of(o.output) + ".RO.dbg"});
    std::vector<NamedFile> inputs = sid_files_of(o.sid);
    inputs.push_back({"the model", o.model});
    inputs.push_back({"the --compare table", o.compare});
    for (const NamedFile& f : block_files(block_options(o))) inputs.push_back(f);
    inputs.push_back({"--controller", o.controller});
    inputs.push_back({"--controller-input", o.controller_input});
    inputs.push_back({"--external", o.external});
    if (wind_file(o.wind)) inputs.push_back({"--wind", o.wind});
    check_outputs(inputs, outputs);
    if (!o.vtk.empty()) check_scene_folder(o.vtk);
    // A bad reference fails before anything is simulated or written.
    std::optional<Table> reference;
    if (!o.compare.empty()) reference = read_table(o.compare);
    auto loaded = load(o.model, o.set, o.sid, o.verbose, err, outputs, sim_routines(o), o.external,
                       o.vtk.empty() ? ModelChannels::declared : ModelChannels::scene);
    if (!loaded) return 1;
    SimRun run = simulate_case(*loaded, o, out, err);
    // The scene's outputs leave the run once drawn: every table sim writes is
    // the one it writes without --vtk.
    std::optional<Scene> scene;
    runtime::SimulationResult with_scene;
    if (!o.vtk.empty() && run.result.rows() > 0) {
        scene.emplace(*loaded->front.model, run.result,
                      scene_surfaces(*loaded->front.model, o.aero));
        with_scene = std::move(run.result);
        run.result = without_outputs(with_scene, scene->scene_outputs());
    }
    const runtime::SimulationResult& result = run.result;
    // That the model has OpenFAST's channels is checked before anything is written.
    if (o.channels == Channels::openfast) openfast_columns(result, 1 + run.view.nx());
    // The table (a copy of the columns) only for what reads it.
    const bool need_table = reference || !o.plot.empty();
    const Table table = need_table ? sim_table(run, o.channels) : Table{};
    if (scene) {
        // The run's files are named by the model; checked against the inputs
        // and sim's other outputs before anything is written.
        std::vector<NamedFile> others = inputs;
        others.insert(others.end(), outputs.begin(), outputs.end());
        write_scene_folder(o.vtk, loaded->front.model->name, *scene, with_scene, run, o.channels,
                           others);
    }
    if (!o.output.empty()) write_sim_csv(run, o.channels, o.output);
    out << runtime::format_summary(result);
    if (!o.output.empty()) out << "wrote " << result.rows() << " rows to " << o.output << "\n";
    if (scene)
        out << "wrote the scene of " << result.rows() << " rows to " << o.vtk << " ("
            << vtk::pvd_name(loaded->front.model->name) << ")\n";
    std::optional<Comparison> comparison;
    if (reference) {
        comparison = compare_tables(table, *reference);
        out << format_comparison(*comparison, o.compare);
    }
    if (!o.plot.empty()) {
        PlotOptions plot;
        plot.title = loaded->front.model->name + (o.linear ? " (linear)" : "");
        runtime::write_file_atomically(
            o.plot,
            svg_plot(plot_panels(table, reference ? &*reference : nullptr, comparison, o), plot));
        out << "wrote " << o.plot << "\n";
    }
    return 0;
}

int lin(const LinOptions& o, std::ostream& out, std::ostream& err) {
    const bool lin_files = o.format == LinFormat::openfast_lin;
    std::vector<NamedFile> outputs{{"-o", o.output}, {"--plot", o.plot}, {"--rao", o.rao}};
    if (lin_files) {
        // Every .lin file is an output: none may be an input or another output.
        outputs.clear();
        for (const std::string& path :
             lin_file_paths(o.output, lin_files_per_azimuth(o) ? o.azimuths : 0))
            outputs.push_back({"-o", path});
    }
    std::vector<NamedFile> inputs = sid_files_of(o.sid);
    inputs.push_back({"the model", o.model});
    inputs.push_back({"--external", o.external});
    for (const NamedFile& f : block_files(block_options(o))) inputs.push_back(f);
    check_outputs(inputs, outputs);
    // The second-order model (M, F and its Jacobians) and, for the modes, A.
    codegen::RoutineSet routines = linear_model_routines();
    if (lin_files) routines.insert(codegen::RoutineId::outputs);
    add_block_routines(block_options(o), false, routines);
    auto loaded = load(o.model, o.set, o.sid, false, err, outputs, routines, o.external);
    if (!loaded || refuse_without_dofs(*loaded, "lin", "linearize", err)) return 1;
    if (loaded->view.nc > 0) refuse_constrained_options(o);
    if (o.sweep) return campbell(*loaded, o, out);
    // The linear model's blocks differentiate as a linearization does (a
    // frozen wake); the trim's Newton steps take the quasi-steady loads'.
    const runtime::ModelView v = with_load_blocks(*loaded, linear_block_options(o));
    const int nq = v.nq, nu = v.nu;
    std::vector<double> q, qd, u;
    operating_point(*loaded, loaded->params, o.at, o.u, q, qd, u);
    if (!o.wind.empty()) set_wind_at_start(*loaded, v, u, o.wind);
    if (v.nc > 0) return constrained_lin(v, o, q, qd, u, out, err);
    if (o.trim) {
        const runtime::TrimResult r = trim_point(
            any_blocks(block_options(o)) ? with_load_blocks(*loaded, trim_block_options(o)) : v, q,
            qd, u, o.hold, o.adjust, trim_settings(*loaded, block_options(o)));
        q = r.q;
        u = r.u;
    }
    if (!o.rao.empty()) return rao_report(*loaded, o, q, u, out, err);
    if (lin_files) write_openfast_lin(*loaded, v, o, q, qd, u, out, o.json);
    if (o.mbc3) {
        const RotorModesRequest r = rotor_request(v, q, qd, u, o.azimuth, o.hold, o.azimuths);
        const std::vector<RotorMode> modes = rotor_modes(v, r);
        out << (o.json ? rotor_modes_json(v, r, modes) : format_rotor_modes(v, r, modes));
        return 0;
    }
    const double t = 0.0;

    const runtime::SecondOrderModel lm = runtime::second_order_model(v, q, qd, u, t);
    const std::vector<runtime::Mode>& modes = lm.modes;
    const double residual = lm.equilibrium_residual;

    if (o.json) {
        out << "{\"dofs\":" << json::strings(v.dof_names)
            << ",\"inputs\":" << json::strings(v.input_names)
            << ",\"M0\":" << json::matrix(matrix_rows(lm.M0, nq, nq))
            << ",\"C0\":" << json::matrix(matrix_rows(lm.C0, nq, nq))
            << ",\"K0\":" << json::matrix(matrix_rows(lm.K0, nq, nq))
            << ",\"Q0\":" << json::matrix(matrix_rows(lm.Q0, nq, nu))
            << ",\"A\":" << json::matrix(matrix_rows(lm.A, 2 * nq, 2 * nq))
            << ",\"B\":" << json::matrix(matrix_rows(lm.B, 2 * nq, nu))
            << ",\"q0\":" << json::array(q) << ",\"qd0\":" << json::array(qd)
            << ",\"u0\":" << json::array(u) << ",\"residual\":" << json::array(lm.F0)
            << ",\"equilibrium_residual\":" << json::number(residual)
            << ",\"modes\":" << modes_json(modes) << "}\n";
        return 0;
    }
    if (residual > 1e-9)
        err << "yamsc: warning: the operating point is not an equilibrium (max |q''| = " << residual
            << ", max |F(q0, q0', u0)| = " << max_abs(lm.F0)
            << "); the linear model is about a moving point\n";
    out << format_mode_table(v.dof_names, modes);
    return 0;
}

} // namespace yamsc::analysis
