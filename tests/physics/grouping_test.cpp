// Composite bodies (symbolic/projection.hpp): M and F summed through composites
// equal Kane's sums body by body, for every grouping, at random states; and the
// grouping derive() picks costs no more than the others. Checked on every
// shipped model, on the 16-DOF turbine from-openfast makes of the free-decay
// deck (where the composites pay: the rotor's blades), and on two trees made
// for it: grouping_tree.mbd (a flexible body with a joint on its node, a DOF
// shared by siblings) and grouping_reused.mbd (a DOF a joint below uses again:
// its anchors overlap and its terms are summed body by body).
#include "equations_fixture.hpp"
#include "openfast/from_openfast.hpp"
#include "test_files.hpp"

#include <algorithm>
#include <filesystem>
#include <sstream>

using namespace yamsc;

namespace {

using Vector = std::vector<double>;

/// The checked model of a file, with its external channels, as derive() takes it.
model::Model checked(const std::string& path) {
    diag::Diagnostics diags;
    driver::FrontEnd fe = driver::run_front_end(path, driver::Until::model, diags);
    INFO(diags.render());
    REQUIRE(fe.model);
    REQUIRE_FALSE(diags.has_errors());
    return model::with_external_channels(*fe.model);
}

symbolic::Equations derive(const model::Model& m, std::optional<symbolic::Grouping> grouping) {
    diag::Diagnostics diags;
    symbolic::DeriveOptions options;
    options.grouping = grouping;
    options.cost = lower::operation_count;
    auto eq = symbolic::derive(m, diags, options);
    INFO(diags.render());
    REQUIRE(eq);
    return std::move(*eq);
}

double max_abs(const Vector& v) {
    double m = 0;
    for (double x : v) m = std::max(m, std::fabs(x));
    return m;
}

/// The largest difference of M and F between `a` and `b` at random states,
/// relative to the largest entry of each (parameters without a default: 1).
double worst_difference(const symbolic::Equations& a, const symbolic::Equations& b) {
    std::map<std::string, double> params;
    for (const auto& p : a.params)
        if (!p.value) params[p.name] = 1.0;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(-1, 1);
    double worst = 0;
    for (int k = 0; k < 3; ++k) {
        Vector q, qd, u;
        for (int i = 0; i < a.nq(); ++i) {
            q.push_back(0.3 * unit(rng));
            qd.push_back(unit(rng));
        }
        for (int i = 0; i < a.nu(); ++i) u.push_back(100 * unit(rng));
        const auto ea = test::evaluate(a, q, qd, u, params, 0.4);
        const auto eb = test::evaluate(b, q, qd, u, params, 0.4);
        Vector Ma, Mb;
        for (std::size_t r = 0; r < ea.M.size(); ++r) {
            Ma.insert(Ma.end(), ea.M[r].begin(), ea.M[r].end());
            Mb.insert(Mb.end(), eb.M[r].begin(), eb.M[r].end());
        }
        const double m_scale = std::max(max_abs(Ma), 1e-300);
        const double f_scale = std::max(max_abs(ea.F), 1e-300);
        for (std::size_t i = 0; i < Ma.size(); ++i)
            worst = std::max(worst, std::fabs(Ma[i] - Mb[i]) / m_scale);
        for (std::size_t i = 0; i < ea.F.size(); ++i)
            worst = std::max(worst, std::fabs(ea.F[i] - eb.F[i]) / f_scale);
    }
    return worst;
}

double cost(const symbolic::Equations& eq) {
    std::vector<GiNaC::ex> roots;
    for (const auto& row : eq.M) roots.insert(roots.end(), row.begin(), row.end());
    roots.insert(roots.end(), eq.F.begin(), eq.F.end());
    return lower::operation_count(eq, roots);
}

std::vector<std::string> models_checked() {
    std::vector<std::string> out;
    for (const auto& entry : std::filesystem::directory_iterator(test::source_path("models")))
        if (entry.path().extension() == ".mbd") out.push_back(entry.path().string());
    std::sort(out.begin(), out.end());
    out.push_back(test::source_path("tests/physics/models/grouping_tree.mbd"));
    out.push_back(test::source_path("tests/physics/models/grouping_reused.mbd"));
    return out;
}

std::string turbine_16dof() {
    const std::string path = test_support::scratch_dir("grouping", "l16") + "/l16.mbd";
    driver::FromOpenFastOptions o;
    o.deck = test::source_path(
        "tests/data/reference/land_16dof_free_decay/NREL5MW_Onshore_FreeDecay.fst");
    o.output = path;
    std::ostringstream out, err;
    REQUIRE_MESSAGE(openfast::from_openfast(o, out, err) == 0, err.str());
    return path;
}

} // namespace

TEST_CASE("M and F through composite bodies equal Kane's sums body by body") {
    std::vector<std::string> paths = models_checked();
    paths.push_back(turbine_16dof());
    for (const std::string& path : paths) {
        CAPTURE(path);
        const model::Model m = checked(path);
        const auto by_body = derive(m, symbolic::Grouping::none);
        for (auto grouping : {symbolic::Grouping::flexible, symbolic::Grouping::all}) {
            CAPTURE(static_cast<int>(grouping));
            CHECK(worst_difference(by_body, derive(m, grouping)) < 1e-13);
        }
    }
}

TEST_CASE("derive() sums M and F with the grouping that costs the fewest operations") {
    for (const std::string& path :
         {test::source_path("models/nrel5mw_land_operating.mbd"),
          test::source_path("tests/physics/models/grouping_tree.mbd"), turbine_16dof()}) {
        CAPTURE(path);
        const model::Model m = checked(path);
        const double chosen = cost(derive(m, std::nullopt));
        double cheapest = chosen;
        for (auto grouping :
             {symbolic::Grouping::none, symbolic::Grouping::flexible, symbolic::Grouping::all})
            cheapest = std::min(cheapest, cost(derive(m, grouping)));
        CHECK(chosen == cheapest);
    }
    // The 16-DOF turbine: the composites take about a quarter off M and F
    // (7653 -> 5921 operations).
    const model::Model m = checked(turbine_16dof());
    CHECK(cost(derive(m, std::nullopt)) < 0.8 * cost(derive(m, symbolic::Grouping::none)));
}
