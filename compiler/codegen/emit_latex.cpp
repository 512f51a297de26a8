#include "codegen/emit_latex.hpp"

#include "codegen/latex_printer.hpp"
#include "diag/diagnostics.hpp"

#include <fmt/format.h>

#include <cctype>

namespace yamsc::codegen {
namespace {

using latex::escape_text;
using latex::Expander;
using latex::symbol_name;

/// The primes at the end of an input channel's name (`theta_p''` -> 2).
int trailing_primes(const std::string& name, std::string& base) {
    std::size_t end = name.size();
    while (end > 0 && name[end - 1] == '\'') --end;
    base = name.substr(0, end);
    return static_cast<int>(name.size() - end);
}

/// An Expander that knows every symbol of the system by its LaTeX name; the
/// accelerations `a` of dMa_dq are the operating point's q''0. Parameters print
/// before the coordinates, rates and inputs in a product (rank 0 and 1).
Expander expander(const ir::System& s) {
    using ir::SymbolKind;
    Expander x(s.graph);
    x.name({SymbolKind::time, 0}, "t");
    for (int i = 0; i < s.nq(); ++i) {
        const std::string& name = s.dofs[static_cast<std::size_t>(i)].name;
        x.name({SymbolKind::q, i}, symbol_name(name));
        x.name({SymbolKind::qd, i}, symbol_name(name, 1));
        x.name({SymbolKind::qdd, i}, symbol_name(name, 2));
    }
    for (int k = 0; k < s.nu(); ++k) {
        std::string base;
        const int primes = trailing_primes(s.inputs[static_cast<std::size_t>(k)].name, base);
        x.name({SymbolKind::input, k}, symbol_name(base, primes));
    }
    for (int j = 0; j < s.np(); ++j)
        x.name({SymbolKind::param, j}, symbol_name(s.params[static_cast<std::size_t>(j)].name), 0);
    for (int i = 0; i < s.nq(); ++i)
        x.name({SymbolKind::acceleration, i},
               symbol_name(s.dofs[static_cast<std::size_t>(i)].name, 2, "0"));
    return x;
}

/// The index of entry (i, j) of an n x m matrix: `11` while every index is one
/// digit, `1,10` otherwise.
std::string index(std::size_t i, std::size_t j, std::size_t n, std::size_t m) {
    const bool short_form = n <= 9 && m <= 9;
    return std::to_string(i + 1) + (short_form ? "" : ",") + std::to_string(j + 1);
}

/// Roughly how wide `latex` prints, in characters: commands such as \left,
/// \mathrm and braces take no room, a Greek letter or \sin about two.
std::size_t visible_length(const std::string& latex) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < latex.size(); ++i) {
        const char c = latex[i];
        if (c == '\\') {
            std::size_t j = i + 1;
            while (j < latex.size() && std::isalpha(static_cast<unsigned char>(latex[j]))) ++j;
            const std::string command = latex.substr(i + 1, j - i - 1);
            if (command != "left" && command != "right" && command != "mathrm" &&
                command != "frac" && command != "dot" && command != "ddot")
                n += command.empty() ? 0 : 2;
            i = j > i + 1 ? j - 1 : i + 1;
        } else if (c != '{' && c != '}' && c != '^' && c != '_' && c != ' ') {
            ++n;
        }
    }
    return n;
}

/// `lhs &= t1 + t2 ...`, broken into lines of about 64 printed characters.
std::string equation(const std::string& lhs, const std::vector<std::string>& terms) {
    std::string out = lhs + " &= ";
    if (terms.empty()) return out + "0";
    std::size_t line = 0;
    for (std::size_t i = 0; i < terms.size(); ++i) {
        const bool negative = terms[i][0] == '-';
        const std::string body = terms[i].substr(1);
        std::string piece =
            i == 0 ? (negative ? "-" + body : body) : (negative ? " - " : " + ") + body;
        const std::size_t width = visible_length(piece);
        if (i > 0 && line + width > 64) {
            out += " \\\\\n  &\\quad";
            line = 0;
        }
        out += piece;
        line += width;
    }
    return out;
}

/// The terms of `e`, or a note when its expansion is too long to print.
std::vector<std::string> terms_or_note(Expander& x, const std::vector<ir::Operand>& e) {
    try {
        return x.terms(e);
    } catch (const latex::TooLong& too_long) {
        return {std::string("+\\text{(not printed: ") + too_long.what() + ")}"};
    }
}

/// An entry and its value Σ weight * node.
struct Entry {
    std::string lhs;
    std::vector<ir::Operand> value;
};

Entry entry(std::string lhs, ir::NodeId value) {
    return {std::move(lhs), {{value, 1.0}}};
}

/// An align* block of the entries that are not zero; a sentence when all are.
std::string block(Expander& x, const std::vector<Entry>& entries, const std::string& all_zero) {
    std::vector<std::string> lines;
    for (const Entry& e : entries) {
        std::vector<std::string> t = terms_or_note(x, e.value);
        if (!t.empty()) lines.push_back(equation(e.lhs, t));
    }
    if (lines.empty()) return all_zero + "\n\n";
    std::string out = "\\begin{align*}\n";
    for (std::size_t i = 0; i < lines.size(); ++i)
        out += lines[i] + (i + 1 < lines.size() ? " \\\\\n" : "\n");
    return out + "\\end{align*}\n";
}

std::string equations_of_motion(const ir::Matrix& M, const ir::Row& F, Expander& x) {
    const std::size_t n = F.size();
    std::vector<Entry> mass, forcing;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i; j < n; ++j)
            mass.push_back(entry("M_{" + index(i, j, n, n) + "}", M[i][j]));
    for (std::size_t i = 0; i < n; ++i)
        forcing.push_back(entry("F_{" + std::to_string(i + 1) + "}", F[i]));
    return "Mass matrix (symmetric: $M_{ji} = M_{ij}$; entries not shown are zero):\n" +
           block(x, mass, "The mass matrix is zero.") + "Forcing:\n" +
           block(x, forcing, "The forcing is zero.");
}

/// The constraint rows: Φ of the holonomic ones, r = B q' + c of all (nothing
/// without constraints).
std::string constraints_section(const ir::System& s, Expander& x) {
    if (s.constraints.empty()) return "";
    std::vector<Entry> phi, r;
    for (const ir::ConstraintRow& c : s.constraints) {
        const std::string name = "{\\text{" + escape_text(c.name) + "}}";
        if (c.holonomic) phi.push_back(entry("\\Phi_" + name, c.phi));
        r.push_back(entry("r_" + name, c.r));
    }
    return "\\subsection*{Constraints}\n"
           "$M\\,\\ddot{q} = F + B^T\\lambda$ with the rows $\\Phi(q, t, u) = 0$ and "
           "$r = B\\,\\dot{q} + c = 0$, $B = \\partial r/\\partial \\dot{q}$.\n\n"
           "Holonomic rows:\n" +
           block(x, phi, "No holonomic rows.") + "Velocity rows:\n" +
           block(x, r, "The velocity rows are zero.");
}

std::string symbols_section(const ir::System& s) {
    std::string out = "\\subsection*{Symbols}\n\\begin{itemize}\n";
    auto item = [](const std::string& math, const std::string& doc) {
        return "\\item $" + math + "$" + (doc.empty() ? "" : " --- " + escape_text(doc)) + "\n";
    };
    out += "\\item Degrees of freedom $q$, in this order:\n\\begin{itemize}\n";
    for (const ir::Dof& d : s.dofs) out += item(symbol_name(d.name), d.doc);
    out += "\\end{itemize}\n";
    if (!s.inputs.empty()) {
        out += "\\item Inputs $u$:\n\\begin{itemize}\n";
        for (const ir::InputChannel& u : s.inputs) {
            std::string base;
            const int primes = trailing_primes(u.name, base);
            out += item(symbol_name(base, primes), u.doc);
        }
        out += "\\end{itemize}\n";
    }
    if (!s.params.empty()) {
        out += "\\item Parameters, with their defaults:\n\\begin{itemize}\n";
        for (const ir::Parameter& p : s.params)
            out += item(symbol_name(p.name) +
                            (p.value ? " = " + latex::number(*p.value) : std::string()),
                        p.doc);
        out += "\\end{itemize}\n";
    }
    return out + "\\end{itemize}\n";
}

std::string linear_section(const ir::System& s) {
    using ir::SymbolKind;
    const std::size_t n = s.dofs.size(), nu = s.inputs.size();
    if (s.dF_dq.size() != n || s.dF_dqd.size() != n || s.dF_du.size() != n || s.dMa_dq.size() != n)
        throw diag::InternalError("latex: the linear model needs the unrolled Jacobians");
    const ir::OperatingPoint& op = s.point;
    Expander at_point = expander(s);
    at_point.substitute({SymbolKind::time, 0}, 0.0);
    std::vector<Entry> point;
    for (std::size_t i = 0; i < n; ++i) {
        const int k = static_cast<int>(i);
        at_point.substitute({SymbolKind::q, k}, op.q[i]);
        at_point.substitute({SymbolKind::qd, k}, op.qd[i]);
        point.push_back(entry(symbol_name(s.dofs[i].name, 0, "0"), op.q[i]));
        point.push_back(entry(symbol_name(s.dofs[i].name, 1, "0"), op.qd[i]));
    }
    for (std::size_t k = 0; k < nu; ++k) {
        at_point.substitute({SymbolKind::input, static_cast<int>(k)}, op.u[k]);
        std::string base;
        const int primes = trailing_primes(s.inputs[k].name, base);
        point.push_back(entry(symbol_name(base, primes, "0"), op.u[k]));
    }
    std::string out = "\\subsection*{Linear model at the operating point}\n"
                      "The operating point of the model's \\texttt{linearize} block "
                      "(values not shown are zero):\n";
    Expander plain = expander(s);
    out += block(plain, point, "All coordinates, rates and inputs are zero.");

    std::vector<Entry> residual;
    for (std::size_t i = 0; i < n; ++i)
        residual.push_back(
            entry("F_{" + std::to_string(i + 1) + "}(q_0, \\dot{q}_0, u_0)", s.F[i]));
    bool equilibrium = true;
    for (const Entry& r : residual) equilibrium = equilibrium && at_point.terms(r.value).empty();
    out += "Linearized equations (paper eq.~24--25): $M_0\\,\\delta\\ddot{q} + "
           "C_0\\,\\delta\\dot{q} + K_0\\,\\delta q = Q_0\\,\\delta u$ with "
           "$M_0 = M|_0$, $C_0 = -\\partial F/\\partial\\dot{q}|_0$, "
           "$K_0 = -\\partial F/\\partial q|_0 + \\partial(M\\ddot{q}_0)/\\partial q|_0$, "
           "$Q_0 = \\partial F/\\partial u|_0$.\n";
    if (equilibrium) {
        out += "The operating point is an equilibrium: $F(q_0, \\dot{q}_0, u_0) = 0$, hence "
               "$\\ddot{q}_0 = 0$.\n\n";
        for (std::size_t i = 0; i < n; ++i)
            at_point.substitute({SymbolKind::acceleration, static_cast<int>(i)}, 0.0);
    } else {
        out += "The operating point is \\emph{not} an equilibrium; its residual is\n" +
               block(at_point, residual, "") +
               "and $K_0$ contains the accelerations $\\ddot{q}_0 = M_0^{-1} F(q_0, \\dot{q}_0, "
               "u_0)$.\n\n";
    }
    std::vector<Entry> M0, C0, K0, Q0;
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = i; j < n; ++j)
            M0.push_back(entry("M_{0," + index(i, j, n, n) + "}", s.M[i][j]));
        for (std::size_t j = 0; j < n; ++j) {
            C0.push_back({"C_{0," + index(i, j, n, n) + "}", {{s.dF_dqd[i][j], -1.0}}});
            K0.push_back({"K_{0," + index(i, j, n, n) + "}",
                          {{s.dMa_dq[i][j], 1.0}, {s.dF_dq[i][j], -1.0}}});
        }
        for (std::size_t k = 0; k < nu; ++k)
            Q0.push_back(entry("Q_{0," + index(i, k, n, nu) + "}", s.dF_du[i][k]));
    }
    out += "Mass ($M_{0,ji} = M_{0,ij}$):\n" + block(at_point, M0, "$M_0$ is zero.");
    out += "Damping:\n" + block(at_point, C0, "$C_0$ is zero.");
    out += "Stiffness:\n" + block(at_point, K0, "$K_0$ is zero.");
    if (nu > 0) out += "Inputs:\n" + block(at_point, Q0, "$Q_0$ is zero.");
    out += "Entries not shown are zero. The state-space form is $A = \\begin{bmatrix} 0 & I \\\\ "
           "-M_0^{-1}K_0 & -M_0^{-1}C_0 \\end{bmatrix}$, $B = \\begin{bmatrix} 0 \\\\ M_0^{-1}Q_0 "
           "\\end{bmatrix}$ (generated function \\texttt{state\\_space}).\n";
    return out;
}

} // namespace

std::string emit_latex(const LatexInput& input, const EmitOptions& options) {
    if (!input.system) throw diag::InternalError("latex: no equations");
    const ir::System& eq = *input.system;
    auto comment = [](const std::string& s) {
        std::string out;
        for (char c : s) out += (c == '\n' || c == '\r') ? ' ' : c;
        return out;
    };
    std::string out;
    out += fmt::format("% Generated by yamsc {} -- do not edit.\n",
                       options.compiler_version.empty() ? std::string("(unknown version)")
                                                        : comment(options.compiler_version));
    out += "% Model " + comment(eq.model_name) + " \"" + comment(eq.title) + "\"\n";
    out += "% Source: " + comment(eq.source_path) + "\n";
    out += "% Source digest: " + comment(eq.source_digest) + "\n";
    out += "% Options: " + comment(options.command_line) + "\n";
    out += "\\documentclass[10pt]{article}\n\\usepackage{amsmath}\n"
           "\\usepackage[margin=2cm]{geometry}\n\\allowdisplaybreaks\n\\sloppy\n"
           "\\setlength{\\parindent}{0pt}\n\\begin{document}\n";
    out += "\\section*{\\texttt{" + escape_text(eq.model_name) + "}" +
           (eq.title.empty() ? "" : ": " + escape_text(eq.title)) + "}\n";
    // A path breaks after its slashes (it may be longer than a line).
    std::string path;
    for (char c : escape_text(eq.source_path))
        path += c == '/' ? "/\\allowbreak{}" : std::string(1, c);
    out += "Equations of motion $M(q)\\,\\ddot{q} = F(q, \\dot{q}, u, t)$ of \\texttt{" + path +
           "}, derived by Kane's method.\n";
    out += symbols_section(eq);

    Expander x = expander(eq);
    if (!eq.exact_F.empty()) {
        out += "\\subsection*{Approximated equations of motion}\nTaylor-expanded about 0 in ";
        for (std::size_t i = 0; i < input.approximations.size(); ++i)
            out += (i == 0 ? "" : "; ") + input.approximations[i];
        out += " (the generated code uses this form).\n\n" + equations_of_motion(eq.M, eq.F, x);
        out += "\\subsection*{Exact equations of motion}\n" +
               equations_of_motion(eq.exact_M, eq.exact_F, x);
    } else {
        out += "\\subsection*{Equations of motion}\n" + equations_of_motion(eq.M, eq.F, x);
    }
    out += constraints_section(eq, x);
    if (eq.point.declared) out += linear_section(eq);
    return out + "\\end{document}\n";
}

} // namespace yamsc::codegen
