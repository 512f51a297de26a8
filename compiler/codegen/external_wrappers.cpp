#include "codegen/external_wrappers.hpp"

#include "codegen/text.hpp"
#include "diag/diagnostics.hpp"

#include <algorithm>
#include <map>
#include <set>

namespace yamsc::codegen {
namespace {

/// The sizes the helpers use, as literals.
struct Sizes {
    int nq = 0, nu = 0, nw = 0, na = 0, ny = 0;
    int uw() const { return nu + nw; }
    int max_args = 1, max_results = 1;
};

Sizes sizes_of(const Module& m) {
    Sizes s;
    s.nq = m.model.nq();
    s.nu = m.model.nu();
    s.ny = m.model.ny();
    for (const ExternalInfo& e : m.externals) {
        s.nw += e.results;
        s.na += e.args;
        s.max_args = std::max(s.max_args, e.args);
        s.max_results = std::max(s.max_results, e.results);
    }
    return s;
}

/// An array size: C++ has no arrays of length 0.
std::string dim(int n) {
    return std::to_string(std::max(n, 1));
}

/// `text` with every @KEY@ replaced by its value.
std::string fill(std::string text, const std::map<std::string, std::string>& values) {
    for (const auto& [key, value] : values) {
        const std::string token = "@" + key + "@";
        for (std::size_t at = text.find(token); at != std::string::npos;
             at = text.find(token, at + value.size()))
            text.replace(at, token.size(), value);
    }
    return text;
}

std::map<std::string, std::string> size_values(const Sizes& s) {
    return {{"NQ", std::to_string(s.nq)},
            {"NU", std::to_string(s.nu)},
            {"NW", std::to_string(s.nw)},
            {"NA", std::to_string(s.na)},
            {"NX", std::to_string(2 * s.nq)},
            {"UW", std::to_string(s.uw())},
            {"SA", dim(s.na)},
            {"SUW", dim(s.uw())},
            {"SWQ", dim(s.nw * s.nq)},
            {"SWU", dim(s.nw * s.nu)},
            {"SAQ", dim(s.na * s.nq)},
            {"SAU", dim(s.na * s.nu)},
            {"SWA", dim(s.nw * s.na)},
            {"SQW", dim(s.nq * s.nw)},
            {"SQUW", dim(s.nq * s.uw())},
            {"SXUW", dim(2 * s.nq * s.uw())},
            {"SYUW", dim(s.ny * s.uw())},
            {"MAXA", std::to_string(s.max_args)},
            {"MAXR", std::to_string(s.max_results)}};
}

bool needs_derivatives(const Module& m) {
    for (const Routine& r : m.routines)
        if (!r.internal && r.id && routine_row(*r.id).derivative) return true;
    return false;
}

const char* const support_text =
    R"CODE(// ---- External functions: the user's C functions (docs/generated-api.md) ----

[[maybe_unused]] [[noreturn]] void external_failure(const char* name, const char* where, const std::string& what,
                                   const double* args, int nargs) {
    std::string message = std::string(where) + ": external function '" + name + "' " + what +
                          "; its arguments were (";
    char number[32];
    for (int i = 0; i < nargs; ++i) {
        std::snprintf(number, sizeof number, "%.17g", args[i]);
        message += (i > 0 ? ", " : "") + std::string(number);
    }
    throw std::domain_error(message + ")");
}

// Every value a user's function returned must be finite.
[[maybe_unused]] void external_check(const char* name, const char* where, const char* what, const double* args,
                    int nargs, const double* values, int n) {
    for (int i = 0; i < n; ++i)
        if (!std::isfinite(values[i])) {
            char text[96];
            std::snprintf(text, sizeof text, "%s[%d] = %g", what, i, values[i]);
            external_failure(name, where, "returned a value that is not finite, " + std::string(text),
                             args, nargs);
        }
}

// u_all = [u, w]: the externals' results w at their arguments a(t, q, q', u).
[[maybe_unused]] void external_inputs(double t, const double* q, const double* qd, const double* u, const Params& p,
                     double* u_all, double* a) {
    external_args(t, q, qd, u, p, a);
    for (int i = 0; i < @NU@; ++i) u_all[i] = u[i];
@CALLS@}
)CODE";

const char* const derivative_text = R"CODE(
// d(result)/d(args), row-major results x args, by central differences of the
// function alone (the step of the runtime's output_matrices).
[[maybe_unused]] void external_differences(void (*f)(const double*, double*), const char* name, const char* where,
                          const double* a, int na, int nr, double* J) {
    double x[@MAXA@], rp[@MAXR@], rm[@MAXR@];
    for (int j = 0; j < na; ++j) x[j] = a[j];
    for (int j = 0; j < na; ++j) {
        const double h = 6e-6 * std::fmax(1.0, std::fabs(a[j]));
        x[j] = a[j] + h;
        f(x, rp);
        external_check(name, where, "result", x, na, rp, nr);
        x[j] = a[j] - h;
        f(x, rm);
        external_check(name, where, "result", x, na, rm, nr);
        x[j] = a[j];
        for (int r = 0; r < nr; ++r) J[r * na + j] = (rp[r] - rm[r]) / (2 * h);
    }
}

// out[r, o0 + j] += sign * sum_k G[r, g0 + k] dw[k, j] (row-major; r < rows, j < cols, k < nw).
[[maybe_unused]] void external_chain(const double* G, int ldg, int g0, int rows, const double* dw, int cols,
                    double* out, int ldo, int o0, double sign) {
    for (int r = 0; r < rows; ++r)
        for (int j = 0; j < cols; ++j) {
            double s = 0.0;
            for (int k = 0; k < @NW@; ++k) s += G[r * ldg + g0 + k] * dw[k * cols + j];
            out[r * ldo + o0 + j] += sign * s;
        }
}

// out[r, j] = G[r, j] for the declared inputs' columns j < nu.
[[maybe_unused]] void external_copy_inputs(const double* G, int rows, double* out) {
    for (int r = 0; r < rows; ++r)
        for (int j = 0; j < @NU@; ++j) out[r * @NU@ + j] = G[r * @UW@ + j];
}

// dw/dq, dw/dq' (nw x nq) and dw/du (nw x nu): dw/da da/d[q, q', u].
[[maybe_unused]] void external_derivatives(double t, const double* q, const double* qd, const double* u,
                          const Params& p, const double* a, double* dw_dq, double* dw_dqd,
                          double* dw_du) {
    double da_dq[@SAQ@], da_dqd[@SAQ@], da_du[@SAU@], dw_da[@SWA@];
    external_args_jacobian(t, q, qd, u, p, da_dq, da_dqd, da_du);
    for (int i = 0; i < @NW@ * @NA@; ++i) dw_da[i] = 0.0;
@JACOBIANS@    for (int i = 0; i < @NW@ * @NQ@; ++i) dw_dq[i] = dw_dqd[i] = 0.0;
    for (int i = 0; i < @NW@ * @NU@; ++i) dw_du[i] = 0.0;
    for (int w = 0; w < @NW@; ++w)
        for (int k = 0; k < @NA@; ++k) {
            const double d = dw_da[w * @NA@ + k];
            if (d == 0.0) continue;
            for (int j = 0; j < @NQ@; ++j) {
                dw_dq[w * @NQ@ + j] += d * da_dq[k * @NQ@ + j];
                dw_dqd[w * @NQ@ + j] += d * da_dqd[k * @NQ@ + j];
            }
            for (int j = 0; j < @NU@; ++j) dw_du[w * @NU@ + j] += d * da_du[k * @NU@ + j];
        }
}
)CODE";

} // namespace

bool wrapped_routine(const Routine& routine) {
    return !routine.internal && routine.id && routine_row(*routine.id).wraps_externals;
}

Module with_inner_routines(const Module& module) {
    Module inner = module;
    std::set<std::string> renamed;
    for (Routine& r : inner.routines)
        if (wrapped_routine(r)) {
            renamed.insert(r.name);
            r.name = "inner_" + r.name;
            r.internal = true;
            r.id.reset(); // a helper now, not the API's routine
        }
    // An inner routine calls inner ones (inner_outputs calls inner_rhs): u is
    // already [u, w] there.
    for (Routine& r : inner.routines)
        for (Step& s : r.steps)
            if (s.kind == StepKind::call && renamed.count(s.call.callee))
                s.call.callee = "inner_" + s.call.callee;
    return inner;
}

std::string external_prototypes(const Module& module) {
    if (module.externals.empty()) return "";
    std::string out = "#ifdef __cplusplus\nextern \"C\" {\n#endif\n";
    for (const ExternalInfo& e : module.externals) {
        out += "/* " + e.name + ": " + e.what + " (" + e.location + "): args[" +
               std::to_string(e.args) + "], result[" + std::to_string(e.results) + "] */\n";
        out += "void " + e.name + "(const double* args, double* result);\n";
        if (e.user_jacobian)
            out += "/* optional: d result / d args, row-major " + std::to_string(e.results) +
                   " x " + std::to_string(e.args) + " */\nvoid " + e.name +
                   "_jacobian(const double* args, double* d_result_d_args);\n";
    }
    return out + "#ifdef __cplusplus\n}\n#endif\n";
}

std::string external_comment(const Module& module) {
    if (module.externals.empty()) return "";
    std::string out = "//\n// External functions, provided by the user (docs/generated-api.md):\n";
    for (const ExternalInfo& e : module.externals) {
        out += "//   " + e.name + ": " + e.what + ", " + std::to_string(e.args) + " arguments, " +
               std::to_string(e.results) + " results (" + comment_quote(e.location) + ")\n";
        out += e.user_jacobian ? "//     derivatives: " + e.name +
                                     "_jacobian when linked, else central differences\n"
                               : "//     derivatives: central differences (without jacobian)\n";
    }
    return out;
}

std::string external_weak_declarations(const Module& module) {
    std::string out;
    for (const ExternalInfo& e : module.externals)
        if (e.user_jacobian)
            out += "extern \"C\" void " + e.name +
                   "_jacobian(const double* args, double* d_result_d_args) "
                   "__attribute__((weak));\n";
    return out.empty()
               ? out
               : "// The derivatives are optional: null when the user's library has none.\n" + out;
}

std::string external_support(const Module& module) {
    const Sizes s = sizes_of(module);
    std::string calls, jacobians;
    int a0 = 0;
    for (const ExternalInfo& e : module.externals) {
        const std::string name = c_string_literal(e.name), where = c_string_literal(e.location);
        const std::string args = "a + " + std::to_string(a0),
                          results = "u_all + " + std::to_string(e.first_input);
        calls += "    ::" + e.name + "(" + args + ", " + results + ");\n";
        calls += "    external_check(" + name + ", " + where + ", \"result\", " + args + ", " +
                 std::to_string(e.args) + ", " + results + ", " + std::to_string(e.results) +
                 ");\n";
        const int w0 = e.first_input - s.nu;
        std::string block = "    {\n        double J[" + dim(e.results * e.args) + "];\n";
        const std::string differences = "external_differences(::" + e.name + ", " + name + ", " +
                                        where + ", " + args + ", " + std::to_string(e.args) + ", " +
                                        std::to_string(e.results) + ", J);\n";
        if (e.user_jacobian) {
            block += "        if (::" + e.name +
                     "_jacobian != nullptr) {\n            ::" + e.name + "_jacobian(" + args +
                     ", J);\n            external_check(" + name + ", " + where +
                     ", \"d_result_d_args\", " + args + ", " + std::to_string(e.args) + ", J, " +
                     std::to_string(e.results * e.args) + ");\n        } else {\n" +
                     "            " + differences + "        }\n";
        } else {
            block += "        " + differences;
        }
        block += "        for (int r = 0; r < " + std::to_string(e.results) +
                 "; ++r)\n            for (int j = 0; j < " + std::to_string(e.args) +
                 "; ++j)\n                dw_da[(" + std::to_string(w0) + " + r) * " +
                 std::to_string(s.na) + " + " + std::to_string(a0) + " + j] = J[r * " +
                 std::to_string(e.args) + " + j];\n    }\n";
        jacobians += block;
        a0 += e.args;
    }
    auto values = size_values(s);
    values["CALLS"] = calls;
    values["JACOBIANS"] = jacobians;
    std::string out = fill(support_text, values);
    if (needs_derivatives(module)) out += fill(derivative_text, values);
    return out;
}

std::string external_wrapper_body(const Module& module, RoutineId id) {
    const Sizes s = sizes_of(module);
    std::string body;
    const char* const inputs = "    double u_all[@SUW@], a[@SA@];\n";
    const char* const derivatives = "    double dw_dq[@SWQ@], dw_dqd[@SWQ@], dw_du[@SWU@];\n";
    switch (id) {
    case RoutineId::outputs_from_qdd:
        body = std::string(inputs) + "    external_inputs(t, q, qd, u, p, u_all, a);\n" +
               "    inner_outputs_from_qdd(t, q, qd, qdd, u_all, p, y);\n";
        break;
    case RoutineId::forcing:
    case RoutineId::outputs: {
        const bool forcing = id == RoutineId::forcing;
        body = std::string(inputs) + "    external_inputs(t, q, qd, u, p, u_all, a);\n" +
               "    inner_" + routine_name(id) + "(t, q, qd, u_all, p, " + (forcing ? "F" : "y") +
               ");\n";
        break;
    }
    case RoutineId::rhs:
        body = std::string(inputs) + "    external_inputs(t, x, x + @NQ@, u, p, u_all, a);\n" +
               "    inner_rhs(t, x, u_all, p, xdot);\n";
        break;
    case RoutineId::jacobians:
        body = std::string(inputs) + derivatives +
               "    double dF_duw[@SQUW@];\n"
               "    external_inputs(t, q, qd, u, p, u_all, a);\n"
               "    inner_jacobians(t, q, qd, u_all, p, dF_dq, dF_dqd, dF_duw);\n"
               "    external_derivatives(t, q, qd, u, p, a, dw_dq, dw_dqd, dw_du);\n"
               "    external_chain(dF_duw, @UW@, @NU@, @NQ@, dw_dq, @NQ@, dF_dq, @NQ@, 0, 1.0);\n"
               "    external_chain(dF_duw, @UW@, @NU@, @NQ@, dw_dqd, @NQ@, dF_dqd, @NQ@, 0, 1.0);\n"
               "    external_copy_inputs(dF_duw, @NQ@, dF_du);\n"
               "    external_chain(dF_duw, @UW@, @NU@, @NQ@, dw_du, @NU@, dF_du, @NU@, 0, 1.0);\n";
        break;
    case RoutineId::rhs_jacobian:
        body = std::string(inputs) + derivatives +
               "    double B[@SQW@];\n"
               "    external_inputs(t, x, x + @NQ@, u, p, u_all, a);\n"
               "    inner_rhs_jacobian(t, x, u_all, p, J);\n"
               "    external_qdd_dw(t, x, u_all, p, B);\n"
               "    external_derivatives(t, x, x + @NQ@, u, p, a, dw_dq, dw_dqd, dw_du);\n"
               "    external_chain(B, @NW@, 0, @NQ@, dw_dq, @NQ@, J + @NQ@ * @NX@, @NX@, 0, 1.0);\n"
               "    external_chain(B, @NW@, 0, @NQ@, dw_dqd, @NQ@, J + @NQ@ * @NX@, @NX@, @NQ@, "
               "1.0);\n";
        break;
    case RoutineId::linear:
        body = std::string(inputs) + derivatives +
               "    double Qw[@SQUW@];\n"
               "    // the linear model is taken at t = 0\n"
               "    external_inputs(0.0, q0, qd0, u0, p, u_all, a);\n"
               "    inner_linear(q0, qd0, u_all, p, M0, C0, K0, Qw);\n"
               "    external_derivatives(0.0, q0, qd0, u0, p, a, dw_dq, dw_dqd, dw_du);\n"
               "    external_chain(Qw, @UW@, @NU@, @NQ@, dw_dq, @NQ@, K0, @NQ@, 0, -1.0);\n"
               "    external_chain(Qw, @UW@, @NU@, @NQ@, dw_dqd, @NQ@, C0, @NQ@, 0, -1.0);\n"
               "    external_copy_inputs(Qw, @NQ@, Q0);\n"
               "    external_chain(Qw, @UW@, @NU@, @NQ@, dw_du, @NU@, Q0, @NU@, 0, 1.0);\n";
        break;
    case RoutineId::state_space:
        body = std::string(inputs) + derivatives +
               "    double Bw[@SXUW@];\n"
               "    external_inputs(0.0, q0, qd0, u0, p, u_all, a);\n"
               "    inner_state_space(q0, qd0, u_all, p, A, Bw);\n"
               "    external_derivatives(0.0, q0, qd0, u0, p, a, dw_dq, dw_dqd, dw_du);\n"
               "    external_chain(Bw, @UW@, @NU@, @NX@, dw_dq, @NQ@, A, @NX@, 0, 1.0);\n"
               "    external_chain(Bw, @UW@, @NU@, @NX@, dw_dqd, @NQ@, A, @NX@, @NQ@, 1.0);\n"
               "    external_copy_inputs(Bw, @NX@, B);\n"
               "    external_chain(Bw, @UW@, @NU@, @NX@, dw_du, @NU@, B, @NU@, 0, 1.0);\n";
        break;
    case RoutineId::output_matrices:
        body = std::string(inputs) + derivatives +
               "    double Dw[@SYUW@];\n"
               "    external_inputs(0.0, q0, qd0, u0, p, u_all, a);\n"
               "    inner_output_matrices(q0, qd0, u_all, p, C, Dw);\n"
               "    external_derivatives(0.0, q0, qd0, u0, p, a, dw_dq, dw_dqd, dw_du);\n"
               "    external_chain(Dw, @UW@, @NU@, @NY@, dw_dq, @NQ@, C, @NX@, 0, 1.0);\n"
               "    external_chain(Dw, @UW@, @NU@, @NY@, dw_dqd, @NQ@, C, @NX@, @NQ@, 1.0);\n"
               "    external_copy_inputs(Dw, @NY@, D);\n"
               "    external_chain(Dw, @UW@, @NU@, @NY@, dw_du, @NU@, D, @NU@, 0, 1.0);\n";
        break;
    case RoutineId::mass_matrix:
    case RoutineId::linear_sensitivities:
    case RoutineId::operating_point:
    case RoutineId::constraints:
    case RoutineId::constraint_matrix:
    case RoutineId::constraint_bias:
    case RoutineId::constraint_jacobians:
        throw diag::InternalError(std::string("code generation: ") + routine_name(id) +
                                  " has no externals' wrapper");
    }
    auto values = size_values(s);
    values["NY"] = std::to_string(s.ny);
    return fill(body, values);
}

} // namespace yamsc::codegen
