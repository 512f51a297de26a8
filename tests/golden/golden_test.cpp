// Text and compile layers: the committed generated/ files are exactly what the
// compiler writes for models/*.mbd (golden files: C++, C and LaTeX); two runs in separate
// processes give identical bytes; every generated file compiles with strict
// flags (C++17 and C99 -pedantic, gcc and clang when present); the C and C++
// outputs compute the same numbers.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <dirent.h>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <vector>

namespace {

const std::string source_dir = YAMSC_SOURCE_DIR;
const std::string work = std::string(YAMSC_TEST_BINARY_DIR) + "/golden";

std::string read(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

int run(const std::string& cmd) {
    return std::system(cmd.c_str());
}

std::vector<std::string> model_names() {
    std::vector<std::string> out;
    DIR* d = opendir((source_dir + "/models").c_str());
    REQUIRE(d);
    while (dirent* e = readdir(d)) {
        std::string n = e->d_name;
        if (n.size() > 4 && n.compare(n.size() - 4, 4, ".mbd") == 0)
            out.push_back(n.substr(0, n.size() - 4));
    }
    closedir(d);
    std::sort(out.begin(), out.end());
    return out;
}

/// Compiles a model into `dir` (cpp + hpp, c + h, tex) from the source folder, with
/// the model path relative as in scripts/update-golden.sh.
void generate(const std::string& name, const std::string& dir) {
    run("mkdir -p " + dir);
    std::string base = "cd " + source_dir + " && " + YAMSC_EXE + " models/" + name + ".mbd";
    REQUIRE(run(base + " -o " + dir + "/" + name + ".cpp --header " + dir + "/" + name + ".hpp") ==
            0);
    REQUIRE(run(base + " -o " + dir + "/" + name + ".c --header " + dir + "/" + name + ".h") == 0);
    REQUIRE(run(base + " --lang latex -o " + dir + "/" + name + ".tex") == 0);
}

/// The golden files of one model: the code and its LaTeX document.
const char* const golden_extensions[] = {".cpp", ".hpp", ".c", ".h", ".tex"};

bool have(const std::string& tool) {
    return run("command -v " + tool + " >/dev/null 2>&1") == 0;
}

} // namespace

TEST_CASE("generated/ matches what the compiler writes for models/") {
    auto names = model_names();
    REQUIRE(!names.empty());
    for (const auto& name : names) {
        CAPTURE(name);
        generate(name, work + "/fresh");
        for (const char* ext : golden_extensions) {
            std::string golden = source_dir + "/generated/" + name + ext;
            INFO("golden file " << golden
                                << " differs: run scripts/update-golden.sh and review the diff");
            CHECK(read(work + "/fresh/" + name + ext) == read(golden));
        }
    }
}

TEST_CASE("two runs in separate processes write identical bytes") {
    for (const auto& name : model_names()) {
        CAPTURE(name);
        generate(name, work + "/run1");
        generate(name, work + "/run2");
        for (const char* ext : golden_extensions)
            CHECK(read(work + "/run1/" + name + ext) == read(work + "/run2/" + name + ext));
    }
}

TEST_CASE("every generated file compiles with strict flags") {
    std::vector<std::string> cxx = {YAMSC_CXX_COMPILER}, cc = {YAMSC_C_COMPILER};
    if (have("clang++")) cxx.push_back("clang++");
    if (have("clang")) cc.push_back("clang");
    for (const auto& name : model_names()) {
        CAPTURE(name);
        std::string dir = source_dir + "/generated/";
        for (const auto& c : cxx) {
            CAPTURE(c);
            CHECK(run(c + " -std=c++17 -Wall -Wextra -Werror -Wshadow -O1 -c " + dir + name +
                      ".cpp -o " + work + "/" + name + "_cpp.o") == 0);
        }
        for (const auto& c : cc) {
            CAPTURE(c);
            CHECK(run(c + " -std=c99 -pedantic -Wall -Wextra -Werror -O1 -c " + dir + name +
                      ".c -o " + work + "/" + name + "_c.o") == 0);
        }
    }
}

TEST_CASE("the C and C++ outputs compute the same numbers") {
    for (const auto& name : model_names()) {
        CAPTURE(name);
        std::string dir = source_dir + "/generated/";
        std::string driver = work + "/" + name + "_agree.cpp";
        std::ofstream out(driver);
        out << "#include \"" << dir << name << ".hpp\"\n"
            << "extern \"C\" {\n#include \"" << dir << name << ".h\"\n}\n"
            << "#include <cmath>\n#include <cstdio>\n#include <vector>\n"
            << "int main() {\n"
            << "  namespace M = " << name << ";\n"
            << "  M::Params p; " << name << "_params pc = " << name << "_default_params();\n"
            << "  const int nq = M::nq, nu = M::nu, ny = M::ny;\n"
            << "  std::vector<double> x(2 * nq), u(nu > 0 ? nu : 1), a(2 * nq), b(2 * nq), ya(ny + "
               "1), yb(ny + 1);\n"
            << "  double worst = 0;\n"
            << "  for (int k = 0; k < 5; ++k) {\n"
            << "    for (int i = 0; i < 2 * nq; ++i) x[i] = std::sin(1.7 * i + 0.3 * k + 0.1);\n"
            << "    for (int i = 0; i < nu; ++i) u[i] = std::cos(0.9 * i + k);\n"
            << "    M::rhs(0.2, x.data(), u.data(), p, a.data());\n"
            << "    " << name << "_rhs(0.2, x.data(), u.data(), &pc, b.data());\n"
            << "    for (int i = 0; i < 2 * nq; ++i) worst = std::fmax(worst, std::fabs(a[i] - "
               "b[i]) / (1 + std::fabs(a[i])));\n"
            << "    M::outputs(0.2, x.data(), x.data() + nq, u.data(), p, ya.data());\n"
            << "    " << name
            << "_outputs(0.2, x.data(), x.data() + nq, u.data(), &pc, yb.data());\n"
            << "    for (int i = 0; i < ny; ++i) worst = std::fmax(worst, std::fabs(ya[i] - yb[i]) "
               "/ (1 + std::fabs(ya[i])));\n"
            << "  }\n"
            << "  std::printf(\"%.3g\\n\", worst);\n"
            << "  return worst < 1e-13 ? 0 : 1;\n}\n";
        out.close();
        std::string exe = work + "/" + name + "_agree";
        REQUIRE(run(std::string(YAMSC_C_COMPILER) + " -std=c99 -O1 -c " + dir + name + ".c -o " +
                    exe + "_c.o") == 0);
        REQUIRE(run(std::string(YAMSC_CXX_COMPILER) + " -std=c++17 -O1 " + driver + " " + dir +
                    name + ".cpp " + exe + "_c.o -o " + exe + " -lm") == 0);
        CHECK(run(exe) == 0);
    }
}
