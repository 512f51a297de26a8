#pragma once
// Test support: IR nodes back as GiNaC expressions over the symbols of the
// equations they were lowered from, for tests that compare the compiler's
// (approximated) equations term by term with printed formulas in GiNaC. The
// compiler itself never converts back: this is a reference path for tests.
#include "ir/system.hpp"
#include "symbolic/equations.hpp"

#include <ginac/ginac.h>

#include <cmath>
#include <stdexcept>
#include <unordered_map>

namespace yamsc::test {

/// Exact where the double is: integers and halves become rationals.
inline GiNaC::ex ginac_number(double v) {
    if (v == std::floor(v) && std::fabs(v) < 1e15) return GiNaC::numeric(static_cast<long>(v));
    if (2 * v == std::floor(2 * v) && std::fabs(v) < 1e15)
        return GiNaC::numeric(static_cast<long>(2 * v), 2);
    return GiNaC::numeric(v);
}

class IrToGinac {
public:
    IrToGinac(const ir::Graph& g, const symbolic::Equations& eq) : g_(g), eq_(eq) {}

    /// The nodes reachable from `id`, once each (small expressions only: GiNaC's
    /// arithmetic walks what it builds as trees).
    GiNaC::ex operator()(ir::NodeId id) {
        if (auto it = done_.find(id); it != done_.end()) return it->second;
        const ir::Node& n = g_.node(id);
        std::vector<std::pair<GiNaC::ex, double>> ops;
        for (const ir::Operand& op : g_.operands(id)) ops.emplace_back((*this)(op.node), op.weight);
        GiNaC::ex r;
        switch (n.kind) {
        case ir::NodeKind::number:
            r = ginac_number(n.value);
            break;
        case ir::NodeKind::symbol:
            r = symbol(n.symbol);
            break;
        case ir::NodeKind::add:
            r = ginac_number(n.value);
            for (const auto& [e, w] : ops) r += ginac_number(w) * e;
            break;
        case ir::NodeKind::mul:
            r = ginac_number(n.value);
            for (const auto& [e, w] : ops) r *= GiNaC::pow(e, ginac_number(w));
            break;
        case ir::NodeKind::call:
            r = call(n.function, ops);
            break;
        }
        return done_.emplace(id, r).first->second;
    }

private:
    GiNaC::ex symbol(ir::SymbolRef s) const {
        const auto i = static_cast<std::size_t>(s.index);
        switch (s.kind) {
        case ir::SymbolKind::time:
            return eq_.t;
        case ir::SymbolKind::q:
            return eq_.dofs.at(i).q;
        case ir::SymbolKind::qd:
            return eq_.dofs.at(i).qd;
        case ir::SymbolKind::qdd:
            return eq_.dofs.at(i).qdd;
        case ir::SymbolKind::input:
            return eq_.inputs.at(i).sym;
        case ir::SymbolKind::param:
            return eq_.params.at(i).sym;
        case ir::SymbolKind::acceleration:
            return eq_.a.at(i);
        case ir::SymbolKind::seed:
        case ir::SymbolKind::multiplier:
            break;
        }
        throw std::runtime_error("ir_to_ginac: a seed or multiplier symbol");
    }

    static GiNaC::ex call(ir::Function f, const std::vector<std::pair<GiNaC::ex, double>>& a) {
        const GiNaC::ex& x = a.at(0).first;
        switch (f) {
        case ir::Function::sin:
            return GiNaC::sin(x);
        case ir::Function::cos:
            return GiNaC::cos(x);
        case ir::Function::tan:
            return GiNaC::tan(x);
        case ir::Function::asin:
            return GiNaC::asin(x);
        case ir::Function::acos:
            return GiNaC::acos(x);
        case ir::Function::atan:
            return GiNaC::atan(x);
        case ir::Function::atan2:
            return GiNaC::atan2(x, a.at(1).first);
        case ir::Function::sinh:
            return GiNaC::sinh(x);
        case ir::Function::cosh:
            return GiNaC::cosh(x);
        case ir::Function::tanh:
            return GiNaC::tanh(x);
        case ir::Function::asinh:
            return GiNaC::asinh(x);
        case ir::Function::acosh:
            return GiNaC::acosh(x);
        case ir::Function::atanh:
            return GiNaC::atanh(x);
        case ir::Function::exp:
            return GiNaC::exp(x);
        case ir::Function::log:
            return GiNaC::log(x);
        case ir::Function::abs:
            return GiNaC::abs(x);
        case ir::Function::sqrt:
            return GiNaC::sqrt(x);
        case ir::Function::pow:
            return GiNaC::pow(x, a.at(1).first);
        }
        throw std::runtime_error("ir_to_ginac: unknown function");
    }

    const ir::Graph& g_;
    const symbolic::Equations& eq_;
    std::unordered_map<ir::NodeId, GiNaC::ex> done_;
};

} // namespace yamsc::test
