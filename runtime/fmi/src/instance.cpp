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
    n_.p = unit_.param_defaults;
    make_view();
    table_ = variables(unit_layout(unit_, view_, n_.p));
    nq_ = static_cast<std::size_t>(view_.nq);
    nz_ = static_cast<std::size_t>(view_.nz);
    start_values();
}

Instance::~Instance() = default;

void Instance::make_view() {
    view_ = unit_.make_view(n_.p.data());
    if (unit_.settings.close_blocks) view_ = unit_.settings.close_blocks(view_, resources_, n_.p);
    if (!view_.rhs) throw std::runtime_error("the model has no right-hand side");
    if (!table_.empty() &&
        (static_cast<std::size_t>(view_.nq) != nq_ || static_cast<std::size_t>(view_.nz) != nz_))
        throw std::runtime_error("the model's states changed with its parameters");
    view_params_ = n_.p;
    view_stale_ = false;
}

// Every number back to its start value (instantiation and Reset).
void Instance::start_values() {
    n_ = Numbers{};
    n_.p = unit_.param_defaults;
    n_.x.assign(nq_ * 2 + nz_, 0.0);
    n_.u.assign(static_cast<std::size_t>(view_.nu), 0.0);
    for (const Variable& v : table_) {
        if (v.role == Role::method)
            n_.method = method_of_code(static_cast<std::int32_t>(v.start)).value();
        else if (double* place = stored(v))
            *place = v.start;
    }
    view_stale_ = n_.p != view_params_;
    // The blocks' discrete states as at the start of a run (Reset after a run).
    if (view_.reset_discrete) view_.reset_discrete();
    changed(true);
}

std::optional<std::size_t> Instance::state_index(const Variable& v) const {
    const auto i = static_cast<std::size_t>(v.index);
    switch (v.role) {
    case Role::position:
        return i;
    case Role::rate:
        return nq_ + i;
    case Role::block_state:
        return 2 * nq_ + i;
    default:
        return std::nullopt;
    }
}

std::optional<std::size_t> Instance::derivative_index(const Variable& v) const {
    const auto i = static_cast<std::size_t>(v.index);
    switch (v.role) {
    case Role::rate:
        return i;
    case Role::acceleration:
        return nq_ + i;
    case Role::block_rate:
        return 2 * nq_ + i;
    default:
        return std::nullopt;
    }
}

double* Instance::stored(const Variable& v) {
    const auto i = static_cast<std::size_t>(v.index);
    if (const auto k = state_index(v)) return &n_.x[*k];
    switch (v.role) {
    case Role::input:
        return &n_.u[i];
    case Role::parameter:
        return &n_.p[i];
    case Role::step:
        return &n_.step;
    default:
        return nullptr;
    }
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
    if (std::find(modes.begin(), modes.end(), n_.mode) != modes.end()) return true;
    log(Status::error, std::string(what) + " is not allowed in " + mode_name(n_.mode));
    return false;
}

Status Instance::enter_initialization(std::optional<double> tolerance, double start_time,
                                      std::optional<double> stop_time) {
    if (!allowed("EnterInitializationMode", {Mode::instantiated})) return Status::error;
    if (!std::isfinite(start_time)) return fail("the start time is not finite");
    if (stop_time && !(*stop_time >= start_time))
        return fail("the stop time is before the start time");
    if (tolerance && !(*tolerance > 0.0)) return fail("the tolerance must be positive");
    n_.tolerance = tolerance;
    n_.t = start_time;
    n_.mode = Mode::initialization;
    changed(true);
    return Status::ok;
}

Status Instance::exit_initialization() {
    if (!allowed("ExitInitializationMode", {Mode::initialization})) return Status::error;
    if (!(n_.step > 0.0) && n_.method != runtime::Method::cvode)
        return fail("yamsc.step must be positive for RK4 and ABM4");
    if (n_.step < 0.0 || !std::isfinite(n_.step))
        return fail("yamsc.step must be finite, not negative");
    refresh_view();
    n_.mode = interface_ == Interface::model_exchange ? Mode::event : Mode::step;
    accept_point();
    return Status::ok;
}

Status Instance::enter_event_mode() {
    if (interface_ != Interface::model_exchange)
        return fail("EnterEventMode: this co-simulation instance has no event mode");
    if (!allowed("EnterEventMode", {Mode::continuous_time, Mode::event})) return Status::error;
    n_.mode = Mode::event;
    return Status::ok;
}

Status Instance::enter_continuous_time_mode() {
    if (!allowed("EnterContinuousTimeMode", {Mode::event})) return Status::error;
    if (interface_ != Interface::model_exchange)
        return fail("EnterContinuousTimeMode: not a model exchange instance");
    refresh_view();
    n_.mode = Mode::continuous_time;
    return Status::ok;
}

Status Instance::enter_step_mode() {
    if (interface_ != Interface::co_simulation)
        return fail("EnterStepMode: not a co-simulation instance");
    if (!allowed("EnterStepMode", {Mode::event})) return Status::error;
    n_.mode = Mode::step;
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
    n_.mode = Mode::terminated;
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
        xdot_.resize(n_.x.size());
        view_.rhs(n_.t, n_.x.data(), n_.u.data(), xdot_.data());
        xdot_known_ = true;
    }
    return xdot_;
}

const std::vector<double>& Instance::outputs() {
    if (!y_known_) {
        refresh_view();
        y_.resize(static_cast<std::size_t>(view_.ny));
        if (view_.ny > 0)
            view_.outputs(n_.t, n_.x.data(), n_.x.data() + nq_, n_.u.data(), y_.data());
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
        if (v->role == Role::time)
            values[k] = n_.t;
        else if (v->role == Role::output)
            values[k] = outputs()[static_cast<std::size_t>(v->index)];
        else if (v->role == Role::acceleration || v->role == Role::block_rate)
            values[k] = derivatives()[*derivative_index(*v)];
        else if (const double* place = stored(*v))
            values[k] = *place;
        else
            return fail("GetFloat64: " + v->name + " is an Int32");
    }
    return Status::ok;
}

Status Instance::check_settable(const Variable& v) const {
    const bool before = n_.mode == Mode::instantiated || n_.mode == Mode::initialization;
    switch (v.causality) {
    case Causality::input:
        if (n_.mode != Mode::terminated) return Status::ok;
        break;
    case Causality::parameter:
        if (before) return Status::ok;
        if (v.variability == Variability::tunable &&
            (n_.mode == Mode::event || n_.mode == Mode::step))
            return Status::ok;
        break;
    case Causality::local:
        if (before && v.initial == Initial::exact) return Status::ok;
        break;
    default:
        break;
    }
    return fail("Set: " + v.name + " cannot be set in " + mode_name(n_.mode));
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
        double* place = stored(*v);
        if (!place) return fail("SetFloat64: " + v->name + " cannot be set");
        if (v->role == Role::parameter && *place != values[k]) view_stale_ = true;
        *place = values[k];
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
        values[k] = method_code(n_.method);
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
        n_.method = *m;
        abm4_.reset();
    }
    return Status::ok;
}

Status Instance::set_time(double t) {
    if (!allowed("SetTime", {Mode::event, Mode::continuous_time})) return Status::error;
    if (!std::isfinite(t)) return fail("SetTime: the time is not finite");
    n_.t = t;
    changed(true);
    return Status::ok;
}

Status Instance::set_continuous_states(const double* x, std::size_t n) {
    if (!allowed("SetContinuousStates", {Mode::event, Mode::continuous_time})) return Status::error;
    if (n != n_.x.size())
        return fail("SetContinuousStates: " + std::to_string(n) + " states given, the model has " +
                    std::to_string(n_.x.size()));
    for (std::size_t i = 0; i < n; ++i)
        if (!std::isfinite(x[i]))
            return fail("SetContinuousStates: state " + std::to_string(i) + " is not finite");
    std::copy(x, x + n, n_.x.begin());
    changed(true);
    return Status::ok;
}

Status Instance::get_continuous_states(double* x, std::size_t n) {
    if (!allowed("GetContinuousStates",
                 {Mode::initialization, Mode::event, Mode::continuous_time, Mode::terminated}))
        return Status::error;
    if (n != n_.x.size())
        return fail("GetContinuousStates: the model has " + std::to_string(n_.x.size()) +
                    " states");
    std::copy(n_.x.begin(), n_.x.end(), x);
    return Status::ok;
}

Status Instance::get_derivatives(double* xdot, std::size_t n) {
    if (!allowed("GetContinuousStateDerivatives",
                 {Mode::initialization, Mode::event, Mode::continuous_time, Mode::terminated}))
        return Status::error;
    if (n != n_.x.size())
        return fail("GetContinuousStateDerivatives: the model has " + std::to_string(n_.x.size()) +
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
    if (n != n_.x.size())
        return fail("GetNominalsOfContinuousStates: the model has " + std::to_string(n_.x.size()) +
                    " states");
    std::fill(nominals, nominals + n, 1.0);
    return Status::ok;
}

// The point the blocks' discrete states are advanced from at the next accepted step.
void Instance::accept_point() {
    n_.t_accepted = n_.t;
    n_.x_accepted = n_.x;
    n_.u_accepted = n_.u;
}

Status Instance::completed_integrator_step() {
    if (!allowed("CompletedIntegratorStep", {Mode::continuous_time})) return Status::error;
    if (view_.project) {
        view_.project(n_.t, n_.x.data(), n_.u.data());
        changed(true);
    }
    if (view_.update_discrete) {
        view_.update_discrete(n_.t_accepted, n_.x_accepted.data(), n_.u_accepted.data(), n_.t,
                              n_.x.data(), n_.u.data());
        changed(false);
    }
    accept_point();
    return Status::ok;
}

} // namespace yamsc::fmi
