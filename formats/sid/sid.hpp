#pragma once
// Standard Input Data (SID) of a modally reduced flexible body (Wallrapp 1994;
// paper Appendix A, C, D3; format in docs/sid-format.md). Plain data: produced by
// the SID reader (sid/reader.hpp) or the beam preprocessor (beam/), consumed by
// the writer and by the symbolic stage.
//
// Conventions (all quantities in body axes, SI units):
//  - A Taylor block T(q) = T0 + sum_k T1_k q_k holds an nrow x ncol matrix; order 0
//    blocks have no T1. Entries are 0-based here, 1-based in files.
//  - Geometric stiffening lives in first-order terms, as in the SID standard:
//    Ct1 = K_gt (unit accelerations), Cr1 = physical + K_gr, Oe1 = physical + K_gw,
//    node phi1 = d2u/dq dq of the node (K_gF: the axial shortening that makes the
//    loads carried at a node soften or stiffen the body). docs/theory.md derives them.
#include <array>
#include <string>
#include <vector>

namespace yamsc::sid {

struct Taylor {
    int order = 0;          // 0 or 1
    int nrow = 0;           // rows of the matrix
    int ncol = 0;           // columns of the matrix
    int nq = 0;             // elastic coordinates (size of the first-order expansion)
    int nqn = 0;            // kept for the file format; always 0 here
    int structure = 3;      // in files: 3 full, 2 symmetric (j <= i listed), 1 diagonal, 0 zero
    std::vector<double> m0; // nrow*ncol, row-major
    std::vector<double> m1; // nrow*ncol*nq when order == 1: index ((i*ncol)+j)*nq+k

    static Taylor zeros(int order, int nrow, int ncol, int nq, int structure = 3);
    double& at0(int i, int j) { return m0[static_cast<std::size_t>(i * ncol + j)]; }
    double at0(int i, int j) const { return m0[static_cast<std::size_t>(i * ncol + j)]; }
    double& at1(int i, int j, int k) {
        return m1[static_cast<std::size_t>((i * ncol + j) * nq + k)];
    }
    double at1(int i, int j, int k) const {
        return m1[static_cast<std::size_t>((i * ncol + j) * nq + k)];
    }
    bool operator==(const Taylor& o) const;
    bool operator!=(const Taylor& o) const { return !(*this == o); }
};

/// A node (marker) of the body: a point where loads act and children attach.
struct Node {
    int id = 0;                      // the number after `new node =`
    std::string rframe = "body ref"; // reference frame named in the file
    Taylor origin; // 3 x 1: undeformed position (m0) and its first-order term (m1 = phi0)
    Taylor phi;    // 3 x nq: translational shape functions at the node (m1: see above)
    Taylor psi;    // 3 x nq: rotational shape functions (small rotation per unit q)
    Taylor ap;     // 3 x 3: orientation of the node frame (m1: psi as skew matrices)
    bool has_sigma = false;
    Taylor sigma; // 6 x n: stresses (optional; welib writes 6 x 1; carried through, not used)
    bool operator==(const Node& o) const;
};

struct Sid {
    double mass = 0;
    int nq = 0;
    std::vector<std::string> mode_names; // ielastq(k), k = 1..nq
    std::vector<Node> nodes;             // in file order
    Taylor md_cm;                        // 3 x 1: first moment of mass (mass * centre of mass)
    Taylor J;                            // 3 x 3: inertia tensor about the body origin
    Taylor Ct;                           // nq x 3
    Taylor Cr;                           // nq x 3
    Taylor Me;                           // nq x nq
    Taylor Gr;                           // 3 x 3nq
    Taylor Ge;                           // nq x 3nq
    Taylor Oe;                           // nq x 6: columns xx, yy, zz, xy+yx, yz+zy, xz+zx
    Taylor ksigma;                       // nq x 1
    Taylor Ke;                           // nq x nq
    Taylor De;                           // nq x nq
    bool operator==(const Sid& o) const;
    bool operator!=(const Sid& o) const { return !(*this == o); }
};

} // namespace yamsc::sid
