#include "instance.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace yamsc::fmi {
namespace {

const char* mode_name(Mode m) {
    switch (m) {
    case Mode::instantiated:
        return "Instantiated";
    case Mode::initialization:
        return "Initialization Mode";
    case Mode::event:
        return "Event Mode";
    case Mode::continuous_time:
        return "Continuous-Time Mode";
    case Mode::step:
        return "Step Mode";
    case Mode::terminated:
        return "Terminated";
    }
    return "?";
}

const char* category(Status s) {
    return s >= Status::error ? "logStatusError"
           : s == Status::ok  ? "logEvents"
                              : "logStatusWarning";
}

} // namespace

Instance::Instance(const UnitModel& unit, Interface interface, std::string name,
                   std::string resources, Logger logger, bool logging_on)
    : unit_(unit), interface_(interface), name_(std::move(name)), resources_(std::move(resources)),
      logger_(std::move(logger)), logging_on_(logging_on) {
    p_ = unit_.param_defaults;
    make_view();
    table_ = variables(unit_layout(unit_, view_, p_));
    nq_ = static_cast<std::size_t>(view_.nq);
    nz_ = static_cast<std::size_t>(view_.nz);
    start_values();
}

Instance::~Instance() = default;

void Instance::make_view() {
    view_ = unit_.make_view(p_.data());
    if (unit_.settings.close_blocks) view_ = unit_.settings.close_blocks(view_, resources_, p_);
    if (!view_.rhs) throw std::runtime_error("the model has no right-hand side");
    if (!table_.empty() &&
        (static_cast<std::size_t>(view_.nq) != nq_ || static_cast<std::size_t>(view_.nz) != nz_))
        throw std::runtime_error("the model's states changed with its parameters");
    view_params_ = p_;
    view_stale_ = false;
}

// Every number back to its start value (instantiation and Reset).
void Instance::start_values() {
    p_ = unit_.param_defaults;
    t_ = 0.0;
    x_.assign(nq_ * 2 + nz_, 0.0);
    u_.assign(static_cast<std::size_t>(view_.nu), 0.0);
    for (const Variable& v : table_) {
        const auto i = static_cast<std::size_t>(v.index);
        switch (v.role) {
        case Role::position:
            x_[i] = v.start;
            break;
        case Role::rate:
            x_[nq_ + i] = v.start;
            break;
        case Role::block_state:
            x_[2 * nq_ + i] = v.start;
            break;
        case Role::input:
            u_[i] = v.start;
            break;
        case Role::parameter:
            p_[i] = v.start;
            break;
        case Role::method:
            method_ = method_of_code(static_cast<std::int32_t>(v.start)).value();
            break;
        case Role::step:
            step_ = v.start;
            break;
        default:
            break;
        }
    }
    tolerance_.reset();
    view_stale_ = p_ != view_params_;
    mode_ = Mode::instantiated;
    changed(true);
}

// Drops what was evaluated at the old numbers; a change of states or time
// outside a step also drops the integrators' history.
void Instance::changed(bool states_or_time) {
    xdot_known_ = y_known_ = false;
    if (states_or_time || view_stale_) abm4_.reset();
}

void Instance::refresh_view() {
    if (view_stale_) {
        make_view();
        abm4_.reset();
    }
}

Status Instance::log(Status status, const std::string& message) const {
    if (logger_ && (logging_on_ || status >= Status::error))
        logger_(status, category(status), message);
    return status;
}

bool Instance::allowed(const char* what, std::initializer_list<Mode> modes) const {
    if (std::find(modes.begin(), modes.end(), mode_) != modes.end()) return true;
    log(Status::error, std::string(what) + " is not allowed in " + mode_name(mode_));
    return false;
}

Status Instance::enter_initialization(std::optional<double> tolerance, double start_time,
                                      std::optional<double> stop_time) {
    if (!allowed("EnterInitializationMode", {Mode::instantiated})) return Status::error;
    if (!std::isfinite(start_time)) return fail("the start time is not finite");
    if (stop_time && !(*stop_time >= start_time))
        return fail("the stop time is before the start time");
    if (tolerance && !(*tolerance > 0.0)) return fail("the tolerance must be positive");
    tolerance_ = tolerance;
    t_ = start_time;
    mode_ = Mode::initialization;
    changed(true);
    return Status::ok;
}

Status Instance::exit_initialization() {
    if (!allowed("ExitInitializationMode", {Mode::initialization})) return Status::error;
    if (!(step_ > 0.0) && method_ != runtime::Method::cvode)
        return fail("yamsc.step must be positive for RK4 and ABM4");
    if (step_ < 0.0 || !std::isfinite(step_))
        return fail("yamsc.step must be finite, not negative");
    refresh_view();
    mode_ = interface_ == Interface::model_exchange ? Mode::event : Mode::step;
    accept_point();
    return Status::ok;
}

Status Instance::enter_event_mode() {
    if (interface_ != Interface::model_exchange)
        return fail("EnterEventMode: this co-simulation instance has no event mode");
    if (!allowed("EnterEventMode", {Mode::continuous_time, Mode::event})) return Status::error;
    mode_ = Mode::event;
    return Status::ok;
}

Status Instance::enter_continuous_time_mode() {
    if (!allowed("EnterContinuousTimeMode", {Mode::event})) return Status::error;
    if (interface_ != Interface::model_exchange)
        return fail("EnterContinuousTimeMode: not a model exchange instance");
    refresh_view();
    mode_ = Mode::continuous_time;
    return Status::ok;
}

Status Instance::enter_step_mode() {
    if (interface_ != Interface::co_simulation)
        return fail("EnterStepMode: not a co-simulation instance");
    if (!allowed("EnterStepMode", {Mode::event})) return Status::error;
    mode_ = Mode::step;
    return Status::ok;
}

Status Instance::update_discrete_states() {
    if (!allowed("UpdateDiscreteStates", {Mode::event})) return Status::error;
    refresh_view();
    return Status::ok;
}

Status Instance::terminate() {
    if (!allowed("Terminate",
                 {Mode::event, Mode::continuous_time, Mode::step, Mode::initialization}))
        return Status::error;
    mode_ = Mode::terminated;
    return Status::ok;
}

Status Instance::reset() {
    start_values();
    rk4_.reset();
    return Status::ok;
}

const Variable* Instance::variable(std::uint32_t vr, const char* function) const {
    if (vr < table_.size()) return &table_[vr];
    log(Status::error,
        std::string(function) + ": no variable has the value reference " + std::to_string(vr));
    return nullptr;
}

const std::vector<double>& Instance::derivatives() {
    if (!xdot_known_) {
        refresh_view();
        xdot_.resize(x_.size());
        view_.rhs(t_, x_.data(), u_.data(), xdot_.data());
        xdot_known_ = true;
    }
    return xdot_;
}

const std::vector<double>& Instance::outputs() {
    if (!y_known_) {
        refresh_view();
        y_.resize(static_cast<std::size_t>(view_.ny));
        if (view_.ny > 0) view_.outputs(t_, x_.data(), x_.data() + nq_, u_.data(), y_.data());
        y_known_ = true;
    }
    return y_;
}

Status Instance::get_float64(const std::uint32_t* vrs, std::size_t n, double* values) {
    if (!allowed("GetFloat64", {Mode::instantiated, Mode::initialization, Mode::event,
                                Mode::continuous_time, Mode::step, Mode::terminated}))
        return Status::error;
    for (std::size_t k = 0; k < n; ++k) {
        const Variable* v = variable(vrs[k], "GetFloat64");
        if (!v) return Status::error;
        const auto i = static_cast<std::size_t>(v->index);
        switch (v->role) {
        case Role::time:
            values[k] = t_;
            break;
        case Role::position:
            values[k] = x_[i];
            break;
        case Role::rate:
            values[k] = x_[nq_ + i];
            break;
        case Role::block_state:
            values[k] = x_[2 * nq_ + i];
            break;
        case Role::acceleration:
            values[k] = derivatives()[nq_ + i];
            break;
        case Role::block_rate:
            values[k] = derivatives()[2 * nq_ + i];
            break;
        case Role::input:
            values[k] = u_[i];
            break;
        case Role::parameter:
            values[k] = p_[i];
            break;
        case Role::output:
            values[k] = outputs()[i];
            break;
        case Role::step:
            values[k] = step_;
            break;
        case Role::method:
            return fail("GetFloat64: " + v->name + " is an Int32");
        }
    }
    return Status::ok;
}

Status Instance::check_settable(const Variable& v) const {
    const bool before = mode_ == Mode::instantiated || mode_ == Mode::initialization;
    switch (v.causality) {
    case Causality::input:
        if (mode_ != Mode::terminated) return Status::ok;
        break;
    case Causality::parameter:
        if (before) return Status::ok;
        if (v.variability == Variability::tunable && (mode_ == Mode::event || mode_ == Mode::step))
            return Status::ok;
        break;
    case Causality::local:
        if (before && v.initial == Initial::exact) return Status::ok;
        break;
    default:
        break;
    }
    return fail("Set: " + v.name + " cannot be set in " + mode_name(mode_));
}

Status Instance::set_float64(const std::uint32_t* vrs, std::size_t n, const double* values) {
    if (!allowed("SetFloat64", {Mode::instantiated, Mode::initialization, Mode::event,
                                Mode::continuous_time, Mode::step}))
        return Status::error;
    for (std::size_t k = 0; k < n; ++k) {
        const Variable* v = variable(vrs[k], "SetFloat64");
        if (!v) return Status::error;
        if (v->type != ValueType::float64) return fail("SetFloat64: " + v->name + " is an Int32");
        if (check_settable(*v) != Status::ok) return Status::error;
        if (!std::isfinite(values[k])) return fail("SetFloat64: " + v->name + " must be finite");
        const auto i = static_cast<std::size_t>(v->index);
        switch (v->role) {
        case Role::position:
            x_[i] = values[k];
            break;
        case Role::rate:
            x_[nq_ + i] = values[k];
            break;
        case Role::block_state:
            x_[2 * nq_ + i] = values[k];
            break;
        case Role::input:
            u_[i] = values[k];
            break;
        case Role::parameter:
            if (p_[i] != values[k]) view_stale_ = true;
            p_[i] = values[k];
            break;
        case Role::step:
            step_ = values[k];
            break;
        default:
            return fail("SetFloat64: " + v->name + " cannot be set");
        }
        changed(v->causality == Causality::local);
    }
    return Status::ok;
}

Status Instance::get_int32(const std::uint32_t* vrs, std::size_t n, std::int32_t* values) {
    if (!allowed("GetInt32", {Mode::instantiated, Mode::initialization, Mode::event,
                              Mode::continuous_time, Mode::step, Mode::terminated}))
        return Status::error;
    for (std::size_t k = 0; k < n; ++k) {
        const Variable* v = variable(vrs[k], "GetInt32");
        if (!v) return Status::error;
        if (v->role != Role::method) return fail("GetInt32: " + v->name + " is not an Int32");
        values[k] = method_code(method_);
    }
    return Status::ok;
}

Status Instance::set_int32(const std::uint32_t* vrs, std::size_t n, const std::int32_t* values) {
    if (!allowed("SetInt32", {Mode::instantiated, Mode::initialization, Mode::event,
                              Mode::continuous_time, Mode::step}))
        return Status::error;
    for (std::size_t k = 0; k < n; ++k) {
        const Variable* v = variable(vrs[k], "SetInt32");
        if (!v) return Status::error;
        if (v->role != Role::method) return fail("SetInt32: " + v->name + " is not an Int32");
        if (check_settable(*v) != Status::ok) return Status::error;
        const auto m = method_of_code(values[k]);
        if (!m)
            return fail("SetInt32: yamsc.method is 0 (RK4), 1 (ABM4) or 2 (CVODE), not " +
                        std::to_string(values[k]));
        method_ = *m;
        abm4_.reset();
    }
    return Status::ok;
}

Status Instance::set_time(double t) {
    if (!allowed("SetTime", {Mode::event, Mode::continuous_time})) return Status::error;
    if (!std::isfinite(t)) return fail("SetTime: the time is not finite");
    t_ = t;
    changed(true);
    return Status::ok;
}

Status Instance::set_continuous_states(const double* x, std::size_t n) {
    if (!allowed("SetContinuousStates", {Mode::event, Mode::continuous_time})) return Status::error;
    if (n != x_.size())
        return fail("SetContinuousStates: " + std::to_string(n) + " states given, the model has " +
                    std::to_string(x_.size()));
    for (std::size_t i = 0; i < n; ++i)
        if (!std::isfinite(x[i]))
            return fail("SetContinuousStates: state " + std::to_string(i) + " is not finite");
    std::copy(x, x + n, x_.begin());
    changed(true);
    return Status::ok;
}

Status Instance::get_continuous_states(double* x, std::size_t n) {
    if (!allowed("GetContinuousStates",
                 {Mode::initialization, Mode::event, Mode::continuous_time, Mode::terminated}))
        return Status::error;
    if (n != x_.size())
        return fail("GetContinuousStates: the model has " + std::to_string(x_.size()) + " states");
    std::copy(x_.begin(), x_.end(), x);
    return Status::ok;
}

Status Instance::get_derivatives(double* xdot, std::size_t n) {
    if (!allowed("GetContinuousStateDerivatives",
                 {Mode::initialization, Mode::event, Mode::continuous_time, Mode::terminated}))
        return Status::error;
    if (n != x_.size())
        return fail("GetContinuousStateDerivatives: the model has " + std::to_string(x_.size()) +
                    " states");
    const std::vector<double>& d = derivatives();
    std::copy(d.begin(), d.end(), xdot);
    return Status::ok;
}

Status Instance::get_nominals(double* nominals, std::size_t n) {
    if (!allowed("GetNominalsOfContinuousStates",
                 {Mode::instantiated, Mode::initialization, Mode::event, Mode::continuous_time,
                  Mode::terminated}))
        return Status::error;
    if (n != x_.size())
        return fail("GetNominalsOfContinuousStates: the model has " + std::to_string(x_.size()) +
                    " states");
    std::fill(nominals, nominals + n, 1.0);
    return Status::ok;
}

// The point the blocks' discrete states are advanced from at the next accepted step.
void Instance::accept_point() {
    t_accepted_ = t_;
    x_accepted_ = x_;
    u_accepted_ = u_;
}

Status Instance::completed_integrator_step() {
    if (!allowed("CompletedIntegratorStep", {Mode::continuous_time})) return Status::error;
    if (view_.project) {
        view_.project(t_, x_.data(), u_.data());
        changed(true);
    }
    if (view_.update_discrete) {
        view_.update_discrete(t_accepted_, x_accepted_.data(), u_accepted_.data(), t_, x_.data(),
                              u_.data());
        changed(false);
    }
    accept_point();
    return Status::ok;
}

} // namespace yamsc::fmi
