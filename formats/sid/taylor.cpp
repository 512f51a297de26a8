#include "sid/sid.hpp"

namespace yamsc::sid {

Taylor Taylor::zeros(int order, int nrow, int ncol, int nq, int structure) {
    Taylor t;
    t.order = order;
    t.nrow = nrow;
    t.ncol = ncol;
    t.nq = nq;
    t.structure = structure;
    t.m0.assign(static_cast<std::size_t>(nrow * ncol), 0.0);
    if (order == 1) t.m1.assign(static_cast<std::size_t>(nrow * ncol * nq), 0.0);
    return t;
}

bool Taylor::operator==(const Taylor& o) const {
    return order == o.order && nrow == o.nrow && ncol == o.ncol && nq == o.nq && nqn == o.nqn &&
           m0 == o.m0 && m1 == o.m1;
}

bool Node::operator==(const Node& o) const {
    return id == o.id && rframe == o.rframe && origin == o.origin && phi == o.phi && psi == o.psi &&
           ap == o.ap && has_sigma == o.has_sigma && (!has_sigma || sigma == o.sigma);
}

bool Sid::operator==(const Sid& o) const {
    return mass == o.mass && nq == o.nq && mode_names == o.mode_names && nodes == o.nodes &&
           md_cm == o.md_cm && J == o.J && Ct == o.Ct && Cr == o.Cr && Me == o.Me && Gr == o.Gr &&
           Ge == o.Ge && Oe == o.Oe && ksigma == o.ksigma && Ke == o.Ke && De == o.De;
}

} // namespace yamsc::sid
