// The constraint rows (docs/theory.md, Constraint rows) against closed forms, and
// every derivative the constraint_derivatives pass forms against central finite
// differences of the rows themselves, at random states: a planar four-bar's
// loop, a rolling disk's contact, a coordinate prescribed by an input of order 2.
#include "ir/evaluate.hpp"
#include "lower/lower.hpp"
#include "model/checker.hpp"
#include "parse/parser.hpp"
#include "passes/passes.hpp"
#include "symbolic/derive.hpp"

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <random>

using namespace yamsc;
using ir::NodeId;
using ir::SymbolKind;

namespace {

struct NoData final : model::DataSource {
    std::optional<sid::Sid> sid_file(const std::string&, const diag::Location&,
                                     diag::Diagnostics&) override {
        return std::nullopt;
    }
    std::optional<beam::Beam> beam_file(const std::string&, const std::string&, double,
                                        const std::vector<std::string>&, const diag::Location&,
                                        diag::Diagnostics&) override {
        return std::nullopt;
    }
    std::optional<sid::Sid> beam_sid(const beam::Beam&, const std::string&, const diag::Location&,
                                     diag::Diagnostics&) override {
        return std::nullopt;
    }
};

ir::System constrained_system(const std::string& text) {
    NoData data;
    diag::Diagnostics diags;
    auto ast = parse::parse_model(std::make_shared<const diag::SourceFile>("m.mbd", text), diags);
    INFO(diags.render());
    REQUIRE(ast);
    auto m = model::check(*ast, data, diags);
    INFO(diags.render());
    REQUIRE(m);
    auto eq = symbolic::derive(*m, diags, {});
    REQUIRE(eq);
    ir::System s = lower::lower(*eq);
    passes::constraint_derivatives(s);
    return s;
}

/// Values of every symbol kind the rows read.
struct State {
    double t = 0;
    std::vector<double> q, qd, u, lambda, a, p;
};

std::vector<double> values(const ir::System& s, const std::vector<NodeId>& roots, const State& x) {
    return ir::evaluate(s.graph, roots, [&](ir::SymbolRef r) {
        const auto i = static_cast<std::size_t>(r.index);
        switch (r.kind) {
        case SymbolKind::time:
            return x.t;
        case SymbolKind::q:
            return x.q.at(i);
        case SymbolKind::qd:
            return x.qd.at(i);
        case SymbolKind::input:
            return x.u.at(i);
        case SymbolKind::param:
            return x.p.at(i);
        case SymbolKind::multiplier:
            return x.lambda.at(i);
        case SymbolKind::acceleration:
            return x.a.at(i);
        default:
            throw std::runtime_error("unexpected symbol");
        }
    });
}

std::vector<NodeId> flat(const ir::Matrix& m) {
    std::vector<NodeId> out;
    for (const ir::Row& row : m) out.insert(out.end(), row.begin(), row.end());
    return out;
}

std::vector<NodeId> column(const std::vector<ir::ConstraintRow>& rows,
                           NodeId ir::ConstraintRow::*f) {
    std::vector<NodeId> out;
    for (const ir::ConstraintRow& r : rows) out.push_back(r.*f);
    return out;
}

State random_state(const ir::System& s, std::mt19937& rng) {
    std::uniform_real_distribution<double> d(-1.0, 1.0);
    State x;
    x.t = d(rng);
    for (int i = 0; i < s.nq(); ++i) {
        x.q.push_back(d(rng));
        x.qd.push_back(d(rng));
        x.a.push_back(d(rng));
    }
    for (int i = 0; i < s.nu(); ++i) x.u.push_back(d(rng));
    for (int i = 0; i < s.nc(); ++i) x.lambda.push_back(d(rng));
    for (const ir::Parameter& p : s.params) x.p.push_back(*p.value);
    return x;
}

/// d f(x + h e)/dh at 0 by central differences, for each entry of f.
template <class F> std::vector<double> central(F f, double h) {
    const std::vector<double> plus = f(h), minus = f(-h);
    std::vector<double> out;
    for (std::size_t i = 0; i < plus.size(); ++i) out.push_back((plus[i] - minus[i]) / (2 * h));
    return out;
}

/// B a + γ and Bᵀ λ from the rows B and γ (the oracles of their derivatives).
std::vector<double> acceleration_rows(const ir::System& s, const State& x) {
    const std::vector<double> B = values(s, flat(s.B), x), gamma = values(s, s.gamma, x);
    std::vector<double> out(gamma);
    const auto nq = static_cast<std::size_t>(s.nq());
    for (std::size_t i = 0; i < gamma.size(); ++i)
        for (std::size_t k = 0; k < nq; ++k) out[i] += B[i * nq + k] * x.a[k];
    return out;
}

std::vector<double> reaction_rows(const ir::System& s, const State& x) {
    const std::vector<double> B = values(s, flat(s.B), x);
    const auto nq = static_cast<std::size_t>(s.nq());
    std::vector<double> out(nq, 0.0);
    for (std::size_t i = 0; i < x.lambda.size(); ++i)
        for (std::size_t k = 0; k < nq; ++k) out[k] += B[i * nq + k] * x.lambda[i];
    return out;
}

void check_close(const std::vector<double>& exact, const std::vector<double>& approx, double tol) {
    REQUIRE(exact.size() == approx.size());
    for (std::size_t i = 0; i < exact.size(); ++i) {
        INFO("entry " << i << ": " << exact[i] << " vs " << approx[i]);
        CHECK(std::fabs(exact[i] - approx[i]) <= tol * (1 + std::fabs(exact[i])));
    }
}

/// Every derivative the pass forms against central differences of the rows, at
/// `x`. Rows of derivative d(f)/d(v_j) are compared column by column.
void check_derivatives(const ir::System& s, const State& x) {
    const int nq = s.nq(), nc = s.nc(), nu = s.nu();
    const double h = 1e-6, tol = 1e-7;
    auto with = [&](std::vector<double> State::*v, int j, double dh) {
        State y = x;
        (y.*v)[static_cast<std::size_t>(j)] += dh;
        return y;
    };
    auto r = [&](const State& y) {
        return values(s, column(s.constraints, &ir::ConstraintRow::r), y);
    };
    const std::vector<double> B = values(s, flat(s.B), x), dr_dq = values(s, flat(s.dr_dq), x);
    const std::vector<double> dBTl_dq = values(s, flat(s.dBTl_dq), x);
    const std::vector<double> dacc_dq = values(s, flat(s.dacc_dq), x);
    const std::vector<double> dacc_dqd = values(s, flat(s.dacc_dqd), x);
    const std::vector<double> dBTl_du = values(s, flat(s.dBTl_du), x);
    const std::vector<double> dacc_du = values(s, flat(s.dacc_du), x);
    auto entries = [](const std::vector<double>& m, int rows, int cols, int j) {
        std::vector<double> out;
        for (int i = 0; i < rows; ++i) out.push_back(m[static_cast<std::size_t>(i * cols + j)]);
        return out;
    };
    for (int j = 0; j < nq; ++j) {
        INFO("column " << j);
        check_close(entries(B, nc, nq, j),
                    central([&](double e) { return r(with(&State::qd, j, e)); }, h), tol);
        check_close(entries(dr_dq, nc, nq, j),
                    central([&](double e) { return r(with(&State::q, j, e)); }, h), tol);
        check_close(entries(dBTl_dq, nq, nq, j),
                    central([&](double e) { return reaction_rows(s, with(&State::q, j, e)); }, h),
                    tol);
        check_close(
            entries(dacc_dq, nc, nq, j),
            central([&](double e) { return acceleration_rows(s, with(&State::q, j, e)); }, h), tol);
        check_close(
            entries(dacc_dqd, nc, nq, j),
            central([&](double e) { return acceleration_rows(s, with(&State::qd, j, e)); }, h),
            tol);
    }
    for (int j = 0; j < nu; ++j) {
        INFO("input " << j);
        check_close(entries(dBTl_du, nq, nu, j),
                    central([&](double e) { return reaction_rows(s, with(&State::u, j, e)); }, h),
                    tol);
        check_close(
            entries(dacc_du, nc, nu, j),
            central([&](double e) { return acceleration_rows(s, with(&State::u, j, e)); }, h), tol);
    }
    // γ: along q(h) = q + h q' + h²/2 q'', q'(h) = q' + h q'' (q'' = a, arbitrary),
    // dr/dh = B q'' + γ. Inputs and t are held: these models' rows read them only
    // where the prescribed test checks γ in closed form.
    auto along = [&](double e) {
        State y = x;
        for (int k = 0; k < nq; ++k) {
            const auto i = static_cast<std::size_t>(k);
            y.q[i] += e * x.qd[i] + 0.5 * e * e * x.a[i];
            y.qd[i] += e * x.a[i];
        }
        return r(y);
    };
    if (nu == 0) check_close(acceleration_rows(s, x), central(along, 1e-5), 1e-7);
}

const char* const four_bar = R"(model four_bar
param L1 = 0.4, L2 = 1.2, L3 = 0.9, d = 1.0
param m1 = 1.0, m2 = 2.0, m3 = 1.5, g = 9.81
dof th1, th2, th3
gravity (0, 0, -g)
rigid crank { mass = m1; com = (L1, 0, 0) }
rigid coupler { mass = m2; com = (L2, 0, 0) }
rigid rocker { mass = m3; com = (L3, 0, 0) }
joint ground -> crank { rotate y th1 }
joint crank -> coupler { at (L1, 0, 0); rotate y th2 }
joint ground -> rocker { at (d, 0, 0); rotate y th3 }
point coupler_end on coupler at (L2, 0, 0)
point rocker_end on rocker at (L3, 0, 0)
constraint loop closing { a = coupler_end; b = rocker_end; components = (x, z); dependent = (th2, th3) }
)";

} // namespace

TEST_CASE("a planar four-bar's loop rows are its closed-form loop equations") {
    const ir::System s = constrained_system(four_bar);
    REQUIRE(s.nc() == 2);
    REQUIRE(s.nh() == 2);
    CHECK(s.constraints[0].name == "closing.x");
    CHECK(s.constraints[1].name == "closing.z");
    CHECK(s.constraints[0].dependent == 1);
    CHECK(s.constraints[1].dependent == 2);
    CHECK(s.constraints[0].source == "m.mbd:14:1");
    std::mt19937 rng(7);
    const double L1 = 0.4, L2 = 1.2, L3 = 0.9, d = 1.0;
    for (int trial = 0; trial < 5; ++trial) {
        const State x = random_state(s, rng);
        const double t1 = x.q[0], t12 = x.q[0] + x.q[1], t3 = x.q[2];
        // Rotations about y: a frame's x axis is (cos, 0, -sin) in its parent's axes.
        const double dx = L1 * std::cos(t1) + L2 * std::cos(t12) - d - L3 * std::cos(t3);
        const double dz = -L1 * std::sin(t1) - L2 * std::sin(t12) + L3 * std::sin(t3);
        // In the coupler's axes (a is a point of the coupler).
        const std::vector<double> closed{std::cos(t12) * dx - std::sin(t12) * dz,
                                         std::sin(t12) * dx + std::cos(t12) * dz};
        check_close(values(s, column(s.constraints, &ir::ConstraintRow::phi), x), closed, 1e-13);
        check_derivatives(s, x);
    }
}

TEST_CASE("a rolling disk's rows are its contact point's height and velocity") {
    const ir::System s = constrained_system(R"(model disk
param R = 0.3, m = 2, g = 9.81
dof x, y, z, psi, phi, theta
gravity (0, 0, -g)
rigid wheel { mass = m; inertia = (0.1, 0.2, 0.1, 0, 0, 0) }
joint ground -> wheel { translate x x; translate y y; translate z z; rotate z psi; rotate x phi; rotate y theta }
constraint rolling contact { wheel = wheel; radius = R; axle = y }
)");
    REQUIRE(s.nc() == 3);
    REQUIRE(s.nh() == 1);
    CHECK(s.constraints[0].name == "contact.height");
    CHECK(s.constraints[1].name == "contact.x");
    CHECK(s.constraints[2].name == "contact.y");
    std::mt19937 rng(11);
    const double R = 0.3;
    for (int trial = 0; trial < 5; ++trial) {
        const State st = random_state(s, rng);
        const double psi = st.q[3], phi = st.q[4];
        const double psid = st.qd[3], phid = st.qd[4], thetad = st.qd[5];
        using V = std::array<double, 3>;
        const V axle{-std::sin(psi) * std::cos(phi), std::cos(psi) * std::cos(phi), std::sin(phi)};
        const V lean_axis{std::cos(psi), std::sin(psi), 0};
        V w, rho, v;
        for (int i = 0; i < 3; ++i)
            w[i] = (i == 2 ? psid : 0) + phid * lean_axis[i] + thetad * axle[i];
        // The lowest point: from the centre, R along -z + sin(phi) axle, normalised.
        for (int i = 0; i < 3; ++i)
            rho[i] = R * (std::sin(phi) * axle[i] - (i == 2 ? 1 : 0)) / std::cos(phi);
        for (int i = 0; i < 3; ++i)
            v[i] = st.qd[i] + w[(i + 1) % 3] * rho[(i + 2) % 3] - w[(i + 2) % 3] * rho[(i + 1) % 3];
        check_close(values(s, column(s.constraints, &ir::ConstraintRow::phi), st),
                    {st.q[2] - R * std::cos(phi), 0, 0}, 1e-13);
        const std::vector<double> r = values(s, column(s.constraints, &ir::ConstraintRow::r), st);
        check_close({r[1], r[2]}, {v[0], v[1]}, 1e-13);
        check_derivatives(s, st);
    }
}

TEST_CASE("a prescribed coordinate's row, with an input of order 2 and time") {
    const ir::System s = constrained_system(R"(model held
param m = 1, L = 1, g = 9.81
input beta order 2
dof th
gravity (0, 0, -g)
rigid arm { mass = m; com = (0, 0, -L) }
joint ground -> arm { rotate y th }
constraint prescribed hold { coordinate = th; value = 0.5*beta + 0.1*t^2 }
)");
    REQUIRE(s.nc() == 1);
    REQUIRE(s.nu() == 3); // beta, beta', beta''
    std::mt19937 rng(3);
    for (int trial = 0; trial < 3; ++trial) {
        const State x = random_state(s, rng);
        const std::vector<NodeId> rows{s.constraints[0].phi, s.constraints[0].r, s.B[0][0],
                                       s.gamma[0]};
        check_close(values(s, rows, x),
                    {x.q[0] - 0.5 * x.u[0] - 0.1 * x.t * x.t, x.qd[0] - 0.5 * x.u[1] - 0.2 * x.t,
                     1.0, -0.5 * x.u[2] - 0.2},
                    1e-14);
        check_close(values(s, flat(s.dacc_du), x), {0, 0, -0.5}, 1e-14);
        check_derivatives(s, x);
    }
}

TEST_CASE("revolute and weld loop rows: b's axes seen from a's") {
    const ir::System s = constrained_system(R"(model joints
dof q1, q2, q3, q4
rigid A { mass = 1 }
rigid B { mass = 1 }
joint ground -> A { rotate z q1; rotate x q2 }
joint ground -> B { at (1, 0, 0); rotate y q3; rotate z q4 }
point pb on B at (0, 0.5, 0)
constraint loop hinge { a = A; b = pb; joint = revolute; axis = z }
constraint loop fix { a = A; b = B; joint = weld; components = (y) }
)");
    std::vector<std::string> names;
    for (const ir::ConstraintRow& r : s.constraints) names.push_back(r.name);
    CHECK(names == std::vector<std::string>{"hinge.x", "hinge.y", "hinge.z", "hinge.rx", "hinge.ry",
                                            "fix.y", "fix.rx", "fix.ry", "fix.rz"});
    using M3 = std::array<std::array<double, 3>, 3>;
    auto times = [](const M3& a, const M3& b) {
        M3 c{};
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                for (int k = 0; k < 3; ++k) c[i][j] += a[i][k] * b[k][j];
        return c;
    };
    // Columns: the turned frame's axes in the frame it turns from.
    auto rotation = [](int axis, double angle) {
        const double c = std::cos(angle), s = std::sin(angle);
        const int i = (axis + 1) % 3, j = (axis + 2) % 3;
        M3 r{};
        r[axis][axis] = 1;
        r[i][i] = c;
        r[j][j] = c;
        r[i][j] = -s;
        r[j][i] = s;
        return r;
    };
    std::mt19937 rng(13);
    for (int trial = 0; trial < 5; ++trial) {
        const State x = random_state(s, rng);
        const M3 A = times(rotation(2, x.q[0]), rotation(0, x.q[1]));
        const M3 B = times(rotation(1, x.q[2]), rotation(2, x.q[3]));
        // a_i . b_j, and B's point in A's axes.
        auto ab = [&](int i, int j) {
            return A[0][i] * B[0][j] + A[1][i] * B[1][j] + A[2][i] * B[2][j];
        };
        std::array<double, 3> pb{1 + 0.5 * B[0][1], 0.5 * B[1][1], 0.5 * B[2][1]}, d{};
        for (int i = 0; i < 3; ++i) d[i] = -(A[0][i] * pb[0] + A[1][i] * pb[1] + A[2][i] * pb[2]);
        std::array<double, 3> o{};
        for (int i = 0; i < 3; ++i) o[i] = -A[0][i]; // B's origin (1, 0, 0) in A's axes
        check_close(values(s, column(s.constraints, &ir::ConstraintRow::phi), x),
                    {d[0], d[1], d[2], ab(0, 2), ab(1, 2), o[1], ab(2, 1), ab(0, 2), ab(1, 0)},
                    1e-13);
        check_derivatives(s, x);
    }
}
