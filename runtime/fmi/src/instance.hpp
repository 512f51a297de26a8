#pragma once
// One instance of a unit: the numbers of the model (time, states, inputs,
// parameters), the standard's state machine, model exchange and
// co-simulation over the runtime's view and integrators. The FMI 3.0 and 2.0
// layers (fmi3_functions.cpp, fmi2_functions.cpp) are thin translations onto
// it; it throws nothing across them (each call returns a Status, errors
// are logged). Internal to yamsc_fmi.
#include "yamsc/abm4.hpp"
#include "yamsc/fmi/unit.hpp"
#include "yamsc/fmi/variables.hpp"
#include "yamsc/model_view.hpp"
#include "yamsc/rk4.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace yamsc::fmi {

/// In the order of both standards' status enumerations (fmi3Status, fmi2Status).
enum class Status { ok, warning, discard, error, fatal };

enum class Interface { model_exchange, co_simulation };

/// The states of the standard's state machine (FMI 3.0 2.3, FMI 2.0 3.2.3 and 4.2.4).
enum class Mode { instantiated, initialization, event, continuous_time, step, terminated };

/// Receives each message the instance logs (its status and category).
using Logger = std::function<void(Status status, const char* category, const std::string& message)>;

/// Every number of an instance a host may get and set again (GetFMUState):
/// what the model's equations are evaluated at, and where the run stands.
struct Numbers {
    Mode mode = Mode::instantiated;
    double t = 0.0;
    std::vector<double> x, u, p; // x = [q, q', z]
    runtime::Method method = runtime::Method::rk4;
    double step = 1e-3;
    std::optional<double> tolerance;
    // Model exchange: the last accepted point, for the blocks' discrete states.
    double t_accepted = 0.0;
    std::vector<double> x_accepted, u_accepted;
};

/// A copy of an instance's numbers and integrator history (GetFMUState / SetFMUState).
struct Snapshot {
    const void* owner = nullptr; // the instance it was taken of (ABM4's history is that one's)
    Interface interface = Interface::co_simulation;
    Numbers numbers;
    std::optional<runtime::Abm4Integrator> abm4;
};

/// A snapshot as bytes (SerializeFMUState) and back; nullopt / null with the
/// reason in `error`. ABM4's history is not written: a snapshot that holds one
/// is refused (after it, the restored run would start ABM4 again and differ).
std::optional<std::vector<unsigned char>> serialize(const Snapshot& s, std::string& error);
Snapshot* deserialize(const unsigned char* bytes, std::size_t size, std::string& error);

class Instance {
public:
    /// Throws std::exception with a message when the model cannot be made (a
    /// load block's data missing from the resources).
    Instance(const UnitModel& unit, Interface interface, std::string name, std::string resources,
             Logger logger, bool logging_on);
    ~Instance();
    Instance(const Instance&) = delete;
    Instance& operator=(const Instance&) = delete;

    const std::string& name() const { return name_; }
    Interface interface() const { return interface_; }
    Mode mode() const { return n_.mode; }
    const std::vector<Variable>& table() const { return table_; }
    std::size_t state_count() const { return n_.x.size(); }
    double time() const { return n_.t; }
    void set_logging(bool on) { logging_on_ = on; }

    /// Logs (errors always, the rest when logging is on) and returns status.
    Status log(Status status, const std::string& message) const;
    /// Logs an error and returns Status::error.
    Status fail(const std::string& message) const { return log(Status::error, message); }
    /// Whether the call `what` is allowed in the current mode (else logs why).
    bool allowed(const char* what, std::initializer_list<Mode> modes) const;

    Status enter_initialization(std::optional<double> tolerance, double start_time,
                                std::optional<double> stop_time);
    Status exit_initialization();
    Status enter_event_mode();
    Status enter_continuous_time_mode();
    Status enter_step_mode();
    Status update_discrete_states();
    Status terminate();
    Status reset();

    Status get_float64(const std::uint32_t* vrs, std::size_t n, double* values);
    Status set_float64(const std::uint32_t* vrs, std::size_t n, const double* values);
    Status get_int32(const std::uint32_t* vrs, std::size_t n, std::int32_t* values);
    Status set_int32(const std::uint32_t* vrs, std::size_t n, const std::int32_t* values);

    // Model exchange.
    Status set_time(double t);
    Status set_continuous_states(const double* x, std::size_t n);
    Status get_continuous_states(double* x, std::size_t n);
    Status get_derivatives(double* xdot, std::size_t n);
    Status get_nominals(double* nominals, std::size_t n);
    Status completed_integrator_step();

    // Co-simulation: advances by h from t (which must be the instance's time).
    Status do_step(double t, double h);

    /// sensitivity = J seed (adjoint: seed^T J) of the unknowns with respect to
    /// the knowns (states and inputs; unknowns: derivatives and outputs).
    Status directional_derivative(const std::uint32_t* unknowns, std::size_t n_unknowns,
                                  const std::uint32_t* knowns, std::size_t n_knowns,
                                  const double* seed, double* sensitivity, bool adjoint);

    Status get_state(Snapshot** state);
    Status set_state(const Snapshot* state);
    static void free_state(Snapshot* state);
    Status serialized_size(const Snapshot* state, std::size_t* size) const;
    Status serialize_state(const Snapshot* state, unsigned char* bytes, std::size_t size) const;
    Status deserialize_state(const unsigned char* bytes, std::size_t size, Snapshot** state) const;

private:
    const UnitModel& unit_;
    Interface interface_;
    std::string name_, resources_;
    Logger logger_;
    bool logging_on_;
    runtime::ModelView view_;
    std::vector<Variable> table_;
    std::size_t nq_ = 0, nz_ = 0;

    Numbers n_;
    std::vector<double> view_params_; // the parameters view_ was made with
    bool view_stale_ = false;         // parameters changed since the view was made

    // Evaluated at (t_, x_, u_) on demand.
    std::vector<double> xdot_, y_;
    bool xdot_known_ = false, y_known_ = false;

    // Co-simulation integrators (made at the first step, dropped when the
    // numbers they hold a history of change).
    std::optional<runtime::Rk4Workspace> rk4_;
    std::optional<runtime::Abm4Integrator> abm4_;

    void start_values();
    void make_view();
    void changed(bool states_or_time);
    void refresh_view();
    const std::vector<double>& derivatives();
    const std::vector<double>& outputs();
    const Variable* variable(std::uint32_t vr, const char* function) const;
    /// The position of a state in x = [q, q', z] (nullopt: not a state).
    std::optional<std::size_t> state_index(const Variable& v) const;
    /// The position of a state derivative in x' (q' is the derivative of q).
    std::optional<std::size_t> derivative_index(const Variable& v) const;
    /// Where the instance keeps a Float64 variable it stores (null: computed, or an Int32).
    double* stored(const Variable& v);
    Status check_settable(const Variable& v) const;
    runtime::OdeFunction ode();
    void step_fixed(double t, double dt);
    void step_cvode(double t, double t_end);
    void accept_point();
    friend struct Jacobian;
};

} // namespace yamsc::fmi
