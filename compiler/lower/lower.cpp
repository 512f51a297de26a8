#include "lower/lower.hpp"

#include "diag/diagnostics.hpp"
#include "lower/from_ginac.hpp"

#include <string>

namespace yamsc::lower {
namespace {

ir::Row import_row(GinacImporter& importer, const symbolic::Row& row) {
    ir::Row out;
    out.reserve(row.size());
    for (const GiNaC::ex& e : row) out.push_back(importer.import(e));
    return out;
}

ir::System lower_with(const symbolic::Equations& eq, const symbolic::OperatingPoint* point) {
    ir::System s;
    s.model_name = eq.model_name;
    s.title = eq.title;
    s.source_path = eq.source_path;
    s.source_digest = eq.source_digest;
    for (const symbolic::Dof& d : eq.dofs) s.dofs.push_back({d.name, d.doc});
    for (const symbolic::InputChannel& u : eq.inputs) s.inputs.push_back({u.name, u.c_name, u.doc});
    for (const symbolic::Parameter& p : eq.params) s.params.push_back({p.name, p.doc, p.value});
    s.graph = ir::Graph(4, ir::Variables{eq.nq(), eq.nu(), eq.np()});

    const std::size_t nq = eq.dofs.size();
    auto malformed = [](const std::string& what) {
        throw diag::InternalError("malformed equations: " + what);
    };
    if (eq.F.size() != nq) malformed("F does not have nq entries");
    for (const symbolic::Row& row : eq.M)
        if (row.size() != nq || eq.M.size() != nq) malformed("M is not nq x nq");
    if (!eq.Ma.empty() && (eq.Ma.size() != nq || eq.a.size() != nq))
        malformed("M a does not have nq entries over nq symbols `a`");

    GinacImporter importer(s.graph, eq);
    for (const symbolic::Row& row : eq.M) s.M.push_back(import_row(importer, row));
    s.F = import_row(importer, eq.F);
    s.Ma = import_row(importer, eq.Ma);
    for (const symbolic::Output& y : eq.outputs)
        s.outputs.push_back(
            {y.name, y.doc, importer.import(y.value), import_row(importer, y.dqdd)});
    for (const symbolic::ConstraintRow& c : eq.constraints)
        s.constraints.push_back({c.name, c.holonomic, c.dependent, c.source, importer.import(c.phi),
                                 importer.import(c.r), importer.import(c.r_t)});
    if (point != nullptr) {
        s.point.q = import_row(importer, point->q);
        s.point.qd = import_row(importer, point->qd);
        s.point.u = import_row(importer, point->u);
        s.point.declared = point->declared;
    } else {
        const ir::NodeId zero = s.graph.number(0.0);
        s.point.q.assign(nq, zero);
        s.point.qd.assign(nq, zero);
        s.point.u.assign(eq.inputs.size(), zero);
    }
    return s;
}

} // namespace

ir::System lower(const symbolic::Equations& eq) {
    return lower_with(eq, nullptr);
}

ir::System lower(const symbolic::Equations& eq, const symbolic::OperatingPoint& point) {
    return lower_with(eq, &point);
}

} // namespace yamsc::lower
