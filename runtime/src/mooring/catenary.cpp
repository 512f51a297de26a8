#include <yamsc/mooring/catenary.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace yamsc::runtime::mooring {
namespace {

void check_properties(const LineProperties& line, const Span& span) {
    auto refuse = [](const std::string& what) {
        throw std::runtime_error("mooring line: " + what);
    };
    if (!(line.length > 0)) refuse("the unstretched length must be positive");
    if (!(line.axial_stiffness > 0)) refuse("the axial stiffness EA must be positive");
    if (!(line.weight_in_fluid > 0)) refuse("the weight in fluid per length must be positive");
    if (!(span.horizontal >= 0) || !std::isfinite(span.vertical))
        refuse("the fairlead's span from the anchor is not finite");
    if (!(span.vertical > 0)) refuse("the fairlead must be above its anchor");
    if (line.seabed_friction >= 0) {
        // Longer than this, the line would have to double back on the seabed:
        // the "L" along the bottom from the anchor and straight up, stretched.
        const double ea_w = line.axial_stiffness / line.weight_in_fluid;
        const double longest =
            span.horizontal - ea_w + std::sqrt(ea_w * ea_w + 2 * span.vertical * ea_w);
        if (line.length >= longest)
            refuse("the line (" + std::to_string(line.length) +
                   " m) is longer than the span allows with the seabed (" +
                   std::to_string(longest) + " m)");
    }
}

// Peyrot and Goulois (Computers & Structures 10, 1979), as FAST starts.
void starting_tensions(const LineProperties& line, const Span& span, double& h, double& v) {
    const double x = std::max(span.horizontal, 1e-6), z = span.vertical;
    const double lambda = line.length <= std::sqrt(x * x + z * z)
                              ? 0.2
                              : std::sqrt(3 * ((line.length * line.length - z * z) / (x * x) - 1));
    h = std::max(std::abs(0.5 * line.weight_in_fluid * x / lambda), 1e-6);
    v = 0.5 * line.weight_in_fluid * (z / std::tanh(lambda) + line.length);
}

} // namespace

Span catenary_span(const LineProperties& line, double h, double v, double* d) {
    const double w = line.weight_in_fluid, L = line.length, EA = line.axial_stiffness;
    const double cb = line.seabed_friction;
    const double a = v / h, sa = std::sqrt(1 + a * a);
    Span s;
    double dx_dh, dx_dv, dz_dh, dz_dv;
    const double hanging = v - w * L; // > 0: the anchor end is lifted off the seabed
    if (cb < 0 || hanging > 0) {
        const double b = hanging / h, sb = std::sqrt(1 + b * b);
        s.horizontal = h / w * (std::asinh(a) - std::asinh(b)) + h * L / EA;
        s.vertical = h / w * (sa - sb) + L / EA * (v - 0.5 * w * L);
        dx_dh = (std::asinh(a) - std::asinh(b) - a / sa + b / sb) / w + L / EA;
        dx_dv = (1 / sa - 1 / sb) / w;
        dz_dh = dx_dv;
        dz_dv = (a / sa - b / sb) / w + L / EA;
    } else {
        const double on_seabed = L - v / w;
        s.vertical = h / w * (sa - 1) + v * v / (2 * EA * w);
        dz_dh = (1 / sa - 1) / w;
        dz_dv = a / sa / w + v / (EA * w);
        const double base = on_seabed + h / w * std::asinh(a) + h * L / EA;
        dx_dh = (std::asinh(a) - a / sa) / w + L / EA;
        if (h > cb * w * on_seabed) { // friction does not hold it all: the anchor pulls
            s.horizontal = base - cb * w / (2 * EA) * on_seabed * on_seabed;
            dx_dv = (1 / sa - 1) / w + cb * on_seabed / EA;
        } else { // the part of the seabed length next to the anchor is slack
            const double taut = on_seabed - h / (cb * w);
            s.horizontal = base - cb * w / (2 * EA) * (on_seabed * on_seabed - taut * taut);
            dx_dh -= taut / EA;
            dx_dv = (1 / sa - 1) / w + h / (EA * w);
        }
    }
    if (d) {
        d[0] = dx_dh;
        d[1] = dx_dv;
        d[2] = dz_dh;
        d[3] = dz_dv;
    }
    return s;
}

CatenarySolution solve_catenary(const LineProperties& line, const Span& span,
                                const CatenarySolution* guess) {
    check_properties(line, span);
    double h, v;
    if (guess && guess->fairlead_horizontal > 0) {
        h = guess->fairlead_horizontal;
        v = guess->fairlead_vertical;
    } else {
        starting_tensions(line, span, h, v);
    }
    const double w = line.weight_in_fluid, L = line.length;
    CatenarySolution out;
    double d[4];
    constexpr int max_iterations = 100;
    for (int it = 1;; ++it) {
        const Span s = catenary_span(line, h, v, d);
        const double ex = s.horizontal - span.horizontal, ez = s.vertical - span.vertical;
        const double det = d[0] * d[3] - d[1] * d[2];
        const double dh = -(d[3] * ex - d[1] * ez) / det;
        const double dv = -(-d[2] * ex + d[0] * ez) / det;
        if (!std::isfinite(dh) || !std::isfinite(dv) || it > max_iterations)
            throw std::runtime_error("mooring line: the catenary did not converge (span " +
                                     std::to_string(span.horizontal) + ", " +
                                     std::to_string(span.vertical) + " m)");
        // H stays positive: a step that would cross zero goes a tenth of the way.
        h = h + dh > 0 ? h + dh : 0.1 * h;
        v += dv;
        out.iterations = it;
        if (std::abs(dh) <= 1e-14 * h + 1e-300 && std::abs(dv) <= 1e-14 * (std::abs(v) + h)) break;
        if (std::abs(ex) + std::abs(ez) <= 1e-13 * (L + span.horizontal + span.vertical) &&
            std::abs(dh) <= 1e-12 * h)
            break;
    }
    out.fairlead_horizontal = h;
    out.fairlead_vertical = v;
    catenary_span(line, h, v, d);
    const double det = d[0] * d[3] - d[1] * d[2];
    out.stiffness[0] = d[3] / det;
    out.stiffness[1] = -d[1] / det;
    out.stiffness[2] = -d[2] / det;
    out.stiffness[3] = d[0] / det;
    const double hanging = v - w * L;
    if (line.seabed_friction < 0 || hanging > 0) {
        out.anchor_horizontal = h;
        out.anchor_vertical = hanging;
    } else {
        out.length_on_seabed = L - v / w;
        out.anchor_horizontal = std::max(0.0, h - line.seabed_friction * w * out.length_on_seabed);
    }
    return out;
}

} // namespace yamsc::runtime::mooring
