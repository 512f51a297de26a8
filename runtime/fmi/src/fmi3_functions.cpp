// The FMI 3.0 functions of a unit (model exchange and co-simulation), each a
// translation onto the instance core (instance.hpp).
#include "yamsc/fmi/fmi3_api.h"

#include "entry.hpp"

#include <optional>
#include <string>

using namespace yamsc::fmi;

namespace {

fmi3Status status(Status s) {
    return static_cast<fmi3Status>(s);
}

Logger fmi3_logger(fmi3InstanceEnvironment environment, fmi3LogMessageCallback log) {
    if (!log) return {};
    return [environment, log](Status s, const char* category, const std::string& message) {
        log(environment, static_cast<fmi3Status>(s), category, message.c_str());
    };
}

// The resources folder as the blocks join file names to it: with its separator.
std::string folder(fmi3String resource_path) {
    std::string f = resource_path ? resource_path : "";
    if (!f.empty() && f.back() != '/') f += '/';
    return f;
}

template <class F> fmi3Status call(fmi3Instance instance, const char* function, F&& f) {
    return status(guarded(instance, function, std::forward<F>(f)));
}

fmi3Status none(fmi3Instance instance, const char* function, size_t n) {
    return status(no_variables_of_type(instance, function, n));
}

fmi3Status absent(fmi3Instance instance, const char* function) {
    return status(unsupported(instance, function));
}

// Scalars only: one value per value reference.
bool scalars(Instance& in, const char* function, size_t nvr, size_t nvalues) {
    if (nvr == nvalues) return true;
    in.fail(std::string(function) + ": " + std::to_string(nvalues) + " values for " +
            std::to_string(nvr) + " value references (every variable is a scalar)");
    return false;
}

} // namespace

extern "C" {

const char* fmi3GetVersion(void) {
    return "3.0";
}

fmi3Status fmi3SetDebugLogging(fmi3Instance instance, fmi3Boolean loggingOn, size_t,
                               const fmi3String[]) {
    return call(instance, "fmi3SetDebugLogging", [&](Instance& in) {
        in.set_logging(loggingOn);
        return Status::ok;
    });
}

fmi3Instance fmi3InstantiateModelExchange(fmi3String instanceName, fmi3String instantiationToken,
                                          fmi3String resourcePath, fmi3Boolean,
                                          fmi3Boolean loggingOn,
                                          fmi3InstanceEnvironment instanceEnvironment,
                                          fmi3LogMessageCallback logMessage) {
    return instantiate(Interface::model_exchange, instanceName, instantiationToken,
                       folder(resourcePath), fmi3_logger(instanceEnvironment, logMessage),
                       loggingOn);
}

fmi3Instance fmi3InstantiateCoSimulation(fmi3String instanceName, fmi3String instantiationToken,
                                         fmi3String resourcePath, fmi3Boolean,
                                         fmi3Boolean loggingOn, fmi3Boolean eventModeUsed,
                                         fmi3Boolean, const fmi3ValueReference[], size_t,
                                         fmi3InstanceEnvironment instanceEnvironment,
                                         fmi3LogMessageCallback logMessage,
                                         fmi3IntermediateUpdateCallback) {
    Logger logger = fmi3_logger(instanceEnvironment, logMessage);
    if (eventModeUsed) {
        // The unit has no events (hasEventMode is false in its description).
        if (logger)
            logger(Status::error, "logStatusError", "this unit has no event mode in co-simulation");
        return nullptr;
    }
    return instantiate(Interface::co_simulation, instanceName, instantiationToken,
                       folder(resourcePath), std::move(logger), loggingOn);
}

fmi3Instance fmi3InstantiateScheduledExecution(fmi3String, fmi3String, fmi3String, fmi3Boolean,
                                               fmi3Boolean,
                                               fmi3InstanceEnvironment instanceEnvironment,
                                               fmi3LogMessageCallback logMessage,
                                               fmi3ClockUpdateCallback, fmi3LockPreemptionCallback,
                                               fmi3UnlockPreemptionCallback) {
    if (logMessage)
        logMessage(instanceEnvironment, fmi3Error, "logStatusError",
                   "this unit provides model exchange and co-simulation, not scheduled execution");
    return nullptr;
}

void fmi3FreeInstance(fmi3Instance instance) {
    delete static_cast<Instance*>(instance);
}

fmi3Status fmi3EnterInitializationMode(fmi3Instance instance, fmi3Boolean toleranceDefined,
                                       fmi3Float64 tolerance, fmi3Float64 startTime,
                                       fmi3Boolean stopTimeDefined, fmi3Float64 stopTime) {
    return call(instance, "fmi3EnterInitializationMode", [&](Instance& in) {
        return in.enter_initialization(
            toleranceDefined ? std::optional<double>(tolerance) : std::nullopt, startTime,
            stopTimeDefined ? std::optional<double>(stopTime) : std::nullopt);
    });
}

fmi3Status fmi3ExitInitializationMode(fmi3Instance instance) {
    return call(instance, "fmi3ExitInitializationMode",
                [](Instance& in) { return in.exit_initialization(); });
}

fmi3Status fmi3EnterEventMode(fmi3Instance instance) {
    return call(instance, "fmi3EnterEventMode", [](Instance& in) { return in.enter_event_mode(); });
}

fmi3Status fmi3Terminate(fmi3Instance instance) {
    return call(instance, "fmi3Terminate", [](Instance& in) { return in.terminate(); });
}

fmi3Status fmi3Reset(fmi3Instance instance) {
    return call(instance, "fmi3Reset", [](Instance& in) { return in.reset(); });
}

fmi3Status fmi3GetFloat64(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                          size_t nValueReferences, fmi3Float64 values[], size_t nValues) {
    return call(instance, "fmi3GetFloat64", [&](Instance& in) {
        if (!scalars(in, "fmi3GetFloat64", nValueReferences, nValues)) return Status::error;
        return in.get_float64(valueReferences, nValueReferences, values);
    });
}

fmi3Status fmi3SetFloat64(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                          size_t nValueReferences, const fmi3Float64 values[], size_t nValues) {
    return call(instance, "fmi3SetFloat64", [&](Instance& in) {
        if (!scalars(in, "fmi3SetFloat64", nValueReferences, nValues)) return Status::error;
        return in.set_float64(valueReferences, nValueReferences, values);
    });
}

fmi3Status fmi3GetInt32(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                        size_t nValueReferences, fmi3Int32 values[], size_t nValues) {
    return call(instance, "fmi3GetInt32", [&](Instance& in) {
        if (!scalars(in, "fmi3GetInt32", nValueReferences, nValues)) return Status::error;
        return in.get_int32(valueReferences, nValueReferences, values);
    });
}

fmi3Status fmi3SetInt32(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                        size_t nValueReferences, const fmi3Int32 values[], size_t nValues) {
    return call(instance, "fmi3SetInt32", [&](Instance& in) {
        if (!scalars(in, "fmi3SetInt32", nValueReferences, nValues)) return Status::error;
        return in.set_int32(valueReferences, nValueReferences, values);
    });
}

// The types the unit has no variable of: only empty calls succeed.
#define YAMSC_FMI3_NO_VARIABLES(T)                                                                 \
    fmi3Status fmi3Get##T(fmi3Instance instance, const fmi3ValueReference[],                       \
                          size_t nValueReferences, fmi3##T[], size_t) {                            \
        return none(instance, "fmi3Get" #T, nValueReferences);                                     \
    }                                                                                              \
    fmi3Status fmi3Set##T(fmi3Instance instance, const fmi3ValueReference[],                       \
                          size_t nValueReferences, const fmi3##T[], size_t) {                      \
        return none(instance, "fmi3Set" #T, nValueReferences);                                     \
    }
YAMSC_FMI3_NO_VARIABLES(Float32)
YAMSC_FMI3_NO_VARIABLES(Int8)
YAMSC_FMI3_NO_VARIABLES(UInt8)
YAMSC_FMI3_NO_VARIABLES(Int16)
YAMSC_FMI3_NO_VARIABLES(UInt16)
YAMSC_FMI3_NO_VARIABLES(UInt32)
YAMSC_FMI3_NO_VARIABLES(Int64)
YAMSC_FMI3_NO_VARIABLES(UInt64)
YAMSC_FMI3_NO_VARIABLES(Boolean)
YAMSC_FMI3_NO_VARIABLES(String)
#undef YAMSC_FMI3_NO_VARIABLES

fmi3Status fmi3GetBinary(fmi3Instance instance, const fmi3ValueReference[], size_t nValueReferences,
                         size_t[], fmi3Binary[], size_t) {
    return none(instance, "fmi3GetBinary", nValueReferences);
}

fmi3Status fmi3SetBinary(fmi3Instance instance, const fmi3ValueReference[], size_t nValueReferences,
                         const size_t[], const fmi3Binary[], size_t) {
    return none(instance, "fmi3SetBinary", nValueReferences);
}

fmi3Status fmi3GetClock(fmi3Instance instance, const fmi3ValueReference[], size_t nValueReferences,
                        fmi3Clock[]) {
    return none(instance, "fmi3GetClock", nValueReferences);
}

fmi3Status fmi3SetClock(fmi3Instance instance, const fmi3ValueReference[], size_t nValueReferences,
                        const fmi3Clock[]) {
    return none(instance, "fmi3SetClock", nValueReferences);
}

fmi3Status fmi3GetNumberOfVariableDependencies(fmi3Instance instance, fmi3ValueReference, size_t*) {
    return absent(instance, "fmi3GetNumberOfVariableDependencies");
}

fmi3Status fmi3GetVariableDependencies(fmi3Instance instance, fmi3ValueReference, size_t[],
                                       fmi3ValueReference[], size_t[], fmi3DependencyKind[],
                                       size_t) {
    return absent(instance, "fmi3GetVariableDependencies");
}

fmi3Status fmi3GetFMUState(fmi3Instance instance, fmi3FMUState* FMUState) {
    return call(instance, "fmi3GetFMUState", [&](Instance& in) {
        if (!FMUState) return in.fail("fmi3GetFMUState: no place for the state");
        auto* s = static_cast<Snapshot*>(*FMUState);
        const Status r = in.get_state(&s);
        *FMUState = s;
        return r;
    });
}

fmi3Status fmi3SetFMUState(fmi3Instance instance, fmi3FMUState FMUState) {
    return call(instance, "fmi3SetFMUState",
                [&](Instance& in) { return in.set_state(static_cast<const Snapshot*>(FMUState)); });
}

fmi3Status fmi3FreeFMUState(fmi3Instance instance, fmi3FMUState* FMUState) {
    return call(instance, "fmi3FreeFMUState", [&](Instance&) {
        if (FMUState) {
            Instance::free_state(static_cast<Snapshot*>(*FMUState));
            *FMUState = nullptr;
        }
        return Status::ok;
    });
}

fmi3Status fmi3SerializedFMUStateSize(fmi3Instance instance, fmi3FMUState FMUState, size_t* size) {
    return call(instance, "fmi3SerializedFMUStateSize", [&](Instance& in) {
        return in.serialized_size(static_cast<const Snapshot*>(FMUState), size);
    });
}

fmi3Status fmi3SerializeFMUState(fmi3Instance instance, fmi3FMUState FMUState,
                                 fmi3Byte serializedState[], size_t size) {
    return call(instance, "fmi3SerializeFMUState", [&](Instance& in) {
        return in.serialize_state(static_cast<const Snapshot*>(FMUState), serializedState, size);
    });
}

fmi3Status fmi3DeserializeFMUState(fmi3Instance instance, const fmi3Byte serializedState[],
                                   size_t size, fmi3FMUState* FMUState) {
    return call(instance, "fmi3DeserializeFMUState", [&](Instance& in) {
        if (!FMUState) return in.fail("fmi3DeserializeFMUState: no place for the state");
        auto* s = static_cast<Snapshot*>(*FMUState);
        const Status r = in.deserialize_state(serializedState, size, &s);
        *FMUState = s;
        return r;
    });
}

fmi3Status fmi3GetDirectionalDerivative(fmi3Instance instance, const fmi3ValueReference unknowns[],
                                        size_t nUnknowns, const fmi3ValueReference knowns[],
                                        size_t nKnowns, const fmi3Float64 seed[], size_t nSeed,
                                        fmi3Float64 sensitivity[], size_t nSensitivity) {
    return call(instance, "fmi3GetDirectionalDerivative", [&](Instance& in) {
        if (nSeed != nKnowns || nSensitivity != nUnknowns)
            return in.fail(
                "fmi3GetDirectionalDerivative: one seed per known and one sensitivity per unknown");
        return in.directional_derivative(unknowns, nUnknowns, knowns, nKnowns, seed, sensitivity,
                                         false);
    });
}

fmi3Status fmi3GetAdjointDerivative(fmi3Instance instance, const fmi3ValueReference unknowns[],
                                    size_t nUnknowns, const fmi3ValueReference knowns[],
                                    size_t nKnowns, const fmi3Float64 seed[], size_t nSeed,
                                    fmi3Float64 sensitivity[], size_t nSensitivity) {
    return call(instance, "fmi3GetAdjointDerivative", [&](Instance& in) {
        if (nSeed != nUnknowns || nSensitivity != nKnowns)
            return in.fail(
                "fmi3GetAdjointDerivative: one seed per unknown and one sensitivity per known");
        return in.directional_derivative(unknowns, nUnknowns, knowns, nKnowns, seed, sensitivity,
                                         true);
    });
}

fmi3Status fmi3EnterConfigurationMode(fmi3Instance instance) {
    return absent(instance, "fmi3EnterConfigurationMode");
}

fmi3Status fmi3ExitConfigurationMode(fmi3Instance instance) {
    return absent(instance, "fmi3ExitConfigurationMode");
}

fmi3Status fmi3GetIntervalDecimal(fmi3Instance instance, const fmi3ValueReference[], size_t,
                                  fmi3Float64[], fmi3IntervalQualifier[]) {
    return absent(instance, "fmi3GetIntervalDecimal");
}

fmi3Status fmi3GetIntervalFraction(fmi3Instance instance, const fmi3ValueReference[], size_t,
                                   fmi3UInt64[], fmi3UInt64[], fmi3IntervalQualifier[]) {
    return absent(instance, "fmi3GetIntervalFraction");
}

fmi3Status fmi3GetShiftDecimal(fmi3Instance instance, const fmi3ValueReference[], size_t,
                               fmi3Float64[]) {
    return absent(instance, "fmi3GetShiftDecimal");
}

fmi3Status fmi3GetShiftFraction(fmi3Instance instance, const fmi3ValueReference[], size_t,
                                fmi3UInt64[], fmi3UInt64[]) {
    return absent(instance, "fmi3GetShiftFraction");
}

fmi3Status fmi3SetIntervalDecimal(fmi3Instance instance, const fmi3ValueReference[], size_t,
                                  const fmi3Float64[]) {
    return absent(instance, "fmi3SetIntervalDecimal");
}

fmi3Status fmi3SetIntervalFraction(fmi3Instance instance, const fmi3ValueReference[], size_t,
                                   const fmi3UInt64[], const fmi3UInt64[]) {
    return absent(instance, "fmi3SetIntervalFraction");
}

fmi3Status fmi3SetShiftDecimal(fmi3Instance instance, const fmi3ValueReference[], size_t,
                               const fmi3Float64[]) {
    return absent(instance, "fmi3SetShiftDecimal");
}

fmi3Status fmi3SetShiftFraction(fmi3Instance instance, const fmi3ValueReference[], size_t,
                                const fmi3UInt64[], const fmi3UInt64[]) {
    return absent(instance, "fmi3SetShiftFraction");
}

fmi3Status fmi3EvaluateDiscreteStates(fmi3Instance instance) {
    return call(instance, "fmi3EvaluateDiscreteStates", [](Instance&) { return Status::ok; });
}

fmi3Status fmi3UpdateDiscreteStates(fmi3Instance instance, fmi3Boolean* discreteStatesNeedUpdate,
                                    fmi3Boolean* terminateSimulation,
                                    fmi3Boolean* nominalsOfContinuousStatesChanged,
                                    fmi3Boolean* valuesOfContinuousStatesChanged,
                                    fmi3Boolean* nextEventTimeDefined, fmi3Float64* nextEventTime) {
    return call(instance, "fmi3UpdateDiscreteStates", [&](Instance& in) {
        // No events: one update settles everything, and no time event follows.
        if (discreteStatesNeedUpdate) *discreteStatesNeedUpdate = false;
        if (terminateSimulation) *terminateSimulation = false;
        if (nominalsOfContinuousStatesChanged) *nominalsOfContinuousStatesChanged = false;
        if (valuesOfContinuousStatesChanged) *valuesOfContinuousStatesChanged = false;
        if (nextEventTimeDefined) *nextEventTimeDefined = false;
        if (nextEventTime) *nextEventTime = 0.0;
        return in.update_discrete_states();
    });
}

fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance instance) {
    return call(instance, "fmi3EnterContinuousTimeMode",
                [](Instance& in) { return in.enter_continuous_time_mode(); });
}

fmi3Status fmi3CompletedIntegratorStep(fmi3Instance instance, fmi3Boolean,
                                       fmi3Boolean* enterEventMode,
                                       fmi3Boolean* terminateSimulation) {
    return call(instance, "fmi3CompletedIntegratorStep", [&](Instance& in) {
        if (enterEventMode) *enterEventMode = false;
        if (terminateSimulation) *terminateSimulation = false;
        return in.completed_integrator_step();
    });
}

fmi3Status fmi3SetTime(fmi3Instance instance, fmi3Float64 time) {
    return call(instance, "fmi3SetTime", [&](Instance& in) { return in.set_time(time); });
}

fmi3Status fmi3SetContinuousStates(fmi3Instance instance, const fmi3Float64 continuousStates[],
                                   size_t nContinuousStates) {
    return call(instance, "fmi3SetContinuousStates", [&](Instance& in) {
        return in.set_continuous_states(continuousStates, nContinuousStates);
    });
}

fmi3Status fmi3GetContinuousStateDerivatives(fmi3Instance instance, fmi3Float64 derivatives[],
                                             size_t nContinuousStates) {
    return call(instance, "fmi3GetContinuousStateDerivatives",
                [&](Instance& in) { return in.get_derivatives(derivatives, nContinuousStates); });
}

fmi3Status fmi3GetEventIndicators(fmi3Instance instance, fmi3Float64[], size_t nEventIndicators) {
    return call(instance, "fmi3GetEventIndicators", [&](Instance& in) {
        if (nEventIndicators != 0)
            return in.fail("fmi3GetEventIndicators: the unit has no event indicators");
        return Status::ok;
    });
}

fmi3Status fmi3GetContinuousStates(fmi3Instance instance, fmi3Float64 continuousStates[],
                                   size_t nContinuousStates) {
    return call(instance, "fmi3GetContinuousStates", [&](Instance& in) {
        return in.get_continuous_states(continuousStates, nContinuousStates);
    });
}

fmi3Status fmi3GetNominalsOfContinuousStates(fmi3Instance instance, fmi3Float64 nominals[],
                                             size_t nContinuousStates) {
    return call(instance, "fmi3GetNominalsOfContinuousStates",
                [&](Instance& in) { return in.get_nominals(nominals, nContinuousStates); });
}

fmi3Status fmi3GetNumberOfEventIndicators(fmi3Instance instance, size_t* nEventIndicators) {
    return call(instance, "fmi3GetNumberOfEventIndicators", [&](Instance&) {
        if (nEventIndicators) *nEventIndicators = 0;
        return Status::ok;
    });
}

fmi3Status fmi3GetNumberOfContinuousStates(fmi3Instance instance, size_t* nContinuousStates) {
    return call(instance, "fmi3GetNumberOfContinuousStates", [&](Instance& in) {
        if (nContinuousStates) *nContinuousStates = in.state_count();
        return Status::ok;
    });
}

fmi3Status fmi3EnterStepMode(fmi3Instance instance) {
    return call(instance, "fmi3EnterStepMode", [](Instance& in) { return in.enter_step_mode(); });
}

fmi3Status fmi3GetOutputDerivatives(fmi3Instance instance, const fmi3ValueReference[], size_t,
                                    const fmi3Int32[], fmi3Float64[], size_t) {
    return absent(instance, "fmi3GetOutputDerivatives");
}

fmi3Status fmi3DoStep(fmi3Instance instance, fmi3Float64 currentCommunicationPoint,
                      fmi3Float64 communicationStepSize, fmi3Boolean,
                      fmi3Boolean* eventHandlingNeeded, fmi3Boolean* terminateSimulation,
                      fmi3Boolean* earlyReturn, fmi3Float64* lastSuccessfulTime) {
    return call(instance, "fmi3DoStep", [&](Instance& in) {
        if (eventHandlingNeeded) *eventHandlingNeeded = false;
        if (terminateSimulation) *terminateSimulation = false;
        if (earlyReturn) *earlyReturn = false;
        const Status s = in.do_step(currentCommunicationPoint, communicationStepSize);
        if (lastSuccessfulTime) *lastSuccessfulTime = in.time();
        return s;
    });
}

fmi3Status fmi3ActivateModelPartition(fmi3Instance instance, fmi3ValueReference, fmi3Float64) {
    return absent(instance, "fmi3ActivateModelPartition");
}

} // extern "C"
