// The FMI 2.0 functions of a unit (model exchange and co-simulation), each a
// translation onto the instance core (instance.hpp).
#include "yamsc/fmi/fmi2_api.h"

#include "entry.hpp"
#include "resource_uri.hpp"

#include <optional>
#include <string>

using namespace yamsc::fmi;

namespace {

fmi2Status status(Status s) {
    return static_cast<fmi2Status>(s);
}

// FMI 2.0 loggers take a format string: the message is passed as an argument.
Logger fmi2_logger(const fmi2CallbackFunctions* functions, std::string instance_name) {
    if (!functions || !functions->logger) return {};
    const fmi2CallbackLogger log = functions->logger;
    const fmi2ComponentEnvironment environment = functions->componentEnvironment;
    return [log, environment, instance_name](Status s, const char* category,
                                             const std::string& message) {
        log(environment, instance_name.c_str(), static_cast<fmi2Status>(s), category, "%s",
            message.c_str());
    };
}

// What fmi2SetupExperiment gives, used by fmi2EnterInitializationMode. Kept
// beside each instance (the core takes them at once, as FMI 3.0 does).
struct Experiment {
    std::optional<double> tolerance, stop_time;
    double start_time = 0.0;
};

// The FMI 2.0 instance: the core and its experiment.
struct Component {
    Instance* core;
    Experiment experiment;
};

Component* component(fmi2Component c) {
    return static_cast<Component*>(c);
}
void* core(fmi2Component c) {
    return c ? component(c)->core : nullptr;
}

template <class F> fmi2Status call(fmi2Component c, const char* function, F&& f) {
    return status(guarded(core(c), function, std::forward<F>(f)));
}

fmi2Status absent(fmi2Component c, const char* function) {
    return status(unsupported(core(c), function));
}

} // namespace

extern "C" {

const char* fmi2GetTypesPlatform(void) {
    return "default";
}
const char* fmi2GetVersion(void) {
    return "2.0";
}

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t, const fmi2String[]) {
    return call(c, "fmi2SetDebugLogging", [&](Instance& in) {
        in.set_logging(loggingOn != fmi2False);
        return Status::ok;
    });
}

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String fmuResourceLocation,
                              const fmi2CallbackFunctions* functions, fmi2Boolean,
                              fmi2Boolean loggingOn) {
    Logger logger = fmi2_logger(functions, instanceName ? instanceName : "");
    std::string resources;
    if (fmuResourceLocation && *fmuResourceLocation) {
        const std::optional<std::string> path = folder_of_file_uri(fmuResourceLocation);
        if (!path) {
            if (logger)
                logger(Status::error, "logStatusError",
                       std::string("the resource location \"") + fmuResourceLocation +
                           "\" is not a file URI");
            return nullptr;
        }
        resources = *path;
    }
    const Interface interface =
        fmuType == fmi2ModelExchange ? Interface::model_exchange : Interface::co_simulation;
    Instance* in = instantiate(interface, instanceName, fmuGUID, resources, std::move(logger),
                               loggingOn != fmi2False);
    if (!in) return nullptr;
    try {
        return new Component{in, {}};
    } catch (...) {
        delete in;
        return nullptr;
    }
}

void fmi2FreeInstance(fmi2Component c) {
    if (!c) return;
    delete component(c)->core;
    delete component(c);
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined, fmi2Real tolerance,
                               fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime) {
    return call(c, "fmi2SetupExperiment", [&](Instance& in) {
        if (!in.allowed("fmi2SetupExperiment", {Mode::instantiated})) return Status::error;
        Experiment& e = component(c)->experiment;
        e.tolerance = toleranceDefined ? std::optional<double>(tolerance) : std::nullopt;
        e.stop_time = stopTimeDefined ? std::optional<double>(stopTime) : std::nullopt;
        e.start_time = startTime;
        return Status::ok;
    });
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c) {
    return call(c, "fmi2EnterInitializationMode", [&](Instance& in) {
        const Experiment& e = component(c)->experiment;
        return in.enter_initialization(e.tolerance, e.start_time, e.stop_time);
    });
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
    return call(c, "fmi2ExitInitializationMode",
                [](Instance& in) { return in.exit_initialization(); });
}

fmi2Status fmi2Terminate(fmi2Component c) {
    return call(c, "fmi2Terminate", [](Instance& in) { return in.terminate(); });
}

fmi2Status fmi2Reset(fmi2Component c) {
    return call(c, "fmi2Reset", [&](Instance& in) {
        component(c)->experiment = {};
        return in.reset();
    });
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       fmi2Real value[]) {
    return call(c, "fmi2GetReal", [&](Instance& in) { return in.get_float64(vr, nvr, value); });
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       const fmi2Real value[]) {
    return call(c, "fmi2SetReal", [&](Instance& in) { return in.set_float64(vr, nvr, value); });
}

fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          fmi2Integer value[]) {
    static_assert(sizeof(fmi2Integer) == sizeof(std::int32_t), "fmi2Integer is a 32-bit int");
    return call(c, "fmi2GetInteger", [&](Instance& in) { return in.get_int32(vr, nvr, value); });
}

fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          const fmi2Integer value[]) {
    return call(c, "fmi2SetInteger", [&](Instance& in) { return in.set_int32(vr, nvr, value); });
}

fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference[], size_t nvr, fmi2Boolean[]) {
    return status(no_variables_of_type(core(c), "fmi2GetBoolean", nvr));
}

fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference[], size_t nvr,
                          const fmi2Boolean[]) {
    return status(no_variables_of_type(core(c), "fmi2SetBoolean", nvr));
}

fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference[], size_t nvr, fmi2String[]) {
    return status(no_variables_of_type(core(c), "fmi2GetString", nvr));
}

fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference[], size_t nvr,
                         const fmi2String[]) {
    return status(no_variables_of_type(core(c), "fmi2SetString", nvr));
}

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate* FMUstate) {
    return call(c, "fmi2GetFMUstate", [&](Instance& in) {
        if (!FMUstate) return in.fail("fmi2GetFMUstate: no place for the state");
        auto* s = static_cast<Snapshot*>(*FMUstate);
        const Status r = in.get_state(&s);
        *FMUstate = s;
        return r;
    });
}

fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate FMUstate) {
    return call(c, "fmi2SetFMUstate",
                [&](Instance& in) { return in.set_state(static_cast<const Snapshot*>(FMUstate)); });
}

fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate* FMUstate) {
    return call(c, "fmi2FreeFMUstate", [&](Instance&) {
        if (FMUstate) {
            Instance::free_state(static_cast<Snapshot*>(*FMUstate));
            *FMUstate = nullptr;
        }
        return Status::ok;
    });
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate FMUstate, size_t* size) {
    return call(c, "fmi2SerializedFMUstateSize", [&](Instance& in) {
        return in.serialized_size(static_cast<const Snapshot*>(FMUstate), size);
    });
}

// fmi2Byte is char: the bytes are the same.
fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate FMUstate, fmi2Byte serializedState[],
                                 size_t size) {
    return call(c, "fmi2SerializeFMUstate", [&](Instance& in) {
        return in.serialize_state(static_cast<const Snapshot*>(FMUstate),
                                  reinterpret_cast<unsigned char*>(serializedState), size);
    });
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte serializedState[], size_t size,
                                   fmi2FMUstate* FMUstate) {
    return call(c, "fmi2DeSerializeFMUstate", [&](Instance& in) {
        if (!FMUstate) return in.fail("fmi2DeSerializeFMUstate: no place for the state");
        auto* s = static_cast<Snapshot*>(*FMUstate);
        const Status r =
            in.deserialize_state(reinterpret_cast<const unsigned char*>(serializedState), size, &s);
        *FMUstate = s;
        return r;
    });
}

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference vUnknown_ref[],
                                        size_t nUnknown, const fmi2ValueReference vKnown_ref[],
                                        size_t nKnown, const fmi2Real dvKnown[],
                                        fmi2Real dvUnknown[]) {
    return call(c, "fmi2GetDirectionalDerivative", [&](Instance& in) {
        return in.directional_derivative(vUnknown_ref, nUnknown, vKnown_ref, nKnown, dvKnown,
                                         dvUnknown, false);
    });
}

fmi2Status fmi2EnterEventMode(fmi2Component c) {
    return call(c, "fmi2EnterEventMode", [](Instance& in) { return in.enter_event_mode(); });
}

fmi2Status fmi2NewDiscreteStates(fmi2Component c, fmi2EventInfo* eventInfo) {
    return call(c, "fmi2NewDiscreteStates", [&](Instance& in) {
        if (eventInfo)
            *eventInfo = fmi2EventInfo{fmi2False, fmi2False, fmi2False, fmi2False, fmi2False, 0.0};
        return in.update_discrete_states();
    });
}

fmi2Status fmi2EnterContinuousTimeMode(fmi2Component c) {
    return call(c, "fmi2EnterContinuousTimeMode",
                [](Instance& in) { return in.enter_continuous_time_mode(); });
}

fmi2Status fmi2CompletedIntegratorStep(fmi2Component c, fmi2Boolean, fmi2Boolean* enterEventMode,
                                       fmi2Boolean* terminateSimulation) {
    return call(c, "fmi2CompletedIntegratorStep", [&](Instance& in) {
        if (enterEventMode) *enterEventMode = fmi2False;
        if (terminateSimulation) *terminateSimulation = fmi2False;
        return in.completed_integrator_step();
    });
}

fmi2Status fmi2SetTime(fmi2Component c, fmi2Real time) {
    return call(c, "fmi2SetTime", [&](Instance& in) { return in.set_time(time); });
}

fmi2Status fmi2SetContinuousStates(fmi2Component c, const fmi2Real x[], size_t nx) {
    return call(c, "fmi2SetContinuousStates",
                [&](Instance& in) { return in.set_continuous_states(x, nx); });
}

fmi2Status fmi2GetDerivatives(fmi2Component c, fmi2Real derivatives[], size_t nx) {
    return call(c, "fmi2GetDerivatives",
                [&](Instance& in) { return in.get_derivatives(derivatives, nx); });
}

fmi2Status fmi2GetEventIndicators(fmi2Component c, fmi2Real[], size_t ni) {
    return call(c, "fmi2GetEventIndicators", [&](Instance& in) {
        if (ni != 0) return in.fail("fmi2GetEventIndicators: the unit has no event indicators");
        return Status::ok;
    });
}

fmi2Status fmi2GetContinuousStates(fmi2Component c, fmi2Real x[], size_t nx) {
    return call(c, "fmi2GetContinuousStates",
                [&](Instance& in) { return in.get_continuous_states(x, nx); });
}

fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component c, fmi2Real x_nominal[], size_t nx) {
    return call(c, "fmi2GetNominalsOfContinuousStates",
                [&](Instance& in) { return in.get_nominals(x_nominal, nx); });
}

fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference[], size_t,
                                       const fmi2Integer[], const fmi2Real[]) {
    return absent(c, "fmi2SetRealInputDerivatives");
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference[], size_t,
                                        const fmi2Integer[], fmi2Real[]) {
    return absent(c, "fmi2GetRealOutputDerivatives");
}

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint,
                      fmi2Real communicationStepSize, fmi2Boolean) {
    return call(c, "fmi2DoStep", [&](Instance& in) {
        return in.do_step(currentCommunicationPoint, communicationStepSize);
    });
}

fmi2Status fmi2CancelStep(fmi2Component c) {
    return absent(c, "fmi2CancelStep");
}

// The status of the last step: doStep finishes before it returns (no asynchronous steps).
fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status* value) {
    return call(c, "fmi2GetStatus", [&](Instance& in) {
        if (s != fmi2DoStepStatus)
            return in.fail("fmi2GetStatus: only fmi2DoStepStatus is a status");
        if (value) *value = fmi2OK;
        return Status::ok;
    });
}

fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real* value) {
    return call(c, "fmi2GetRealStatus", [&](Instance& in) {
        if (s != fmi2LastSuccessfulTime)
            return in.fail("fmi2GetRealStatus: only fmi2LastSuccessfulTime is a real");
        if (value) *value = in.time();
        return Status::ok;
    });
}

fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind, fmi2Integer*) {
    return absent(c, "fmi2GetIntegerStatus");
}

fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean* value) {
    return call(c, "fmi2GetBooleanStatus", [&](Instance& in) {
        if (s != fmi2Terminated)
            return in.fail("fmi2GetBooleanStatus: only fmi2Terminated is a boolean");
        if (value) *value = fmi2False;
        return Status::ok;
    });
}

fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind, fmi2String*) {
    return absent(c, "fmi2GetStringStatus");
}

} // extern "C"
