#pragma once
// The algebra of loads linear in the accelerations (LoadBlock::added_mass):
// with the model's M q'' = F(u + l0 - A G^T q''), where G = dF/d(loads), the
// accelerations the block's loads see, s = G^T q'', solve
//     (I + G^T W A) s = G^T q''_0,   W = M^-1 G,  q''_0 = M^-1 F(u + l0),
// and the loads applied are l0 - A s (then M q'' = F gives the same q'' as
// (M + G A G^T) q'' = F(u + l0)). Only nl x nl is factored: nl is a body's 6.
#include <vector>

namespace yamsc::runtime::detail {

struct AddedMassTerms {
    int nq = 0, nl = 0;
    std::vector<double> W; // M^-1 G, nq x nl row-major
    std::vector<double> G; // M W, nq x nl row-major
};

/// W from the base's q'' at the loads l0 (qdd0) and at each load stepped by h_k
/// (qdd_k, k = 0..nl-1): the model is affine in its load inputs, so the
/// difference quotients are its columns; G = M W with M (nq x nq).
AddedMassTerms added_mass_terms(int nq, int nl, const double* M, const std::vector<double>& qdd0,
                                const std::vector<std::vector<double>>& qdd_k,
                                const std::vector<double>& h);

/// s = G^T q'' of the coupled solution, from q''_0 and A (nl x nl).
std::vector<double> coupled_accelerations(const AddedMassTerms& t, const double* A,
                                          const std::vector<double>& qdd0);

/// The mass matrix with the added mass, M + G A G^T (nq x nq, in place).
void add_added_mass(const AddedMassTerms& t, const double* A, double* M);

} // namespace yamsc::runtime::detail
