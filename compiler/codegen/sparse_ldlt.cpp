#include "codegen/sparse_ldlt.hpp"

#include "diag/diagnostics.hpp"

#include <algorithm>
#include <tuple>

namespace yamsc::codegen {

bool LdltPlan::nonzero(int i, int j) const {
    const std::vector<int>& column = below.at(static_cast<std::size_t>(j));
    return std::binary_search(column.begin(), column.end(), i);
}

bool LdltPlan::nonzero_in_m(int i, int j) const {
    const int a = order.at(static_cast<std::size_t>(i)), b = order.at(static_cast<std::size_t>(j));
    return pattern[static_cast<std::size_t>(std::max(a, b))]
                  [static_cast<std::size_t>(std::min(a, b))];
}

LowerPattern mass_pattern(const ir::Graph& graph, const std::vector<std::vector<ir::NodeId>>& M) {
    LowerPattern p(M.size());
    for (std::size_t i = 0; i < M.size(); ++i)
        for (std::size_t j = 0; j <= i; ++j) {
            const ir::Node& node = graph.node(M[i].at(j));
            p[i].push_back(!(node.kind == ir::NodeKind::number && node.value == 0.0));
        }
    return p;
}

LowerPattern dense_pattern(int n) {
    LowerPattern p(static_cast<std::size_t>(std::max(n, 0)));
    for (std::size_t i = 0; i < p.size(); ++i) p[i].assign(i + 1, true);
    return p;
}

namespace {

using Matrix = std::vector<std::vector<char>>;

/// The symmetric adjacency of the pattern's off-diagonal nonzeros.
Matrix adjacency(const LowerPattern& pattern) {
    const std::size_t n = pattern.size();
    Matrix adj(n, std::vector<char>(n, 0));
    for (std::size_t i = 0; i < n; ++i) {
        if (pattern[i].size() != i + 1)
            throw diag::InternalError("code generation: the pattern of M is not a lower triangle");
        for (std::size_t j = 0; j < i; ++j) adj[i][j] = adj[j][i] = pattern[i][j] ? 1 : 0;
    }
    return adj;
}

int count_of(const std::vector<char>& row, const std::vector<char>& mask) {
    int c = 0;
    for (std::size_t k = 0; k < row.size(); ++k) c += row[k] && mask[k];
    return c;
}

/// The multiply-subtract updates of the factorisation: each nonzero L(i, k)
/// of row i meets the nonzero L(j, k) of each later column j (W(i, j) and, for
/// i == j, D(i)).
long updates_of(const LdltPlan& plan) {
    const std::size_t n = static_cast<std::size_t>(plan.n);
    Matrix nz(n, std::vector<char>(n, 0));
    for (std::size_t k = 0; k < n; ++k)
        for (int i : plan.below[k]) nz[static_cast<std::size_t>(i)][k] = 1;
    long updates = 0;
    for (std::size_t j = 0; j < n; ++j) {
        updates += count_of(nz[j], nz[j]); // D(j)
        for (int i : plan.below[j]) {
            long common = 0;
            for (std::size_t k = 0; k < j; ++k)
                common += nz[static_cast<std::size_t>(i)][k] && nz[j][k];
            updates += common;
        }
    }
    return updates;
}

} // namespace

LdltPlan plan_ldlt(const LowerPattern& pattern) {
    Matrix adj = adjacency(pattern);
    const int n = static_cast<int>(pattern.size());
    LdltPlan plan;
    plan.n = n;
    plan.pattern = pattern;
    std::vector<char> remaining(static_cast<std::size_t>(n), 1);
    std::vector<int> original_degree;
    for (const std::vector<char>& row : adj) original_degree.push_back(count_of(row, remaining));
    std::vector<std::vector<int>> neighbours_at_elimination; // by step, original indices
    for (int step = 0; step < n; ++step) {
        int best = -1;
        std::tuple<int, int, int> best_key;
        for (int v = 0; v < n; ++v) {
            if (!remaining[v]) continue;
            const std::tuple<int, int, int> key{count_of(adj[v], remaining), original_degree[v], v};
            if (best < 0 || key < best_key) {
                best = v;
                best_key = key;
            }
        }
        std::vector<int> neighbours;
        for (int a = 0; a < n; ++a)
            if (remaining[a] && adj[best][a]) neighbours.push_back(a);
        // Eliminating `best` couples all its remaining neighbours: the fill-in.
        for (int a : neighbours)
            for (int b : neighbours)
                if (a != b) adj[a][b] = 1;
        remaining[best] = 0;
        plan.order.push_back(best);
        neighbours_at_elimination.push_back(std::move(neighbours));
    }
    std::vector<int> position(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) position[plan.order[k]] = k;
    long entries = 0;
    for (int k = 0; k < n; ++k) {
        std::vector<int> rows;
        for (int a : neighbours_at_elimination[k]) rows.push_back(position[a]);
        std::sort(rows.begin(), rows.end());
        entries += static_cast<long>(rows.size());
        plan.below.push_back(std::move(rows));
    }
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < i; ++j) plan.structural_zeros += pattern[i][j] ? 0 : 1;
    const long off_diagonal = static_cast<long>(n) * (n - 1) / 2;
    plan.fill_in = static_cast<int>(entries - (off_diagonal - plan.structural_zeros));
    plan.updates = updates_of(plan);
    plan.straight_line = n > 0 && plan.updates <= straight_line_max_updates;
    return plan;
}

} // namespace yamsc::codegen
