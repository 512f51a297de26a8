// Models compiled on the fly into shared libraries, as `yamsc sim` does: the
// export shim is pasted after the model (not included), the library is loaded
// and its view must behave like the statically linked model.
#include "runtime/test_models.hpp"

#include "yamsc/abi_export.hpp"
#include "yamsc/dynamic_model.hpp"
#include "yamsc/rk4.hpp"

#include <doctest/doctest.h>

#include <dlfcn.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace yamsc::runtime;
namespace fs = std::filesystem;

namespace {

const fs::path work_dir = fs::path(YAMSC_TEST_BINARY_DIR) / "runtime_abi";
const fs::path source_dir = fs::path(YAMSC_SOURCE_DIR);

std::string read_file(const fs::path& path) {
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// The export shim's text, as the compiler embeds it.
std::string abi_export_text() {
    return read_file(source_dir / "runtime" / "include" / "yamsc" / "abi_export.hpp");
}

// Compiles `source` into lib<name>.so with the flags `yamsc sim` uses (plus
// -Werror: the shim must compile cleanly under the strictest user flags).
fs::path compile_shared(const std::string& name, const std::string& source) {
    fs::create_directories(work_dir);
    const fs::path cpp = work_dir / (name + ".cpp");
    const fs::path lib = work_dir / ("lib" + name + ".so");
    std::ofstream(cpp) << source;
    fs::remove(lib);
    const std::string command = std::string("\"") + YAMSC_CXX_COMPILER +
                                "\" -std=c++17 -shared -fPIC -O1 -fvisibility=hidden -Wall "
                                "-Wextra -Werror -I\"" +
                                (source_dir / "tests").string() + "\" -o \"" + lib.string() +
                                "\" \"" + cpp.string() + "\"";
    REQUIRE_MESSAGE(std::system(command.c_str()) == 0, command);
    return lib;
}

// Built once for all test cases: compiling takes about a second.
const fs::path& oscillator_library() {
    static const fs::path lib = compile_shared(
        "oscillator", "#include \"runtime/oscillator_model.hpp\"\n" + abi_export_text() +
                          "\nYAMSC_EXPORT_MODEL(test_oscillator)\n");
    return lib;
}

std::vector<double> rk4_trajectory(const ModelView& view) {
    std::vector<double> states;
    simulate_rk4(view, {0.1, -0.5}, std::vector<double>{1.0}, 2.0, 0.01,
                 [&](double, const double* x) {
                     states.insert(states.end(), x, x + 2);
                     return true;
                 });
    return states;
}

} // namespace

TEST_CASE("a compiled model reports its sizes, names and default parameters") {
    const SharedModel model(oscillator_library().string());
    CHECK(model.nq() == 1);
    CHECK(model.nu() == 1);
    CHECK(model.np() == 3);
    CHECK(model.ny() == 2);
    CHECK(model.dof_names() == std::vector<std::string>{"x"});
    CHECK(model.input_names() == std::vector<std::string>{"f"});
    CHECK(model.param_names() == std::vector<std::string>{"m", "c", "k"});
    CHECK(model.output_names() == std::vector<std::string>{"spring_force", "kinetic_energy"});
    CHECK(model.default_params() == std::vector<double>{2.0, 0.4, 50.0});
    CHECK(model.param_index("k") == 2);
    CHECK(model.param_index("nope") == -1);
}

TEST_CASE("the loaded model integrates like the statically linked one") {
    const SharedModel model(oscillator_library().string());
    test_oscillator::Params p;
    p.k = 80.0; // not the default: the parameters must cross the ABI
    const auto loaded = rk4_trajectory(model.view({p.m, p.c, p.k}));
    const auto linked = rk4_trajectory(from_generated<test_oscillator::Model>(p));
    REQUIRE(loaded.size() == linked.size());
    double worst = 0.0;
    for (std::size_t i = 0; i < loaded.size(); ++i)
        worst = std::max(worst, std::abs(loaded[i] - linked[i]));
    MESSAGE("largest difference between loaded and linked model: ", worst);
    CHECK(worst <= 1e-14);

    // Every function of the view goes through the library.
    const ModelView view = model.view({p.m, p.c, p.k});
    const double q = 0.2, qd = -1.0, u = 3.0;
    double M, F, J[4], dq, dqd, du, y[2];
    view.mass_matrix(0.0, &q, &u, &M);
    view.forcing(0.0, &q, &qd, &u, &F);
    const double x[2] = {q, qd};
    view.rhs_jacobian(0.0, x, &u, J);
    view.jacobians(0.0, &q, &qd, &u, &dq, &dqd, &du);
    view.outputs(0.0, &q, &qd, &u, y);
    CHECK(M == p.m);
    CHECK(F == doctest::Approx(u - p.c * qd - p.k * q));
    CHECK(J[2] == doctest::Approx(-p.k / p.m));
    CHECK(dq == -p.k);
    CHECK(dqd == -p.c);
    CHECK(du == 1.0);
    CHECK(y[0] == doctest::Approx(p.k * q));
}

TEST_CASE("a view keeps its library loaded after the SharedModel is gone") {
    ModelView view;
    {
        const SharedModel model(oscillator_library().string());
        view = model.view(model.default_params());
    }
    const double x[2] = {0.1, 0.0}, u = 0.0;
    double xdot[2];
    view.rhs(0.0, x, &u, xdot);
    CHECK(xdot[1] == doctest::Approx(-50.0 * 0.1 / 2.0));
}

TEST_CASE("two models loaded at once keep their own symbols") {
    const fs::path pendulum_lib =
        compile_shared("pendulum", "#include \"runtime/test_models.hpp\"\n" + abi_export_text() +
                                       "\nYAMSC_EXPORT_MODEL(test_pendulum)\n");
    const SharedModel oscillator(oscillator_library().string());
    const SharedModel pendulum(pendulum_lib.string());
    CHECK(oscillator.dof_names() == std::vector<std::string>{"x"});
    CHECK(pendulum.dof_names() == std::vector<std::string>{"phi"});
    CHECK(pendulum.nu() == 0);
    const ModelView view = pendulum.view(pendulum.default_params());
    const double x[2] = {0.5, 0.0};
    double xdot[2];
    view.rhs(0.0, x, nullptr, xdot);
    CHECK(xdot[1] == doctest::Approx(-9.81 / 0.8 * std::sin(0.5)));
}

TEST_CASE("wrong parameters for a view are rejected by name") {
    const SharedModel model(oscillator_library().string());
    CHECK_THROWS_AS(model.view({1.0, 2.0}), std::invalid_argument);
    CHECK_THROWS_WITH_AS(model.view({1.0, 0.1, NAN}), doctest::Contains("'k'"),
                         std::invalid_argument);
}

TEST_CASE("missing, foreign and mismatched libraries are errors, not crashes") {
    CHECK_THROWS_WITH_AS(SharedModel((work_dir / "does_not_exist.so").string()),
                         doctest::Contains("does_not_exist.so"), SharedModelError);

    fs::create_directories(work_dir);
    const fs::path garbage = work_dir / "garbage.so";
    std::ofstream(garbage) << "this is not an ELF file\n";
    CHECK_THROWS_AS(SharedModel(garbage.string()), SharedModelError);

    const fs::path future =
        compile_shared("future_abi", "extern \"C\" __attribute__((visibility(\"default\"))) int "
                                     "yamsc_abi_version(void) { return 99; }\n");
    CHECK_THROWS_WITH_AS(SharedModel(future.string()), doctest::Contains("version 99"),
                         SharedModelError);

    const fs::path partial =
        compile_shared("partial_abi", "extern \"C\" __attribute__((visibility(\"default\"))) int "
                                      "yamsc_abi_version(void) { return 1; }\n");
    CHECK_THROWS_WITH_AS(SharedModel(partial.string()), doctest::Contains("yamsc_sizes"),
                         SharedModelError);
}

TEST_CASE("views bind their parameters once, each its own (the ABI's bound routines)") {
    void* handle = dlopen(oscillator_library().c_str(), RTLD_NOW | RTLD_LOCAL);
    REQUIRE(handle);
    const auto bytes = reinterpret_cast<yamsc_params_bytes_fn>(dlsym(handle, "yamsc_params_bytes"));
    REQUIRE(static_cast<bool>(bytes));
    CHECK(bytes() == static_cast<int>(sizeof(test_oscillator::Params)));
    for (const char* symbol : {"yamsc_params_bind", "yamsc_rhs_bound", "yamsc_rhs_jacobian_bound",
                               "yamsc_outputs_bound"})
        CHECK_MESSAGE(dlsym(handle, symbol) != nullptr, symbol);
    dlclose(handle);

    const SharedModel model(oscillator_library().string());
    const ModelView soft = model.view({2.0, 0.4, 50.0}), stiff = model.view({2.0, 0.4, 80.0});
    const double x[2] = {0.1, 0.0}, u = 0.0;
    double a[2], b[2], J[4], y[2];
    soft.rhs(0.0, x, &u, a);
    stiff.rhs(0.0, x, &u, b);
    CHECK(a[1] == -50.0 * 0.1 / 2.0);
    CHECK(b[1] == -80.0 * 0.1 / 2.0);
    stiff.rhs_jacobian(0.0, x, &u, J);
    CHECK(J[2] == -80.0 / 2.0);
    soft.outputs(0.0, x, x + 1, &u, y);
    CHECK(y[0] == 50.0 * 0.1);
}

TEST_CASE("outputs_from_qdd crosses the ABI when the model has it, and is empty otherwise") {
    // The hand-written oscillator has no outputs_from_qdd: its library still
    // builds, and its views (loaded or linked) leave it empty.
    const SharedModel plain(oscillator_library().string());
    CHECK_FALSE(plain.view(plain.default_params()).outputs_from_qdd);
    CHECK_FALSE(from_generated<test_oscillator::Model>({}).outputs_from_qdd);
    // A model that has one: its own outputs with y[1] = the q'' given.
    const fs::path lib = compile_shared(
        "with_qdd",
        "#include \"runtime/oscillator_model.hpp\"\n"
        "namespace with_qdd {\n"
        "struct Model : test_oscillator::Model {\n"
        "    static void outputs_from_qdd(double t, const double* q, const double* qd,\n"
        "                                 const double* qdd, const double* u,\n"
        "                                 const Params& p, double* y) {\n"
        "        outputs(t, q, qd, u, p, y);\n"
        "        y[1] = qdd[0] * p.k;\n"
        "    }\n"
        "};\n"
        "} // namespace with_qdd\n" +
            abi_export_text() + "\nYAMSC_EXPORT_MODEL(with_qdd)\n");
    const SharedModel model(lib.string());
    const ModelView view = model.view({2.0, 0.4, 80.0});
    REQUIRE(view.outputs_from_qdd);
    const double q = 0.2, qd = -1.0, qdd = 3.0, u = 1.0;
    double y[2];
    view.outputs_from_qdd(0.0, &q, &qd, &qdd, &u, y);
    CHECK(y[0] == doctest::Approx(80.0 * q));
    CHECK(y[1] == 240.0);
}
