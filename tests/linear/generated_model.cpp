#include "generated_model.hpp"

#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace linear_test {

namespace {

// The evaluation program. Step h of the differences: cbrt(eps) scaled, which
// balances truncation (h^2) and rounding (eps/h) errors at about eps^(2/3).
const char* driver_text = R"(#include "model.cpp"
#include <cmath>
#include <cstdio>
#include <vector>

using Model = NS::Model;
static const int nq = Model::nq, nu = Model::nu, np = Model::np, ny = Model::ny, nx = 2 * nq;

static void print(int k, const char* name, const std::vector<double>& v) {
    std::printf("%d %s", k, name);
    for (double x : v) std::printf(" %.17g", x);
    std::printf("\n");
}

static double step(double x) { return 6e-6 * (std::fabs(x) > 1 ? std::fabs(x) : 1.0); }

int main() {
    std::vector<double> pa(np + 1), q0(nq), qd0(nq), u0(nu + 1);
    Model::params_to_array(Model::Params{}, pa.data());
    pa.resize(np);
    print(-1, "sizes", {double(nq), double(nu), double(np), double(ny)});
    print(-1, "defaults", pa);
    pa.resize(np + 1);
    for (int k = 0;; ++k) {
        for (int i = 0; i < np; ++i) if (std::scanf("%lf", &pa[i]) != 1) return 0;
        for (int i = 0; i < nq; ++i) if (std::scanf("%lf", &q0[i]) != 1) return 1;
        for (int i = 0; i < nq; ++i) if (std::scanf("%lf", &qd0[i]) != 1) return 1;
        for (int i = 0; i < nu; ++i) if (std::scanf("%lf", &u0[i]) != 1) return 1;
        const Model::Params p = Model::params_from_array(pa.data());
        std::vector<double> oq(nq), oqd(nq), ou(nu + 1);
        Model::operating_point(p, oq.data(), oqd.data(), ou.data());
        ou.resize(nu);
        print(k, "op_q", oq);
        print(k, "op_qd", oqd);
        print(k, "op_u", ou);
        std::vector<double> A(nx * nx), B(nx * nu + 1), M0(nq * nq), C0(nq * nq), K0(nq * nq),
            Q0(nq * nu + 1), C(ny * nx + 1), D(ny * nu + 1);
        Model::state_space(q0.data(), qd0.data(), u0.data(), p, A.data(), B.data());
        Model::linear(q0.data(), qd0.data(), u0.data(), p, M0.data(), C0.data(), K0.data(),
                      Q0.data());
        Model::output_matrices(q0.data(), qd0.data(), u0.data(), p, C.data(), D.data());
        B.resize(nx * nu); Q0.resize(nq * nu); C.resize(ny * nx); D.resize(ny * nu);
        print(k, "A", A); print(k, "B", B); print(k, "M0", M0); print(k, "C0", C0);
        print(k, "K0", K0); print(k, "Q0", Q0); print(k, "C", C); print(k, "D", D);

        // Central differences of rhs and outputs in x = [q, q'] and u, at t = 0.
        std::vector<double> x(nx), Afd(nx * nx), Bfd(nx * nu), Cfd(ny * nx), Dfd(ny * nu);
        for (int i = 0; i < nq; ++i) { x[i] = q0[i]; x[nq + i] = qd0[i]; }
        std::vector<double> fp(nx), fm(nx), yp(ny + 1), ym(ny + 1);
        for (int j = 0; j < nx; ++j) {
            std::vector<double> xp = x, xm = x;
            const double h = step(x[j]);
            xp[j] += h; xm[j] -= h;
            Model::rhs(0.0, xp.data(), u0.data(), p, fp.data());
            Model::rhs(0.0, xm.data(), u0.data(), p, fm.data());
            Model::outputs(0.0, xp.data(), xp.data() + nq, u0.data(), p, yp.data());
            Model::outputs(0.0, xm.data(), xm.data() + nq, u0.data(), p, ym.data());
            for (int i = 0; i < nx; ++i) Afd[i * nx + j] = (fp[i] - fm[i]) / (2 * h);
            for (int i = 0; i < ny; ++i) Cfd[i * nx + j] = (yp[i] - ym[i]) / (2 * h);
        }
        for (int j = 0; j < nu; ++j) {
            std::vector<double> up = u0, um = u0;
            const double h = step(u0[j]);
            up[j] += h; um[j] -= h;
            Model::rhs(0.0, x.data(), up.data(), p, fp.data());
            Model::rhs(0.0, x.data(), um.data(), p, fm.data());
            Model::outputs(0.0, x.data(), x.data() + nq, up.data(), p, yp.data());
            Model::outputs(0.0, x.data(), x.data() + nq, um.data(), p, ym.data());
            for (int i = 0; i < nx; ++i) Bfd[i * nu + j] = (fp[i] - fm[i]) / (2 * h);
            for (int i = 0; i < ny; ++i) Dfd[i * nu + j] = (yp[i] - ym[i]) / (2 * h);
        }
        print(k, "A_fd", Afd); print(k, "B_fd", Bfd); print(k, "C_fd", Cfd); print(k, "D_fd", Dfd);
        std::fflush(stdout);
    }
}
)";

using test_support::replace_all;

} // namespace

GeneratedModel::GeneratedModel(const std::string& model, const std::string& ns) {
    dir_ = scratch_dir(ns);
    const std::string path = std::string(YAMSC_SOURCE_DIR) + "/" + model;
    REQUIRE_MESSAGE(run(std::string(YAMSC_EXE) + " " + path + " -o " + dir_ + "/model.cpp 2>" +
                        dir_ + "/yamsc.log"),
                    read_file(dir_ + "/yamsc.log"));
    source = read_file(dir_ + "/model.cpp");
    // The C output of the same model must compile cleanly too.
    REQUIRE_MESSAGE(run(std::string(YAMSC_EXE) + " " + path + " -o " + dir_ + "/model.c"),
                    "yamsc --lang c failed");
    REQUIRE_MESSAGE(run(std::string(YAMSC_C_COMPILER) +
                        " -std=c99 -pedantic -Wall -Wextra -Werror -c " + dir_ + "/model.c -o " +
                        dir_ + "/model_c.o > " + dir_ + "/cc.log 2>&1"),
                    read_file(dir_ + "/cc.log"));
    write_file(dir_ + "/driver.cpp", replace_all(driver_text, "NS::", ns + "::"));
    exe_ = dir_ + "/driver";
    const std::string compile = std::string(YAMSC_CXX_COMPILER) +
                                " -std=c++17 -O1 -Wall -Wextra -Werror -I" + dir_ + " " + dir_ +
                                "/driver.cpp -o " + exe_ + " > " + dir_ + "/compile.log 2>&1";
    REQUIRE_MESSAGE(run(compile), read_file(dir_ + "/compile.log"));
    write_file(dir_ + "/none.txt", "");
    REQUIRE(run(exe_ + " < " + dir_ + "/none.txt > " + dir_ + "/sizes.txt"));
    Values head = parse_printed(read_file(dir_ + "/sizes.txt"))[-1];
    const std::vector<double>& sizes = head["sizes"];
    REQUIRE(sizes.size() == 4);
    nq = static_cast<int>(sizes[0]);
    nu = static_cast<int>(sizes[1]);
    np = static_cast<int>(sizes[2]);
    ny = static_cast<int>(sizes[3]);
    defaults = head["defaults"];
    std::vector<double> op = operating_point(defaults);
    op_q.assign(op.begin(), op.begin() + nq);
    op_qd.assign(op.begin() + nq, op.begin() + 2 * nq);
    op_u.assign(op.begin() + 2 * nq, op.end());
}

std::vector<Values> GeneratedModel::evaluate(const std::vector<Point>& points) const {
    std::ostringstream in;
    in.precision(17);
    for (const Point& pt : points) {
        for (double v : pt.p) in << v << " ";
        for (double v : pt.q) in << v << " ";
        for (double v : pt.qd) in << v << " ";
        for (double v : pt.u) in << v << " ";
        in << "\n";
    }
    write_file(dir_ + "/points.txt", in.str());
    REQUIRE(run(exe_ + " < " + dir_ + "/points.txt > " + dir_ + "/values.txt"));
    std::map<int, Values> all = parse_printed(read_file(dir_ + "/values.txt"));
    std::vector<Values> out;
    for (std::size_t k = 0; k < points.size(); ++k) out.push_back(all[static_cast<int>(k)]);
    return out;
}

std::vector<double> GeneratedModel::operating_point(const std::vector<double>& p) const {
    Point pt{p, std::vector<double>(static_cast<std::size_t>(nq), 0.0),
             std::vector<double>(static_cast<std::size_t>(nq), 0.0),
             std::vector<double>(static_cast<std::size_t>(nu), 0.0)};
    Values v = evaluate({pt})[0];
    std::vector<double> out = v["op_q"];
    out.insert(out.end(), v["op_qd"].begin(), v["op_qd"].end());
    out.insert(out.end(), v["op_u"].begin(), v["op_u"].end());
    return out;
}

std::map<int, Values> parse_printed(const std::string& text) {
    std::map<int, Values> out;
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        std::istringstream words(line);
        int k = 0;
        std::string name, w;
        words >> k >> name;
        std::vector<double>& v = out[k][name];
        while (words >> w) v.push_back(std::strtod(w.c_str(), nullptr));
    }
    return out;
}

} // namespace linear_test
