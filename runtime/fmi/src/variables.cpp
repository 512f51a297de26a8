#include "yamsc/fmi/variables.hpp"

#include "yamsc/fmi/unit.hpp"

#include <stdexcept>
#include <utility>

namespace yamsc::fmi {
namespace {

std::string doc(const std::vector<std::string>& docs, std::size_t i) {
    return i < docs.size() ? docs[i] : std::string();
}

class TableBuilder {
public:
    explicit TableBuilder(std::vector<Variable>& out) : out_(out) {}

    Variable& add(std::string name, Role role, int index, Causality causality,
                  Variability variability, Initial initial, double start, std::string description) {
        Variable v;
        v.name = std::move(name);
        v.value_reference = static_cast<std::uint32_t>(out_.size());
        v.causality = causality;
        v.variability = variability;
        v.initial = initial;
        v.start = start;
        v.description = std::move(description);
        v.role = role;
        v.index = index;
        out_.push_back(std::move(v));
        return out_.back();
    }

private:
    std::vector<Variable>& out_;
};

} // namespace

std::int32_t method_code(runtime::Method method) {
    switch (method) {
    case runtime::Method::rk4:
        return 0;
    case runtime::Method::abm4:
        return 1;
    case runtime::Method::cvode:
        return 2;
    }
    return -1;
}

std::optional<runtime::Method> method_of_code(std::int32_t code) {
    for (runtime::Method m : {runtime::Method::rk4, runtime::Method::abm4, runtime::Method::cvode})
        if (method_code(m) == code) return m;
    return std::nullopt;
}

UnitLayout layout_of(const runtime::ModelView& view, std::vector<std::string> param_names,
                     std::vector<double> param_values) {
    if (param_names.size() != param_values.size())
        throw std::invalid_argument("layout_of: one value per parameter name");
    UnitLayout l;
    l.dof_names = view.dof_names;
    l.block_state_names = view.block_state_names;
    l.input_names = view.input_names;
    l.output_names = view.output_names;
    l.param_names = std::move(param_names);
    l.param_values = std::move(param_values);
    l.initial_state.assign(static_cast<std::size_t>(2 * view.nq), 0.0);
    l.initial_state.insert(l.initial_state.end(), view.block_initial_states.begin(),
                           view.block_initial_states.end());
    return l;
}

UnitLayout unit_layout(const UnitModel& unit, const runtime::ModelView& view,
                       const std::vector<double>& params) {
    UnitLayout l = layout_of(view, unit.param_names, params);
    const UnitSettings& s = unit.settings;
    if (!s.initial_state.empty()) {
        if (s.initial_state.size() != static_cast<std::size_t>(2 * view.nq))
            throw std::invalid_argument("the unit's initial state has " +
                                        std::to_string(s.initial_state.size()) +
                                        " values, not 2 nq = " + std::to_string(2 * view.nq));
        std::copy(s.initial_state.begin(), s.initial_state.end(), l.initial_state.begin());
    }
    l.method = s.method;
    l.step = s.step;
    return l;
}

std::vector<Variable> variables(const UnitLayout& l) {
    const std::size_t nq = l.dof_names.size(), nz = l.block_state_names.size();
    if (l.initial_state.size() != 2 * nq + nz)
        throw std::invalid_argument("variables: the initial state has " +
                                    std::to_string(l.initial_state.size()) +
                                    " values, not 2 nq + nz = " + std::to_string(2 * nq + nz));
    if (l.param_values.size() != l.param_names.size())
        throw std::invalid_argument("variables: one start value per parameter");
    std::vector<Variable> out;
    TableBuilder t(out);
    using C = Causality;
    using V = Variability;
    using I = Initial;
    t.add("time", Role::time, 0, C::independent, V::continuous, I::none, 0.0,
          "simulation time [s]");

    const auto q0 = static_cast<std::uint32_t>(out.size());
    for (std::size_t i = 0; i < nq; ++i)
        t.add(l.dof_names[i], Role::position, static_cast<int>(i), C::local, V::continuous,
              I::exact, l.initial_state[i], doc(l.dof_docs, i));
    const auto qd0 = static_cast<std::uint32_t>(out.size());
    for (std::size_t i = 0; i < nq; ++i)
        t.add(l.dof_names[i] + "'", Role::rate, static_cast<int>(i), C::local, V::continuous,
              I::exact, l.initial_state[nq + i], "rate of " + l.dof_names[i])
            .derivative_of = q0 + static_cast<std::uint32_t>(i);
    const auto z0 = static_cast<std::uint32_t>(out.size());
    for (std::size_t i = 0; i < nz; ++i)
        t.add(l.block_state_names[i], Role::block_state, static_cast<int>(i), C::local,
              V::continuous, I::exact, l.initial_state[2 * nq + i], "state of a load block");
    for (std::size_t i = 0; i < nq; ++i)
        t.add(l.dof_names[i] + "''", Role::acceleration, static_cast<int>(i), C::local,
              V::continuous, I::calculated, 0.0, "acceleration of " + l.dof_names[i])
            .derivative_of = qd0 + static_cast<std::uint32_t>(i);
    for (std::size_t i = 0; i < nz; ++i)
        t.add("der(" + l.block_state_names[i] + ")", Role::block_rate, static_cast<int>(i),
              C::local, V::continuous, I::calculated, 0.0, "rate of " + l.block_state_names[i])
            .derivative_of = z0 + static_cast<std::uint32_t>(i);

    for (std::size_t i = 0; i < l.input_names.size(); ++i)
        t.add(l.input_names[i], Role::input, static_cast<int>(i), C::input, V::continuous, I::none,
              0.0, doc(l.input_docs, i));
    for (std::size_t i = 0; i < l.param_names.size(); ++i) {
        const bool tunable =
            l.param_tunable.empty() || (i < l.param_tunable.size() && l.param_tunable[i]);
        t.add(l.param_names[i], Role::parameter, static_cast<int>(i), C::parameter,
              tunable ? V::tunable : V::fixed, I::exact, l.param_values[i], doc(l.param_docs, i));
    }
    for (std::size_t i = 0; i < l.output_names.size(); ++i)
        t.add(l.output_names[i], Role::output, static_cast<int>(i), C::output, V::continuous,
              I::calculated, 0.0, doc(l.output_docs, i));

    t.add("yamsc.method", Role::method, 0, C::parameter, V::fixed, I::exact,
          static_cast<double>(method_code(l.method)),
          "co-simulation integrator: 0 RK4, 1 ABM4, 2 CVODE")
        .type = ValueType::int32;
    t.add("yamsc.step", Role::step, 0, C::parameter, V::fixed, I::exact, l.step,
          "co-simulation internal step (RK4, ABM4: the step; CVODE: the largest step, 0 free) [s]");
    return out;
}

} // namespace yamsc::fmi
