// Which coordinates and speeds the constraints make dependent: the rows' named
// DOFs first, the rest by QR with column pivoting of B; the rank checks that
// find redundant rows and named DOFs that cannot be solved for.
#include "yamsc/constraints.hpp"

#include "rows.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace yamsc::runtime {

using constraints::Matrix;
using constraints::Vector;

namespace {

std::size_t at(int i) {
    return static_cast<std::size_t>(i);
}

Eigen::Index rank_of(const Eigen::MatrixXd& m, double tolerance) {
    if (m.rows() == 0 || m.cols() == 0) return 0;
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(m);
    qr.setThreshold(tolerance);
    return qr.rank();
}

std::string row_name(const ModelView& v, int row) {
    std::string s = "'" + v.constraint_names[at(row)] + "'";
    if (at(row) < v.constraint_sources.size() && !v.constraint_sources[at(row)].empty())
        s += " (" + v.constraint_sources[at(row)] + ")";
    return s;
}

/// The first row (in order) in the span of the rows before it: redundant.
void check_redundant(const ModelView& v, const Matrix& B, double tolerance) {
    for (int i = 0; i < v.nc; ++i) {
        const Eigen::MatrixXd upto = B.topRows(i + 1);
        if (rank_of(upto.transpose(), tolerance) == i + 1) continue;
        // Its coefficients on the rows before it (least squares: they span it).
        const Eigen::MatrixXd before = B.topRows(i).transpose();
        const Eigen::VectorXd c =
            before.completeOrthogonalDecomposition().solve(Eigen::VectorXd(B.row(i).transpose()));
        std::vector<int> related;
        const double cmax = i > 0 ? c.cwiseAbs().maxCoeff() : 0.0;
        for (int j = 0; j < i; ++j)
            if (std::fabs(c[j]) > 1e-8 * cmax) related.push_back(j);
        std::ostringstream msg;
        msg << "constraint row " << row_name(v, i) << " is redundant at the initial state";
        if (related.empty())
            msg << ": it does not depend on any coordinate there";
        else {
            msg << ": it depends on ";
            for (std::size_t k = 0; k < related.size(); ++k)
                msg << (k ? ", " : "") << row_name(v, related[k]);
        }
        throw ConstraintError(ConstraintErrorKind::redundant, i, related, msg.str());
    }
}

/// Completes `chosen` (columns named for rows of `rows`) to rows.rows()
/// columns such that rows[:, chosen] is invertible: the rows' component outside
/// the named columns' span, QR with column pivoting over the others.
void complete(const ModelView& v, const Matrix& rows, std::vector<int>& chosen,
              const std::vector<int>& named_by, double tolerance) {
    const Eigen::Index m = rows.rows();
    const Matrix named = constraints::columns_of(rows, chosen);
    Eigen::MatrixXd complement = Eigen::MatrixXd::Identity(m, m);
    if (!chosen.empty()) {
        Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr{Eigen::MatrixXd(named)};
        qr.setThreshold(tolerance);
        if (qr.rank() < static_cast<Eigen::Index>(chosen.size())) {
            // The named column QR left last cannot be solved for.
            int column = qr.colsPermutation().indices()[qr.rank()];
            // A column the QR chose itself is no one's to blame: the last named one is.
            for (int k = static_cast<int>(chosen.size()) - 1; named_by[at(column)] < 0 && k >= 0;
                 --k)
                column = k;
            const int row = named_by[at(column)];
            if (row < 0)
                throw ConstraintError(ConstraintErrorKind::singular, -1, {},
                                      "the constraints cannot be solved for their dependent "
                                      "DOFs at the initial state (singular)");
            throw ConstraintError(
                ConstraintErrorKind::singular, row, {},
                "constraint row " + row_name(v, row) + " names '" +
                    v.dof_names[at(chosen[at(column)])] +
                    "' dependent, but the rows cannot be solved for it at the initial state "
                    "(singular): name another DOF or none");
        }
        const Eigen::MatrixXd Q = qr.householderQ();
        complement = Q.rightCols(m - static_cast<Eigen::Index>(chosen.size()));
    }
    std::vector<int> rest;
    for (int j = 0; j < v.nq; ++j)
        if (std::find(chosen.begin(), chosen.end(), j) == chosen.end()) rest.push_back(j);
    const Eigen::MatrixXd reduced =
        complement.transpose() * Eigen::MatrixXd(constraints::columns_of(rows, rest));
    const Eigen::Index need = complement.cols();
    if (need == 0) return;
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(reduced);
    qr.setThreshold(tolerance);
    if (qr.rank() < need)
        throw ConstraintError(ConstraintErrorKind::singular, -1, {},
                              "the constraints cannot be solved for any set of dependent DOFs "
                              "at the initial state (singular)");
    for (Eigen::Index k = 0; k < need; ++k)
        chosen.push_back(rest[at(qr.colsPermutation().indices()[k])]);
}

} // namespace

DependentChoice choose_dependent(const ModelView& v, double t, const double* x, const double* u,
                                 const ConstraintOptions& o) {
    constraints::require_rows(v, "choose_dependent");
    const Matrix B = constraints::matrix_b(v, t, x, u);
    check_redundant(v, B, o.rank_tolerance);
    DependentChoice c;
    c.named.assign(at(v.nq), false);
    std::vector<int> named_by;
    const auto name = [&](int row, std::vector<int>& into) {
        const int dof =
            at(row) < v.constraint_dependent.size() ? v.constraint_dependent[at(row)] : -1;
        if (dof < 0) return;
        if (c.named[at(dof)])
            throw ConstraintError(ConstraintErrorKind::singular, row, {},
                                  "constraint row " + row_name(v, row) + " names '" +
                                      v.dof_names[at(dof)] +
                                      "' dependent, which another row names already");
        c.named[at(dof)] = true;
        into.push_back(dof);
        named_by.push_back(row);
    };
    for (int i = 0; i < v.nh; ++i) name(i, c.coordinates);
    complete(v, B.topRows(v.nh), c.coordinates, named_by, o.rank_tolerance);
    c.speeds = c.coordinates;
    // Rows of holonomic coordinates are the first nh: whatever named them stays.
    named_by.resize(c.speeds.size(), -1);
    for (int i = v.nh; i < v.nc; ++i) name(i, c.speeds);
    complete(v, B, c.speeds, named_by, o.rank_tolerance);
    for (int j = 0; j < v.nq; ++j) {
        if (std::find(c.coordinates.begin(), c.coordinates.end(), j) == c.coordinates.end())
            c.independent_coordinates.push_back(j);
        if (std::find(c.speeds.begin(), c.speeds.end(), j) == c.speeds.end())
            c.independent_speeds.push_back(j);
    }
    return c;
}

std::string describe_choice(const ModelView& v, const DependentChoice& c) {
    std::ostringstream out;
    const auto list = [&](const char* what, const std::vector<int>& dofs, bool mark) {
        out << what << ":";
        if (dofs.empty()) out << " (none)";
        for (std::size_t k = 0; k < dofs.size(); ++k) {
            out << (k ? ", " : " ") << v.dof_names[at(dofs[k])];
            if (mark && c.named[at(dofs[k])]) out << " (named)";
        }
        out << "\n";
    };
    list("dependent coordinates", c.coordinates, true);
    list("independent coordinates", c.independent_coordinates, false);
    list("dependent speeds", c.speeds, true);
    list("independent speeds", c.independent_speeds, false);
    return out.str();
}

} // namespace yamsc::runtime
