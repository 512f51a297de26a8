// `--lang latex`: the document's content for models whose equations are known
// in closed form, determinism, and (when pdflatex is installed) that it
// compiles as a standalone document.
#include "generated_model.hpp"

#include <doctest/doctest.h>

#include <fstream>

using namespace linear_test;

namespace {

/// `yamsc MODEL -o NAME.tex` in a scratch directory; the text.
std::string latex_of(const std::string& model_text_or_path, const std::string& name,
                     bool is_text = false) {
    const std::string dir = scratch_dir("latex_" + name);
    std::string path = std::string(YAMSC_SOURCE_DIR) + "/" + model_text_or_path;
    if (is_text) {
        path = dir + "/" + name + ".mbd";
        write_file(path, model_text_or_path);
    }
    const std::string tex = dir + "/" + name + ".tex";
    REQUIRE_MESSAGE(
        run(std::string(YAMSC_EXE) + " " + path + " -o " + tex + " 2> " + dir + "/err.txt"),
        read_file(dir + "/err.txt"));
    return read_file(tex);
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

/// Braces balance and every environment that opens closes.
void check_structure(const std::string& tex) {
    int depth = 0;
    for (std::size_t i = 0; i < tex.size(); ++i) {
        if (tex[i] == '\\' && i + 1 < tex.size()) {
            ++i; // \{ and \} are characters
            continue;
        }
        if (tex[i] == '%') { // comment to the end of the line
            while (i < tex.size() && tex[i] != '\n') ++i;
            continue;
        }
        if (tex[i] == '{') ++depth;
        if (tex[i] == '}') --depth;
        REQUIRE(depth >= 0);
    }
    CHECK(depth == 0);
    auto count = [&](const std::string& s) {
        std::size_t n = 0;
        for (auto p = tex.find(s); p != std::string::npos; p = tex.find(s, p + 1)) ++n;
        return n;
    };
    CHECK(count("\\begin{align*}") == count("\\end{align*}"));
    CHECK(count("\\begin{itemize}") == count("\\end{itemize}"));
    CHECK(count("\\left") == count("\\right"));
    CHECK(contains(tex, "\\documentclass"));
    CHECK(tex.size() > 20);
    CHECK(tex.substr(tex.size() - 15) == "\\end{document}\n");
}

/// Compiles with pdflatex when it is installed (not a build dependency).
void check_compiles(const std::string& tex, const std::string& name) {
    if (!run("command -v pdflatex > /dev/null 2>&1")) {
        MESSAGE("pdflatex not installed: LaTeX compilation not checked");
        return;
    }
    const std::string dir = scratch_dir("pdflatex_" + name);
    write_file(dir + "/" + name + ".tex", tex);
    const bool ok = run("cd " + dir + " && pdflatex -interaction=nonstopmode -halt-on-error " +
                        name + ".tex > out.log 2>&1");
    CHECK_MESSAGE(ok, read_file(dir + "/out.log"));
    CHECK(run("test -s " + dir + "/" + name + ".pdf"));
    CHECK_FALSE(contains(read_file(dir + "/" + name + ".log"), "Overfull"));
}

} // namespace

TEST_CASE("latex: the pendulum held by a torque, with its linear model") {
    const std::string tex = latex_of("tests/linear/models/pendulum_op.mbd", "pendulum_op");
    check_structure(tex);
    CHECK(contains(tex, "M_{11} &= L^{2} m\n"));
    CHECK(contains(tex, "F_{1} &= \\tau - c \\dot{\\theta} - L g m \\sin\\left(\\theta\\right)\n"));
    // The operating point is a function of the parameters, and an equilibrium.
    CHECK(contains(tex, "\\theta_{0} &= \\mathrm{th}_{0}"));
    CHECK(contains(tex, "\\tau_{0} &= \\Omega c + L g m \\sin\\left(\\mathrm{th}_{0}\\right)"));
    CHECK(contains(tex, "The operating point is an equilibrium"));
    CHECK(contains(tex, "K_{0,11} &= L g m \\cos\\left(\\mathrm{th}_{0}\\right)"));
    CHECK(contains(tex, "C_{0,11} &= c\n"));
    CHECK(contains(tex, "Q_{0,11} &= 1\n"));
    // Byte-identical from one run to the next.
    CHECK(latex_of("tests/linear/models/pendulum_op.mbd", "pendulum_op_again") == tex);
    check_compiles(tex, "pendulum_op");
}

TEST_CASE("latex: a point that is not an equilibrium shows its residual and q''0") {
    const std::string model = R"(model swing
param m = 2, L = 1.5, g = 9.81, a = 0.3
dof th
gravity (0, 0, -g)
rigid bob { mass = m; com = (0, 0, -L) }
joint ground -> bob { rotate y th }
linearize { th = a }
)";
    const std::string tex = latex_of(model, "swing", true);
    check_structure(tex);
    CHECK(contains(tex, "\\emph{not} an equilibrium"));
    CHECK(contains(tex, "F_{1}(q_0, \\dot{q}_0, u_0) &= -L g m \\sin\\left(a\\right)"));
    CHECK(contains(tex, "K_{0,11} &= L g m \\cos\\left(a\\right)"));
    check_compiles(tex, "swing");
}

TEST_CASE("latex: the double pendulum, exact and approximated to first order") {
    std::ifstream in(std::string(YAMSC_SOURCE_DIR) + "/models/double_pendulum.mbd");
    std::string text((std::istreambuf_iterator<char>(in)), {});
    const std::string tex = latex_of(text + "\napprox th1, th2 order 1\n", "dp_approx", true);
    check_structure(tex);
    const auto approximated = tex.find("\\subsection*{Approximated equations of motion}");
    const auto exact = tex.find("\\subsection*{Exact equations of motion}");
    REQUIRE(approximated != std::string::npos);
    REQUIRE(exact != std::string::npos);
    const std::string approx_part = tex.substr(approximated, exact - approximated);
    const std::string exact_part = tex.substr(exact);
    CHECK(contains(approx_part, "Taylor-expanded about 0 in $\\mathrm{th}_{1}$, "
                                "$\\mathrm{th}_{2}$ to order 1"));
    // M to order 1 in the angles is constant: the hand linearization.
    CHECK(contains(approx_part,
                   "M_{11} &= 2\\,L_{1} L_{2} m_{2} + L_{1}^{2} m_{1} + L_{1}^{2} m_{2} + "
                   "L_{2}^{2} m_{2} \\\\\n"));
    CHECK(contains(approx_part, "M_{12} &= L_{1} L_{2} m_{2} + L_{2}^{2} m_{2} \\\\\n"));
    CHECK_FALSE(contains(approx_part, "\\sin"));
    CHECK_FALSE(contains(approx_part, "\\cos"));
    CHECK(contains(exact_part, "2\\,L_{1} L_{2} m_{2} \\cos\\left(\\mathrm{th}_{2}\\right)"));
    check_compiles(tex, "dp_approx");
}

TEST_CASE("latex: the 2-DOF turbine prints like the paper's eq. 36-44") {
    const std::string tex = latex_of("models/nrel5mw_land_2dof.mbd", "nrel5mw_land_2dof");
    check_structure(tex);
    // The rotor and nacelle: M22 = J_xR, F2 = tau_a - tau_g (eq. 36).
    CHECK(contains(tex, "M_{22} &= J_{xR}\n"));
    CHECK(contains(tex, "F_{2} &= \\tau_{a} - \\tau_{g}\n"));
    // Eq. 37-38: M_e + M_N + M_R + nu_y^2 (J_yN + J_oR + ...), nu_y = 0.0185205.
    CHECK(contains(tex, "M_{11} &= 53982.8 + 0.000343011\\,J_{oR} + 0.000343011\\,J_{yN} + "
                        "M_{N} + M_{R}"));
    // Eq. 41 and 43-44: nu_y g (M_N x_NG + M_R x_NR), f_a nu_y (x_NR sin + z_NR cos), f_a cos.
    CHECK(contains(tex, "0.0185205\\,M_{N} g x_{NG}"));
    CHECK(contains(tex, "0.0185205\\,M_{R} g x_{NR}"));
    CHECK(contains(tex, "0.0185205\\,x_{NR} f_{a} \\sin\\left(\\theta_{t}\\right)"));
    CHECK(contains(tex, "0.0185205\\,z_{NR} f_{a} \\cos\\left(\\theta_{t}\\right)"));
    CHECK(contains(tex, "f_{a} \\cos\\left(\\theta_{t}\\right)"));
    // No linearize block: no linear section.
    CHECK_FALSE(contains(tex, "Linear model at the operating point"));
    check_compiles(tex, "nrel5mw_land_2dof");
}
