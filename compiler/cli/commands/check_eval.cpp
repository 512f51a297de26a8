// `yamsc check` and `yamsc eval`: a model validated, its equations evaluated.
#include "analysis/commands.hpp"
#include "cli/commands/commands.hpp"

namespace yamsc::cli {

namespace {

using driver::CheckOptions;
using driver::EvalOptions;

CheckOptions parse_check(const Args& a) {
    return {a.model(), a.has("--json")};
}

EvalOptions parse_eval(const Args& a) {
    EvalOptions o;
    o.model = a.model();
    if (a.has("--q")) o.q = driver::parse_list(a.get("--q"), "--q");
    if (a.has("--qd")) o.qd = driver::parse_list(a.get("--qd"), "--qd");
    o.u = a.assignments("--u");
    o.set = a.assignments("--set");
    o.sid = a.get("--sid");
    o.t = a.number("--t", 0.0);
    o.external = a.get("--external");
    o.compiled = a.has("--compiled") || !o.external.empty();
    return o;
}

/// The interpreted equations (driver), or the compiled code (analysis).
int run_eval(const EvalOptions& o, std::ostream& out, std::ostream& err) {
    return o.compiled ? analysis::eval_compiled(o, out, err) : driver::eval(o, out, err);
}

} // namespace

Command check_command() {
    return make_command(
        "check", "parse and validate a model; list what it declares",
        "yamsc check MODEL.mbd [--json]",
        R"(  --json              JSON on stdout: DOFs, inputs, parameters, bodies and
                      their joints, outputs and external functions
)",
        {{}, {"--json"}}, parse_check, driver::check);
}

Command eval_command() {
    return make_command(
        "eval", "M, F and the outputs of a model at one state",
        R"(yamsc eval MODEL.mbd [--q v,..] [--qd v,..] [--u name=v,..] [--set name=v,..] [--t T]
                     [--compiled] [--external lib.so|file.c|file.cpp]
                     [--sid body=file.sid,..] --json)",
        R"(  --q v,..            the DOFs (default zeros)
  --qd v,..           their rates (default zeros)
  --u name=v,..       inputs
  --set name=v,..     parameter values (accept `deg`: --set theta=5deg)
  --sid body=file.sid the shape integrals of a flexible body with `symbolic modes`
  --t T               the time
  --compiled          from the model's compiled code instead of the interpreted equations
  --external LIB      the model's external functions (implies --compiled)
  --json              JSON on stdout: {"nq","dofs","M","F","outputs","y"}
)",
        {{"--q", "--qd", "--u", "--set", "--sid", "--t", "--external"}, {"--json", "--compiled"}},
        parse_eval, run_eval);
}

} // namespace yamsc::cli
