#include "compile_support.hpp"

#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <sstream>

namespace codegen_test {
namespace {

namespace fs = std::filesystem;
using yamsc::codegen::EmitOptions;
using yamsc::codegen::EmittedFiles;

std::string literal_list(const std::vector<double>& v) {
    std::string out;
    for (double x : v) out += (out.empty() ? "" : ", ") + fmt::format("{:.17g}", x);
    return out.empty() ? "0.0" : out;
}

std::size_t at_least_one(std::size_t n) {
    return n == 0 ? 1 : n;
}

// The evaluation code for one model, in the common subset of C and C++; the
// spelling of names comes from `lang`.
std::string run_function(Language lang, const ModelUnderTest& m) {
    const std::string& name = m.eq->model_name;
    const bool c = lang == Language::c;
    auto fn = [&](const std::string& f) { return c ? name + "_" + f : name + "::" + f; };
    const std::string params_type = c ? name + "_params" : name + "::Params";
    const std::string pp = c ? "&p" : "p";
    const std::size_t nq = m.point.q.size(), nu = m.point.u.size(), np = m.point.p.size(),
                      ny = m.eq->outputs.size(), nx = 2 * nq;
    std::string s = fmt::format("static void run_{}(void) {{\n", name);
    s += fmt::format("    const double pa[{}] = {{{}}};\n", at_least_one(np),
                     literal_list(m.point.p));
    s += fmt::format("    const double q[{}] = {{{}}};\n", at_least_one(nq),
                     literal_list(m.point.q));
    s += fmt::format("    const double qd[{}] = {{{}}};\n", at_least_one(nq),
                     literal_list(m.point.qd));
    s += fmt::format("    const double uv[{}] = {{{}}};\n", at_least_one(nu),
                     literal_list(m.point.u));
    s += fmt::format("    const double* u = {};\n", nu == 0 ? (c ? "NULL" : "nullptr") : "uv");
    s += fmt::format("    const double t = {:.17g};\n", m.point.t);
    s += fmt::format("    const {} p = {};\n", params_type, fn("params_from_array") + "(pa)");
    s += fmt::format("    const {} d = {};\n", params_type,
                     c ? fn("default_params") + "()" : params_type + "{}");
    s += fmt::format("    double defaults[{}] = {{0}}, M[{}] = {{0}}, F[{}] = {{0}};\n",
                     at_least_one(np), nq * nq + 1, nq + 1);
    s += fmt::format("    double A[{}] = {{0}}, B[{}] = {{0}}, C[{}] = {{0}}, y[{}] = {{0}};\n",
                     nq * nq + 1, nq * nq + 1, nq * nu + 1, ny + 1);
    s += fmt::format(
        "    double x[{0}] = {{0}}, xdot[{0}] = {{0}}, xp[{0}], xm[{0}], fp[{0}], fm[{0}];\n",
        nx + 1);
    s += fmt::format("    double J[{0}] = {{0}}, Jfd[{0}] = {{0}};\n    int i, j;\n", nx * nx + 1);
    s += "    (void)uv;\n";
    s += fmt::format("    {}({}, defaults);\n", fn("params_to_array"), c ? "&d" : "d");
    s += fmt::format("    print(\"{}\", \"defaults\", defaults, {});\n", name, np);
    s += fmt::format("    {}(t, q, u, {}, M);\n", fn(c ? "mass_matrix_tu" : "mass_matrix"), pp);
    s += fmt::format("    print(\"{}\", \"M\", M, {});\n", name, nq * nq);
    if (m.module.mass_matrix_short_form) {
        s += fmt::format("    double Ms[{}];\n", nq * nq + 1);
        s += fmt::format("    {}(q, {}, Ms);\n", fn("mass_matrix"), pp);
        s += fmt::format("    print(\"{}\", \"M_short\", Ms, {});\n", name, nq * nq);
    }
    s += fmt::format("    {}(t, q, qd, u, {}, F);\n", fn("forcing"), pp);
    s += fmt::format("    print(\"{}\", \"F\", F, {});\n", name, nq);
    s += fmt::format("    {}(t, q, qd, u, {}, A, B, C);\n", fn("jacobians"), pp);
    s += fmt::format(
        "    print(\"{0}\", \"dF_dq\", A, {1});\n    print(\"{0}\", \"dF_dqd\", B, {1});\n", name,
        nq * nq);
    s += fmt::format("    print(\"{}\", \"dF_du\", C, {});\n", name, nq * nu);
    s += fmt::format("    {}(t, q, qd, u, {}, y);\n", fn("outputs"), pp);
    s += fmt::format("    print(\"{}\", \"y\", y, {});\n", name, ny);
    s += fmt::format("    for (i = 0; i < {0}; ++i) {{ x[i] = q[i]; x[{0} + i] = qd[i]; }}\n", nq);
    s += fmt::format("    {}(t, x, u, {}, xdot);\n", fn("rhs"), pp);
    s += fmt::format("    print(\"{}\", \"xdot\", xdot, {});\n", name, nx);
    s += fmt::format("    {}(t, x, u, {}, J);\n", fn("rhs_jacobian"), pp);
    s += fmt::format("    print(\"{}\", \"J\", J, {});\n", name, nx * nx);
    s += fmt::format(
        "    for (j = 0; j < {0}; ++j) {{\n"
        "        const double h = 1e-6 * (fabs(x[j]) > 1.0 ? fabs(x[j]) : 1.0);\n"
        "        for (i = 0; i < {0}; ++i) {{ xp[i] = x[i]; xm[i] = x[i]; }}\n"
        "        xp[j] += h;\n        xm[j] -= h;\n"
        "        {1}(t, xp, u, {2}, fp);\n        {1}(t, xm, u, {2}, fm);\n"
        "        for (i = 0; i < {0}; ++i) Jfd[i * {0} + j] = (fp[i] - fm[i]) / (2.0 * h);\n"
        "    }}\n",
        nx, fn("rhs"), pp);
    s += fmt::format("    print(\"{}\", \"J_fd\", Jfd, {});\n", name, nx * nx);
    if (!c) {
        s += fmt::format("    run_model<{}::Model>(\"{}\", p, x, u, t);\n", name, name);
    }
    return s + "}\n\n";
}

std::string driver(Language lang, const std::vector<ModelUnderTest>& models) {
    const bool c = lang == Language::c;
    std::string s;
    for (const ModelUnderTest& m : models) {
        const std::string& name = m.eq->model_name;
        if (m.with_header)
            s += fmt::format("#include \"{}.{}\"\n", name, c ? "h" : "hpp");
        else
            s += fmt::format("#include \"{}.{}\"\n", name, c ? "c" : "cpp");
    }
    s += c ? "#include <math.h>\n#include <stddef.h>\n#include <stdio.h>\n\n"
           : "#include <cmath>\n#include <cstdio>\nusing std::fabs;\nusing std::printf;\n\n";
    s += "static void print(const char* model, const char* what, const double* v, int n) {\n"
         "    int i;\n    printf(\"%s %s\", model, what);\n"
         "    for (i = 0; i < n; ++i) printf(\" %.17g\", v[i]);\n    printf(\"\\n\");\n}\n\n";
    if (!c)
        s += "// The Model bundle, as the runtime's from_generated<Model> uses it.\n"
             "template <class Model>\n"
             "static void run_model(const char* name, const typename Model::Params& p, const "
             "double* x, const double* u, double t) {\n"
             "    double xdot[2 * Model::nq + 1];\n"
             "    Model::rhs(t, x, u, p, xdot);\n"
             "    std::printf(\"%s names %s %s\\n\", name, Model::model_name, "
             "Model::dof_names[0]);\n"
             "    print(name, \"xdot_model\", xdot, 2 * Model::nq);\n}\n\n";
    for (const ModelUnderTest& m : models) s += run_function(lang, m);
    s += "int main(void) {\n";
    for (const ModelUnderTest& m : models) s += fmt::format("    run_{}();\n", m.eq->model_name);
    return s + "    return 0;\n}\n";
}

Results parse(const std::string& output) {
    Results r;
    std::istringstream lines(output);
    std::string line;
    while (std::getline(lines, line)) {
        std::istringstream words(line);
        std::string model, what;
        words >> model >> what;
        if (what == "names") continue;
        std::vector<double> values;
        std::string w;
        while (words >> w) values.push_back(std::strtod(w.c_str(), nullptr));
        r[model + " " + what] = values;
    }
    return r;
}

bool run(const std::string& command, std::string& log) {
    log += "$ " + command + "\n";
    return std::system(command.c_str()) == 0;
}

} // namespace

RunResult compile_and_run(Language lang, const std::vector<ModelUnderTest>& models,
                          const std::string& dir_name) {
    const bool c = lang == Language::c;
    const std::string dir = scratch_dir(dir_name);
    RunResult result;
    std::string sources;
    for (const ModelUnderTest& m : models) {
        const std::string& name = m.eq->model_name;
        EmitOptions options;
        options.compiler_version = "test";
        options.command_line = "--lang " + std::string(c ? "c" : "cpp");
        options.max_function_statements = m.max_function_statements;
        if (m.with_header) options.header_name = name + (c ? ".h" : ".hpp");
        const EmittedFiles files = c ? yamsc::codegen::emit_c(m.module, options)
                                     : yamsc::codegen::emit_cpp(m.module, options);
        const std::string source = dir + "/" + name + (c ? ".c" : ".cpp");
        write_file(source, files.source);
        result.files.push_back(source);
        if (m.with_header) {
            write_file(dir + "/" + options.header_name, files.header);
            result.files.push_back(dir + "/" + options.header_name);
            sources += " " + source;
        }
    }
    const std::string driver_path = dir + (c ? "/driver.c" : "/driver.cpp");
    write_file(driver_path, driver(lang, models));
    const std::string exe = dir + "/driver";
    const std::string flags = c ? "-std=c99 -pedantic -O2 -Wall -Wextra -Werror -Wshadow"
                                : "-std=c++17 -pedantic -O2 -Wall -Wextra -Werror -Wshadow";
    const std::string compiler = c ? YAMSC_C_COMPILER : YAMSC_CXX_COMPILER;
    const std::string compile = fmt::format("{} {} -I{} {}{} -o {} -lm > {}/compile.log 2>&1",
                                            compiler, flags, dir, driver_path, sources, exe, dir);
    if (!run(compile, result.log)) {
        result.log += read_file(dir + "/compile.log");
        return result;
    }
    if (!run(exe + " > " + dir + "/out.txt 2>&1", result.log)) {
        result.log += read_file(dir + "/out.txt");
        return result;
    }
    result.values = parse(read_file(dir + "/out.txt"));
    result.ok = true;
    return result;
}

} // namespace codegen_test
