// `yamsc [compile] MODEL.mbd -o model.cpp`: a model compiled to C++, C or LaTeX.
#include "cli/commands/commands.hpp"
#include "driver/commands.hpp"
#include "driver/targets.hpp"

namespace yamsc::cli {

namespace {

using driver::CompileOptions;
using driver::Derivatives;
using driver::Dump;
using driver::Language;
using driver::Real;

/// The language of a compile: --lang, else the extension of -o.
Language language_of(const Args& a, const std::string& output) {
    std::vector<std::pair<std::string, Language>> languages;
    for (const driver::Target* t : driver::targets()) languages.emplace_back(t->name, t->language);
    if (a.has("--lang")) return choice(a, "--lang", Language::cpp, languages);
    const auto slash = output.find_last_of('/');
    const auto dot = output.find_last_of('.');
    const std::string ext = dot == std::string::npos || (slash != std::string::npos && dot < slash)
                                ? ""
                                : output.substr(dot + 1);
    if (const driver::Target* t = driver::target_for_extension(ext)) return t->language;
    throw UsageError("cannot tell the language from '" + output + "': give --lang " +
                     driver::target_names("|"));
}

CompileOptions parse_compile(const Args& a) {
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
    if (o.real == Real::single_precision && !driver::target(o.lang).single_precision)
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
    return o;
}

} // namespace

Command compile_command() {
    return make_command(
        "compile", "compile a model to C++, C or LaTeX (the default command)",
        R"(yamsc [compile] MODEL.mbd -o model.cpp [--header model.hpp] [--lang cpp|c|latex]
                [--namespace NS] [--depfile FILE] [--dump=ast|model|module] [-v]
                [--real double|float] [--jacobians auto|unrolled|tangent]
                [--sensitivities p1,p2,..])",
        R"(  -o FILE             the generated source (required unless --dump)
  --header FILE       its header (C++ and C)
  --lang L            cpp, c or latex; default from -o's extension (.cpp .cc .cxx .hpp,
                      .c .h, .tex)
  --namespace NS      the C++ namespace, or the C prefix, of the generated names
  --depfile FILE      a make rule: the output depends on the model and its data files
  --dump F            print an intermediate form (ast, model or module) and stop
  -v                  the time of each stage on stderr
  --real R            double (default) or float: the type of generated C
  --jacobians J       auto (default: tangent from 25 DOFs), unrolled or tangent
  --sensitivities p,..  d(M0, C0, K0, Q0)/dp for these parameters (linear_sensitivities)
Details: docs/cli.md, docs/generated-api.md.
)",
        {{"-o", "--header", "--lang", "--namespace", "--dump", "--depfile", "--real", "--jacobians",
          "--sensitivities"},
         {"-v"}},
        parse_compile, driver::compile);
}

} // namespace yamsc::cli
