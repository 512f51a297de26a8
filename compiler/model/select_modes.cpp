#include "model/flexible.hpp"

namespace yamsc::model {

namespace {

/// How a Taylor block's dimensions depend on the modes.
enum class Dim { fixed, modes, modes3 }; // modes3: 3 columns per mode (Gr, Ge)

/// Index map of one dimension: new index -> old index.
std::vector<int> dim_map(Dim d, int old_size, const std::vector<int>& keep) {
    std::vector<int> map;
    if (d == Dim::fixed) {
        for (int i = 0; i < old_size; ++i) map.push_back(i);
    } else if (d == Dim::modes) {
        map = keep;
    } else {
        for (int k : keep)
            for (int c = 0; c < 3; ++c) map.push_back(3 * k + c);
    }
    return map;
}

sid::Taylor reduce(const sid::Taylor& t, Dim rows, Dim cols, const std::vector<int>& keep) {
    std::vector<int> r = dim_map(rows, t.nrow, keep), c = dim_map(cols, t.ncol, keep);
    int nq = static_cast<int>(keep.size());
    sid::Taylor out = sid::Taylor::zeros(t.order, static_cast<int>(r.size()),
                                         static_cast<int>(c.size()), nq, t.structure);
    out.nqn = t.nqn;
    for (std::size_t i = 0; i < r.size(); ++i)
        for (std::size_t j = 0; j < c.size(); ++j) {
            int ii = static_cast<int>(i), jj = static_cast<int>(j);
            out.at0(ii, jj) = t.at0(r[i], c[j]);
            if (t.order == 1)
                for (int k = 0; k < nq; ++k)
                    out.at1(ii, jj, k) = t.at1(r[i], c[j], keep[static_cast<std::size_t>(k)]);
        }
    return out;
}

} // namespace

sid::Sid select_modes(const sid::Sid& s, const std::vector<int>& keep) {
    sid::Sid out;
    out.mass = s.mass;
    out.nq = static_cast<int>(keep.size());
    for (int k : keep)
        out.mode_names.push_back(static_cast<std::size_t>(k) < s.mode_names.size()
                                     ? s.mode_names[static_cast<std::size_t>(k)]
                                     : "mode " + std::to_string(k + 1));
    for (const auto& n : s.nodes) {
        sid::Node m = n;
        m.origin = reduce(n.origin, Dim::fixed, Dim::fixed, keep);
        m.phi = reduce(n.phi, Dim::fixed, Dim::modes, keep);
        m.psi = reduce(n.psi, Dim::fixed, Dim::modes, keep);
        m.ap = reduce(n.ap, Dim::fixed, Dim::fixed, keep);
        if (n.has_sigma) m.sigma = reduce(n.sigma, Dim::fixed, Dim::modes, keep);
        out.nodes.push_back(std::move(m));
    }
    out.md_cm = reduce(s.md_cm, Dim::fixed, Dim::fixed, keep);
    out.J = reduce(s.J, Dim::fixed, Dim::fixed, keep);
    out.Ct = reduce(s.Ct, Dim::modes, Dim::fixed, keep);
    out.Cr = reduce(s.Cr, Dim::modes, Dim::fixed, keep);
    out.Me = reduce(s.Me, Dim::modes, Dim::modes, keep);
    out.Gr = reduce(s.Gr, Dim::fixed, Dim::modes3, keep);
    out.Ge = reduce(s.Ge, Dim::modes, Dim::modes3, keep);
    out.Oe = reduce(s.Oe, Dim::modes, Dim::fixed, keep);
    out.ksigma = reduce(s.ksigma, Dim::modes, Dim::fixed, keep);
    out.Ke = reduce(s.Ke, Dim::modes, Dim::modes, keep);
    out.De = reduce(s.De, Dim::modes, Dim::modes, keep);
    return out;
}

} // namespace yamsc::model
