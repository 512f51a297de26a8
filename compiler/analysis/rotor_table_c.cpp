// `yamsc rotor-table TABLE -o rotor_table.c [--prefix NAME]`: the rotor block's
// table and its C1 interpolation as one self-contained C99 file (static
// arrays, libm only), for code that embeds the generated model (controllers,
// observers) and fills its thrust and aero_torque inputs itself. The same
// numbers as the runtime's interpolate() (runtime/src/performance_table.cpp),
// checked by tests/embedded.
#include "analysis/commands.hpp"
#include "analysis/rotor_table_bem.hpp"
#include "driver/outputs.hpp"

#include "diag/errors.hpp"
#include "text/number.hpp"

#include "embedded_hermite.hpp"

#include <yamsc/atomic_file.hpp>
#include <yamsc/performance_table.hpp>

#include <cctype>
#include <sstream>

namespace yamsc::analysis {

using driver::check_outputs;
using driver::RotorTableOptions;
namespace {

/// The shortest text that reads back as the same double (a C literal).
std::string literal(double value) {
    std::string text = text::shortest(value);
    if (text.find_first_of(".e") == std::string::npos) text += ".0";
    return text;
}

std::string array(const std::string& name, const std::vector<double>& v) {
    std::ostringstream s;
    s << "static const double " << name << "[" << v.size() << "] = {";
    for (std::size_t i = 0; i < v.size(); ++i)
        s << (i % 6 == 0 ? "\n    " : " ") << literal(v[i]) << (i + 1 < v.size() ? "," : "");
    s << "\n};\n";
    return s.str();
}

bool identifier(const std::string& s) {
    if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) return false;
    for (char c : s)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
    return true;
}

} // namespace

std::string rotor_table_c(const runtime::PerformanceTable& t, const std::string& prefix,
                          const std::string& source_name) {
    const std::string p = prefix + "_";
    std::ostringstream s;
    s << "/* Rotor performance table (" << source_name
      << ") and its C1 interpolation, written by yamsc rotor-table.\n"
         " * "
      << p
      << "coefficient(which, tsr, pitch_deg, &d_tsr, &d_pitch): which = 0 Cp, 1 Ct,\n"
         " * 2 Cq; the value and its partial derivatives per unit TSR and per degree.\n"
         " * Tensor product of cubic Hermite interpolants, node slopes of the parabola\n"
         " * through each node and its neighbours, continued linearly outside the table:\n"
         " * exact at the nodes, continuous first derivatives. Thrust and torque:\n"
         " * T = 0.5 rho pi R^2 V^2 Ct, Q = 0.5 rho pi R^3 V^2 Cq (docs/cli.md). */\n"
         "#include <stddef.h>\n\n";
    const std::size_t nt = t.tsr.size(), np = t.pitch_deg.size();
    s << "#define " << p << "NTSR " << nt << "\n#define " << p << "NPITCH " << np << "\n\n";
    s << array(p + "tsr", t.tsr) << array(p + "pitch", t.pitch_deg) << array(p + "cp", t.cp)
      << array(p + "ct", t.ct) << array(p + "cq", t.cq);
    s << R"(
)" << hermite_weights_text
      << R"(
double PFX_coefficient(int which, double tsr, double pitch_deg, double* d_tsr, double* d_pitch);

double PFX_coefficient(int which, double tsr, double pitch_deg, double* d_tsr, double* d_pitch) {
    const double* v = which == 0 ? PFX_cp : (which == 1 ? PFX_ct : PFX_cq);
    double wt0[PFX_NTSR], wt1[PFX_NTSR], wp0[PFX_NPITCH], wp1[PFX_NPITCH];
    double value = 0.0, dt = 0.0, dp = 0.0, v0, v1;
    size_t r, k;
    PFX_weights(PFX_tsr, PFX_NTSR, tsr, 0, wt0);
    PFX_weights(PFX_tsr, PFX_NTSR, tsr, 1, wt1);
    PFX_weights(PFX_pitch, PFX_NPITCH, pitch_deg, 0, wp0);
    PFX_weights(PFX_pitch, PFX_NPITCH, pitch_deg, 1, wp1);
    for (r = 0; r < PFX_NTSR; ++r) {
        if (wt0[r] == 0.0 && wt1[r] == 0.0) continue;
        v0 = 0.0;
        v1 = 0.0;
        for (k = 0; k < PFX_NPITCH; ++k) {
            v0 += wp0[k] * v[r * PFX_NPITCH + k];
            v1 += wp1[k] * v[r * PFX_NPITCH + k];
        }
        value += wt0[r] * v0;
        dt += wt1[r] * v0;
        dp += wt0[r] * v1;
    }
    if (d_tsr) *d_tsr = dt;
    if (d_pitch) *d_pitch = dp;
    return value;
}
)";
    std::string text = s.str();
    for (std::size_t at = text.find("PFX_"); at != std::string::npos; at = text.find("PFX_", at))
        text.replace(at, 4, p);
    return text;
}

int rotor_table(const RotorTableOptions& o, std::ostream& out, std::ostream& err) {
    if (is_openfast_deck(o.table)) return rotor_table_from_deck(o, out, err);
    if (!identifier(o.prefix)) throw diag::UsageError("--prefix must be a C identifier");
    check_outputs({{"the table", o.table}}, {{"-o", o.output}});
    runtime::PerformanceTable t;
    try {
        t = runtime::read_performance_table(o.table);
    } catch (const std::runtime_error& e) {
        throw diag::UserError(e.what());
    }
    if (t.tsr.size() < 3 || t.pitch_deg.size() < 3)
        throw diag::UserError(o.table + ": rotor-table needs 3 or more TSRs and pitch angles");
    const std::string name = o.table.substr(o.table.find_last_of('/') + 1);
    runtime::write_file_atomically(o.output, rotor_table_c(t, o.prefix, name));
    out << "wrote " << o.output << " (" << t.tsr.size() << " TSRs x " << t.pitch_deg.size()
        << " pitch angles)\n";
    return 0;
}

} // namespace yamsc::analysis
