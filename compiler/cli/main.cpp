// yamsc: the command line. Parses arguments into the driver's option structs,
// runs the command, and maps errors to exit statuses: 0 success, 1 user error,
// 2 usage error, 70 internal error.
#include "diag/diagnostics.hpp"
#include "driver/bindings.hpp"
#include "driver/commands.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace {

using yamsc::diag::UsageError;

const char* usage_text = R"(usage:
  yamsc MODEL.mbd -o model.cpp [--header model.hpp] [--lang cpp|c|latex] [--namespace NS]
                  [--depfile FILE] [--dump=ast|model|module] [-v] [--real double|float]
                  [--jacobians auto|unrolled|tangent] [--sensitivities p1,p2,..]
  yamsc check MODEL.mbd [--json]
  yamsc eval MODEL.mbd [--q v,..] [--qd v,..] [--u name=v,..] [--set name=v,..] [--t T]
                       [--compiled] [--external lib.so|file.c|file.cpp] --json
  yamsc lin MODEL.mbd [--at name=v,..] [--u name=v,..] [--set name=v,..] [--json]
                      [--trim [--hold dof,..] [--adjust input,..]]
                      [--mbc3 [--azimuths N] [--azimuth dof]]
                      [--aero Cp_Ct_Cq.txt] [--wind V]
                      [--sweep NAME=FROM:STEP:TO [--schedule points.csv] [-o campbell.csv]
                                                 [--plot campbell.svg]]
                      [--format openfast-lin -o case.lin [--azimuths N [--azimuth dof]]]
  yamsc trim MODEL.mbd [--at name=v,..] [--u name=v,..] [--set name=v,..] [--hold dof,..]
                       [--adjust input,..] [--aero Cp_Ct_Cq.txt] [--wind V] [--json]
  yamsc sim MODEL.mbd --tmax T --dt DT [--ic name=v,..] [--u name=v,..] [--set name=v,..]
                      [--method rk4|abm4|cvode] [--rtol R] [--atol A] [-o out.csv]
                      [--dt-out DT_OUT] [-v]
                      [--channels all|openfast] [--compare ref.csv] [--plot out.svg]
                      [--plot-channels a,b,..] [--linear [--at name=v,..]]
                      [--aero Cp_Ct_Cq.txt] [--wind V|step:V0:V1:t=T|wind.csv]
                      [--controller libdiscon.so [--controller-input DISCON.IN]]
  yamsc batch CASES.csv [-o OUTDIR] [--threads N] [--shard k/N] [-q]
  yamsc batch merge OUTDIR... [-o summary.csv]
  yamsc from-openfast ELASTODYN.dat|DECK.fst [--dofs NAME=on|off,..] [--cp-table FILE] -o model.mbd
  yamsc rotor-table Cp_Ct_Cq.txt -o rotor_table.c [--prefix NAME]
  yamsc sid --elastodyn-tower FILE | --elastodyn-blade FILE --length L [--modes fa1,ss1,..]
            [--stations N] [-o body.sid]
  yamsc --version | --help
eval, lin, trim and sim take --external lib.so|file.c|file.cpp: the model's external
functions (a library exporting them, or a source compiled with the model; docs/cli.md).
eval, lin, trim and sim take --sid body=file.sid: the shape integrals of a flexible body
declared with `symbolic modes`, read from a SID file. Values accept `deg`: --set theta_t=5deg.
sim starts from the model's `initial` block (zeros without one); --ic overrides single values.
batch runs one sim per row of CASES.csv (columns id,model,tmax,dt and optionally method,rtol,
atol,set,ic,u,wind,aero,set:NAME,ic:NAME,u:NAME; docs/batch.md); a rerun runs only the cases
not finished yet.
Exit status: 0 ok, 1 error in the model or its inputs, 2 usage error (also an output that
names an input or another output: nothing is written), 70 internal error.
)";

/// Command-line options of one subcommand: `--name value`, `--name=value`, flags.
class Args {
public:
    Args(int argc, char** argv, int first, const std::set<std::string>& valued,
         const std::set<std::string>& flags) {
        for (int i = first; i < argc; ++i) {
            std::string a = argv[i];
            if (a.size() > 1 && a[0] == '-' &&
                !(a.size() > 1 && (std::isdigit(a[1]) || a[1] == '.'))) {
                std::string name = a, value;
                bool has_value = false;
                if (auto eq = a.find('='); eq != std::string::npos && a.rfind("--", 0) == 0) {
                    name = a.substr(0, eq);
                    value = a.substr(eq + 1);
                    has_value = true;
                }
                if (flags.count(name)) {
                    if (has_value) throw UsageError(name + " takes no value");
                    values_[name] = "1";
                } else if (valued.count(name)) {
                    if (!has_value) {
                        if (i + 1 >= argc) throw UsageError(name + " needs a value");
                        value = argv[++i];
                    }
                    if (values_.count(name)) throw UsageError(name + " is given twice");
                    values_[name] = value;
                } else {
                    throw UsageError("unknown option '" + name + "'");
                }
            } else {
                positional_.push_back(a);
            }
        }
    }
    bool has(const std::string& name) const { return values_.count(name) > 0; }
    std::string get(const std::string& name, const std::string& fallback = "") const {
        auto it = values_.find(name);
        return it == values_.end() ? fallback : it->second;
    }
    std::string model() const {
        if (positional_.size() != 1)
            throw UsageError(positional_.empty() ? "no model file given"
                                                 : "one model file expected, got " +
                                                       std::to_string(positional_.size()));
        return positional_[0];
    }
    const std::vector<std::string>& positionals() const { return positional_; }
    std::vector<yamsc::driver::Assignment> assignments(const std::string& name) const {
        return has(name) ? yamsc::driver::parse_assignments(get(name), name)
                         : std::vector<yamsc::driver::Assignment>{};
    }
    double number(const std::string& name, double fallback) const {
        return has(name) ? yamsc::driver::parse_value(get(name), name) : fallback;
    }

private:
    std::map<std::string, std::string> values_;
    std::vector<std::string> positional_;
};

/// The value of option `name` among `choices` (its fallback when not given);
/// anything else is a usage error that lists the choices.
template <class Enum>
Enum choice(const Args& a, const std::string& name, Enum fallback,
            const std::vector<std::pair<std::string, Enum>>& choices) {
    if (!a.has(name)) return fallback;
    const std::string given = a.get(name);
    std::string names;
    for (std::size_t i = 0; i < choices.size(); ++i) {
        if (choices[i].first == given) return choices[i].second;
        names += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choices[i].first;
    }
    throw UsageError(name + " must be " + names + ", not '" + given + "'");
}

/// The language of a compile: --lang, else the extension of -o.
yamsc::driver::Language language_of(const Args& a, const std::string& output) {
    using yamsc::driver::Language;
    if (a.has("--lang"))
        return choice(a, "--lang", Language::cpp,
                      {{"cpp", Language::cpp}, {"c", Language::c}, {"latex", Language::latex}});
    const auto slash = output.find_last_of('/');
    const auto dot = output.find_last_of('.');
    const std::string ext = dot == std::string::npos || (slash != std::string::npos && dot < slash)
                                ? ""
                                : output.substr(dot + 1);
    if (ext == "cpp" || ext == "cc" || ext == "cxx" || ext == "hpp") return Language::cpp;
    if (ext == "c" || ext == "h") return Language::c;
    if (ext == "tex") return Language::latex;
    throw UsageError("cannot tell the language from '" + output + "': give --lang cpp|c|latex");
}

/// "a,b,c" -> {"a", "b", "c"}; "" -> {}.
std::vector<std::string> comma_list(const std::string& text) {
    std::vector<std::string> items;
    for (std::size_t start = 0; !text.empty() && start <= text.size();) {
        std::size_t comma = text.find(',', start);
        if (comma == std::string::npos) comma = text.size();
        items.push_back(text.substr(start, comma - start));
        start = comma + 1;
    }
    return items;
}

int run(int argc, char** argv) {
    using namespace yamsc::driver;
    if (argc < 2) throw UsageError("no command given");
    std::string cmd = argv[1];
    if (cmd == "--help" || cmd == "-h") {
        std::cout << usage_text;
        return 0;
    }
    if (cmd == "--version") {
        std::cout << "yamsc " << YAMSC_VERSION << "\n";
        return 0;
    }
    if (cmd == "check") {
        Args a(argc, argv, 2, {}, {"--json"});
        return check({a.model(), a.has("--json")}, std::cout, std::cerr);
    }
    if (cmd == "eval") {
        Args a(argc, argv, 2, {"--q", "--qd", "--u", "--set", "--sid", "--t", "--external"},
               {"--json", "--compiled"});
        EvalOptions o;
        o.model = a.model();
        if (a.has("--q")) o.q = parse_list(a.get("--q"), "--q");
        if (a.has("--qd")) o.qd = parse_list(a.get("--qd"), "--qd");
        o.u = a.assignments("--u");
        o.set = a.assignments("--set");
        o.sid = a.get("--sid");
        o.t = a.number("--t", 0.0);
        o.external = a.get("--external");
        o.compiled = a.has("--compiled") || !o.external.empty();
        return o.compiled ? eval_compiled(o, std::cout, std::cerr) : eval(o, std::cout, std::cerr);
    }
    if (cmd == "lin") {
        Args a(argc, argv, 2,
               {"--at", "--u", "--set", "--sid", "--sweep", "-o", "--plot", "--hold", "--azimuths",
                "--azimuth", "--aero", "--wind", "--adjust", "--schedule", "--format",
                "--external"},
               {"--json", "--trim", "--mbc3"});
        LinOptions o;
        o.format = choice(a, "--format", LinFormat::table,
                          {{"table", LinFormat::table}, {"openfast-lin", LinFormat::openfast_lin}});
        const bool lin_files = o.format == LinFormat::openfast_lin;
        o.model = a.model();
        o.trim = a.has("--trim");
        o.mbc3 = a.has("--mbc3");
        o.hold = comma_list(a.get("--hold"));
        o.adjust = comma_list(a.get("--adjust"));
        if (!o.trim && !o.adjust.empty()) throw UsageError("--adjust needs --trim");
        o.azimuth = a.get("--azimuth");
        const double azimuths = a.number("--azimuths", o.azimuths);
        if (azimuths != std::floor(azimuths)) throw UsageError("--azimuths must be a whole number");
        o.azimuths = static_cast<int>(std::min(azimuths, 1e6));
        o.azimuths_given = a.has("--azimuths");
        if (!o.trim && !o.mbc3 && !o.azimuths_given && !o.hold.empty())
            throw UsageError("--hold needs --trim, --mbc3 or --azimuths");
        if (!o.mbc3 && !lin_files && (a.has("--azimuths") || a.has("--azimuth")))
            throw UsageError("--azimuths and --azimuth need --mbc3 or --format openfast-lin");
        if (o.azimuths < 1 || o.azimuths > 3600)
            throw UsageError("--azimuths must be between 1 and 3600");
        if (a.has("--sweep")) o.sweep = parse_sweep(a.get("--sweep"));
        o.output = a.get("-o");
        o.plot = a.get("--plot");
        if (!o.sweep && !lin_files && (!o.output.empty() || !o.plot.empty()))
            throw UsageError("lin writes files (-o, --plot) only for --sweep or --format");
        if (lin_files && o.output.empty())
            throw UsageError("--format openfast-lin needs -o FILE.lin");
        if (lin_files && (o.sweep || !o.plot.empty()))
            throw UsageError("--format openfast-lin does not take --sweep or --plot");
        o.at = a.assignments("--at");
        o.u = a.assignments("--u");
        o.set = a.assignments("--set");
        o.sid = a.get("--sid");
        o.external = a.get("--external");
        o.json = a.has("--json");
        o.aero = a.get("--aero");
        o.wind = a.get("--wind");
        if (o.sweep && o.json) throw UsageError("--sweep writes CSV, not --json");
        o.schedule = a.get("--schedule");
        if (!o.sweep && !o.schedule.empty()) throw UsageError("--schedule needs --sweep");
        if (o.sweep && !o.wind.empty() && o.sweep->name == "V_wind")
            throw UsageError("--sweep V_wind=.. sets the wind: drop --wind");
        return lin(o, std::cout, std::cerr);
    }
    if (cmd == "trim") {
        Args a(argc, argv, 2,
               {"--at", "--u", "--set", "--sid", "--hold", "--adjust", "--aero", "--wind",
                "--external"},
               {"--json"});
        TrimOptions o;
        o.model = a.model();
        o.at = a.assignments("--at");
        o.u = a.assignments("--u");
        o.set = a.assignments("--set");
        o.sid = a.get("--sid");
        o.hold = comma_list(a.get("--hold"));
        o.adjust = comma_list(a.get("--adjust"));
        o.aero = a.get("--aero");
        o.wind = a.get("--wind");
        o.external = a.get("--external");
        o.json = a.has("--json");
        return trim(o, std::cout, std::cerr);
    }
    if (cmd == "rotor-table") {
        Args a(argc, argv, 2, {"-o", "--prefix"}, {});
        RotorTableOptions o;
        o.table = a.model();
        o.output = a.get("-o");
        if (o.output.empty()) throw UsageError("rotor-table needs -o rotor_table.c");
        if (a.has("--prefix")) o.prefix = a.get("--prefix");
        return rotor_table(o, std::cout, std::cerr);
    }
    if (cmd == "sid") {
        Args a(
            argc, argv, 2,
            {"--elastodyn-tower", "--elastodyn-blade", "--length", "--modes", "--stations", "-o"},
            {});
        SidOptions o;
        o.tower = a.get("--elastodyn-tower");
        o.blade = a.get("--elastodyn-blade");
        o.length = a.number("--length", 0);
        o.stations = static_cast<int>(a.number("--stations", 50));
        o.output = a.get("-o");
        o.modes = comma_list(a.get("--modes"));
        return sid(o, std::cout, std::cerr);
    }
    if (cmd == "sim") {
        Args a(argc, argv, 2,
               {"--tmax",    "--dt",       "--dt-out",  "--ic",         "--u",
                "--set",     "--sid",      "--method",  "-o",           "--rtol",
                "--atol",    "--channels", "--compare", "--plot",       "--plot-channels",
                "--at",      "--aero",     "--wind",    "--controller", "--controller-input",
                "--external"},
               {"-v", "--linear"});
        SimOptions o;
        o.model = a.model();
        if (!a.has("--tmax") || !a.has("--dt")) throw UsageError("sim needs --tmax and --dt");
        o.tmax = a.number("--tmax", 0);
        o.dt = a.number("--dt", 0);
        if (!(o.tmax > 0) || !(o.dt > 0)) throw UsageError("--tmax and --dt must be positive");
        o.dt_out = a.number("--dt-out", 0);
        if (a.has("--dt-out")) {
            // As runtime::output_stride checks it (the CLI does not link the runtime).
            const double steps = o.dt_out / o.dt;
            if (!(o.dt_out > 0) || std::round(steps) < 1 ||
                std::fabs(steps - std::round(steps)) > 1e-9 * std::round(steps))
                throw UsageError("--dt-out must be a positive multiple of --dt");
        }
        o.ic = a.assignments("--ic");
        o.u = a.assignments("--u");
        o.set = a.assignments("--set");
        o.sid = a.get("--sid");
        o.external = a.get("--external");
        o.method = choice(
            a, "--method", SimMethod::rk4,
            {{"rk4", SimMethod::rk4}, {"abm4", SimMethod::abm4}, {"cvode", SimMethod::cvode}});
        o.rtol = a.number("--rtol", o.rtol);
        o.atol = a.number("--atol", o.atol);
        o.output = a.get("-o");
        o.verbose = a.has("-v");
        o.channels = choice(a, "--channels", Channels::all,
                            {{"all", Channels::all}, {"openfast", Channels::openfast}});
        o.compare = a.get("--compare");
        o.plot = a.get("--plot");
        o.plot_channels = comma_list(a.get("--plot-channels"));
        o.linear = a.has("--linear");
        o.at = a.assignments("--at");
        if (!o.at.empty() && !o.linear) throw UsageError("--at needs --linear");
        o.aero = a.get("--aero");
        o.wind = a.get("--wind");
        o.controller = a.get("--controller");
        o.controller_input = a.get("--controller-input");
        if (o.controller.empty() && !o.controller_input.empty())
            throw UsageError("--controller-input needs --controller");
        if (!o.controller.empty() && (o.linear || o.method == SimMethod::cvode))
            throw UsageError("--controller runs with RK4 or ABM4 on the nonlinear model");
        return sim(o, std::cout, std::cerr);
    }
    if (cmd == "batch" && argc > 2 && std::string(argv[2]) == "merge") {
        Args a(argc, argv, 3, {"-o"}, {});
        BatchMergeOptions o;
        o.dirs = a.positionals();
        o.output = a.get("-o");
        return batch_merge(o, std::cout, std::cerr);
    }
    if (cmd == "batch") {
        Args a(argc, argv, 2, {"-o", "--threads", "--shard"}, {"-q"});
        BatchOptions o;
        o.manifest = a.model();
        o.output_dir = a.get("-o");
        const double threads = a.number("--threads", 0);
        if (threads != std::floor(threads) || threads < 1 || threads > 4096)
            if (a.has("--threads")) throw UsageError("--threads must be a whole number >= 1");
        o.threads = static_cast<int>(threads);
        if (a.has("--shard")) {
            const std::string s = a.get("--shard");
            const auto slash = s.find('/');
            std::size_t k_end = 0, n_end = 0;
            try {
                if (slash == std::string::npos) throw std::invalid_argument(s);
                o.shard = std::stoi(s.substr(0, slash), &k_end);
                o.shards = std::stoi(s.substr(slash + 1), &n_end);
            } catch (const std::exception&) {
                k_end = 0;
            }
            if (k_end != slash || slash + 1 + n_end != s.size() || o.shards < 1 || o.shard < 1 ||
                o.shard > o.shards)
                throw UsageError("--shard takes k/N with 1 <= k <= N (e.g. 2/8), not '" + s + "'");
        }
        o.quiet = a.has("-q");
        o.stop_on_signal = true;
        return batch(o, std::cout, std::cerr);
    }
    if (cmd == "from-openfast") {
        Args a(argc, argv, 2, {"--dofs", "-o", "--cp-table"}, {});
        FromOpenFastOptions o;
        o.deck = a.model();
        o.output = a.get("-o");
        o.cp_table = a.get("--cp-table");
        if (o.output.empty()) throw UsageError("from-openfast needs -o model.mbd");
        for (const std::string& item : comma_list(a.get("--dofs"))) {
            const auto eq = item.find('=');
            const std::string value = eq == std::string::npos ? "" : item.substr(eq + 1);
            if (eq == std::string::npos || (value != "on" && value != "off"))
                throw UsageError("--dofs takes NAME=on|off items (e.g. GenDOF=off), not '" + item +
                                 "'");
            o.dofs.emplace_back(item.substr(0, eq), value == "on");
        }
        return from_openfast(o, std::cout, std::cerr);
    }
    Args a(argc, argv, 1,
           {"-o", "--header", "--lang", "--namespace", "--dump", "--depfile", "--real",
            "--jacobians", "--sensitivities"},
           {"-v"});
    CompileOptions o;
    o.model = a.model();
    o.output = a.get("-o");
    o.header = a.get("--header");
    o.name_space = a.get("--namespace");
    o.dump = choice(a, "--dump", Dump::none,
                    {{"ast", Dump::ast}, {"model", Dump::model}, {"module", Dump::module}});
    if (o.output.empty() && o.dump == Dump::none) throw UsageError("no output given (-o FILE)");
    if (o.dump == Dump::none) o.lang = language_of(a, o.output);
    o.depfile = a.get("--depfile");
    if (a.has("--real"))
        o.real = choice(a, "--real", Real::double_precision,
                        {{"double", Real::double_precision}, {"float", Real::single_precision}});
    if (o.real == Real::single_precision && o.lang != Language::c)
        throw UsageError("--real float applies to --lang c only");
    if (a.has("--jacobians"))
        o.jacobians = choice(a, "--jacobians", Derivatives::automatic,
                             {{"auto", Derivatives::automatic},
                              {"unrolled", Derivatives::unrolled},
                              {"tangent", Derivatives::tangent}});
    o.sensitivities = comma_list(a.get("--sensitivities"));
    if (o.jacobians == Derivatives::tangent && !o.sensitivities.empty())
        throw UsageError("--sensitivities needs --jacobians unrolled (or auto)");
    o.verbose = a.has("-v");
    return compile(o, std::cout, std::cerr);
}

} // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const UsageError& e) {
        std::cerr << "yamsc: usage error: " << e.what() << "\n" << usage_text;
        return 2;
    } catch (const yamsc::diag::UserError& e) {
        std::cerr << "yamsc: error: " << e.what() << "\n";
        return 1;
    } catch (const yamsc::diag::InternalError& e) {
        std::cerr << "yamsc: internal error: " << e.what()
                  << "\nThis is a bug in yamsc, not in your model: please report it.\n";
        return 70;
    } catch (const std::exception& e) {
        std::cerr << "yamsc: error: " << e.what() << "\n";
        return 1;
    }
}
