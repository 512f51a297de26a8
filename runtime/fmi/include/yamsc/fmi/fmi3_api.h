/* The FMI 3.0 C interface as a unit exports it, declared from the text of the
 * Functional Mock-up Interface 3.0 standard (section 2.2): its types and the
 * functions a unit with model exchange and co-simulation provides. Names,
 * argument types and their order are the standard's (they are the ABI a host
 * binds by name); the layout and comments are ours. yamsc does not ship the
 * Modelica Association's headers (docs/fmi.md, Conventions). */
#ifndef YAMSC_FMI_FMI3_API_H
#define YAMSC_FMI_FMI3_API_H

#include <stddef.h>
#include <stdint.h>
#ifndef __cplusplus
#include <stdbool.h>
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* The one symbol visibility of the unit's entry points: the rest of the
 * unit's code is hidden (runtime/fmi/CMakeLists.txt). */
#if defined(_WIN32)
#define YAMSC_FMI3_EXPORT __declspec(dllexport)
#else
#define YAMSC_FMI3_EXPORT __attribute__((visibility("default")))
#endif

/* Scalar types (2.2.2). */
typedef void* fmi3Instance;
typedef void* fmi3InstanceEnvironment;
typedef void* fmi3FMUState;
typedef uint32_t fmi3ValueReference;
typedef float fmi3Float32;
typedef double fmi3Float64;
typedef int8_t fmi3Int8;
typedef uint8_t fmi3UInt8;
typedef int16_t fmi3Int16;
typedef uint16_t fmi3UInt16;
typedef int32_t fmi3Int32;
typedef uint32_t fmi3UInt32;
typedef int64_t fmi3Int64;
typedef uint64_t fmi3UInt64;
typedef bool fmi3Boolean;
typedef char fmi3Char;
typedef const fmi3Char* fmi3String;
typedef uint8_t fmi3Byte;
typedef const fmi3Byte* fmi3Binary;
typedef bool fmi3Clock;

/* Status of every call, in increasing severity (2.2.3). */
typedef enum { fmi3OK, fmi3Warning, fmi3Discard, fmi3Error, fmi3Fatal } fmi3Status;

/* Kinds of dependency of an unknown on a known (2.2.10). */
typedef enum {
    fmi3Independent,
    fmi3Constant,
    fmi3Fixed,
    fmi3Tunable,
    fmi3Discrete,
    fmi3Dependent
} fmi3DependencyKind;

/* What fmi3GetInterval* reports of a clock's interval (2.2.9). */
typedef enum {
    fmi3IntervalNotYetKnown,
    fmi3IntervalUnchanged,
    fmi3IntervalChanged
} fmi3IntervalQualifier;

/* Callbacks the host gives at instantiation (2.2.4). */
typedef void (*fmi3LogMessageCallback)(fmi3InstanceEnvironment instanceEnvironment,
                                       fmi3Status status, fmi3String category, fmi3String message);
typedef void (*fmi3ClockUpdateCallback)(fmi3InstanceEnvironment instanceEnvironment);
typedef void (*fmi3IntermediateUpdateCallback)(
    fmi3InstanceEnvironment instanceEnvironment, fmi3Float64 intermediateUpdateTime,
    fmi3Boolean intermediateVariableSetRequested, fmi3Boolean intermediateVariableGetAllowed,
    fmi3Boolean intermediateStepFinished, fmi3Boolean canReturnEarly,
    fmi3Boolean* earlyReturnRequested, fmi3Float64* earlyReturnTime);
typedef void (*fmi3LockPreemptionCallback)(void);
typedef void (*fmi3UnlockPreemptionCallback)(void);

/* Inquire the version and set debug logging (2.2.4, 2.2.5). */
YAMSC_FMI3_EXPORT const char* fmi3GetVersion(void);
YAMSC_FMI3_EXPORT fmi3Status fmi3SetDebugLogging(fmi3Instance instance, fmi3Boolean loggingOn,
                                                 size_t nCategories, const fmi3String categories[]);

/* Creation and destruction of instances (2.3.1). */
YAMSC_FMI3_EXPORT fmi3Instance fmi3InstantiateModelExchange(
    fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath,
    fmi3Boolean visible, fmi3Boolean loggingOn, fmi3InstanceEnvironment instanceEnvironment,
    fmi3LogMessageCallback logMessage);
YAMSC_FMI3_EXPORT fmi3Instance fmi3InstantiateCoSimulation(
    fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath,
    fmi3Boolean visible, fmi3Boolean loggingOn, fmi3Boolean eventModeUsed,
    fmi3Boolean earlyReturnAllowed, const fmi3ValueReference requiredIntermediateVariables[],
    size_t nRequiredIntermediateVariables, fmi3InstanceEnvironment instanceEnvironment,
    fmi3LogMessageCallback logMessage, fmi3IntermediateUpdateCallback intermediateUpdate);
YAMSC_FMI3_EXPORT fmi3Instance fmi3InstantiateScheduledExecution(
    fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath,
    fmi3Boolean visible, fmi3Boolean loggingOn, fmi3InstanceEnvironment instanceEnvironment,
    fmi3LogMessageCallback logMessage, fmi3ClockUpdateCallback clockUpdate,
    fmi3LockPreemptionCallback lockPreemption, fmi3UnlockPreemptionCallback unlockPreemption);
YAMSC_FMI3_EXPORT void fmi3FreeInstance(fmi3Instance instance);

/* Initialization, events, termination and reset (2.3.2 - 2.3.4). */
YAMSC_FMI3_EXPORT fmi3Status fmi3EnterInitializationMode(
    fmi3Instance instance, fmi3Boolean toleranceDefined, fmi3Float64 tolerance,
    fmi3Float64 startTime, fmi3Boolean stopTimeDefined, fmi3Float64 stopTime);
YAMSC_FMI3_EXPORT fmi3Status fmi3ExitInitializationMode(fmi3Instance instance);
YAMSC_FMI3_EXPORT fmi3Status fmi3EnterEventMode(fmi3Instance instance);
YAMSC_FMI3_EXPORT fmi3Status fmi3Terminate(fmi3Instance instance);
YAMSC_FMI3_EXPORT fmi3Status fmi3Reset(fmi3Instance instance);

/* Getting and setting variable values (2.2.6): one pair per type. */
#define YAMSC_FMI3_GET_SET(T)                                                                      \
    YAMSC_FMI3_EXPORT fmi3Status fmi3Get##T(                                                       \
        fmi3Instance instance, const fmi3ValueReference valueReferences[],                         \
        size_t nValueReferences, fmi3##T values[], size_t nValues);                                \
    YAMSC_FMI3_EXPORT fmi3Status fmi3Set##T(                                                       \
        fmi3Instance instance, const fmi3ValueReference valueReferences[],                         \
        size_t nValueReferences, const fmi3##T values[], size_t nValues);
YAMSC_FMI3_GET_SET(Float32)
YAMSC_FMI3_GET_SET(Float64)
YAMSC_FMI3_GET_SET(Int8)
YAMSC_FMI3_GET_SET(UInt8)
YAMSC_FMI3_GET_SET(Int16)
YAMSC_FMI3_GET_SET(UInt16)
YAMSC_FMI3_GET_SET(Int32)
YAMSC_FMI3_GET_SET(UInt32)
YAMSC_FMI3_GET_SET(Int64)
YAMSC_FMI3_GET_SET(UInt64)
YAMSC_FMI3_GET_SET(Boolean)
YAMSC_FMI3_GET_SET(String)
#undef YAMSC_FMI3_GET_SET
YAMSC_FMI3_EXPORT fmi3Status fmi3GetBinary(fmi3Instance instance,
                                           const fmi3ValueReference valueReferences[],
                                           size_t nValueReferences, size_t valueSizes[],
                                           fmi3Binary values[], size_t nValues);
YAMSC_FMI3_EXPORT fmi3Status fmi3SetBinary(fmi3Instance instance,
                                           const fmi3ValueReference valueReferences[],
                                           size_t nValueReferences, const size_t valueSizes[],
                                           const fmi3Binary values[], size_t nValues);
YAMSC_FMI3_EXPORT fmi3Status fmi3GetClock(fmi3Instance instance,
                                          const fmi3ValueReference valueReferences[],
                                          size_t nValueReferences, fmi3Clock values[]);
YAMSC_FMI3_EXPORT fmi3Status fmi3SetClock(fmi3Instance instance,
                                          const fmi3ValueReference valueReferences[],
                                          size_t nValueReferences, const fmi3Clock values[]);

/* Dependencies of variables (2.2.10). */
YAMSC_FMI3_EXPORT fmi3Status fmi3GetNumberOfVariableDependencies(fmi3Instance instance,
                                                                 fmi3ValueReference valueReference,
                                                                 size_t* nDependencies);
YAMSC_FMI3_EXPORT fmi3Status fmi3GetVariableDependencies(
    fmi3Instance instance, fmi3ValueReference dependent, size_t elementIndicesOfDependent[],
    fmi3ValueReference independents[], size_t elementIndicesOfIndependents[],
    fmi3DependencyKind dependencyKinds[], size_t nDependencies);

/* The complete state of an instance (2.2.7). */
YAMSC_FMI3_EXPORT fmi3Status fmi3GetFMUState(fmi3Instance instance, fmi3FMUState* FMUState);
YAMSC_FMI3_EXPORT fmi3Status fmi3SetFMUState(fmi3Instance instance, fmi3FMUState FMUState);
YAMSC_FMI3_EXPORT fmi3Status fmi3FreeFMUState(fmi3Instance instance, fmi3FMUState* FMUState);
YAMSC_FMI3_EXPORT fmi3Status fmi3SerializedFMUStateSize(fmi3Instance instance,
                                                        fmi3FMUState FMUState, size_t* size);
YAMSC_FMI3_EXPORT fmi3Status fmi3SerializeFMUState(fmi3Instance instance, fmi3FMUState FMUState,
                                                   fmi3Byte serializedState[], size_t size);
YAMSC_FMI3_EXPORT fmi3Status fmi3DeserializeFMUState(fmi3Instance instance,
                                                     const fmi3Byte serializedState[], size_t size,
                                                     fmi3FMUState* FMUState);

/* Partial derivatives (2.2.11). */
YAMSC_FMI3_EXPORT fmi3Status fmi3GetDirectionalDerivative(
    fmi3Instance instance, const fmi3ValueReference unknowns[], size_t nUnknowns,
    const fmi3ValueReference knowns[], size_t nKnowns, const fmi3Float64 seed[], size_t nSeed,
    fmi3Float64 sensitivity[], size_t nSensitivity);
YAMSC_FMI3_EXPORT fmi3Status fmi3GetAdjointDerivative(
    fmi3Instance instance, const fmi3ValueReference unknowns[], size_t nUnknowns,
    const fmi3ValueReference knowns[], size_t nKnowns, const fmi3Float64 seed[], size_t nSeed,
    fmi3Float64 sensitivity[], size_t nSensitivity);

/* Configuration mode (structural parameters, 2.2.2). */
YAMSC_FMI3_EXPORT fmi3Status fmi3EnterConfigurationMode(fmi3Instance instance);
YAMSC_FMI3_EXPORT fmi3Status fmi3ExitConfigurationMode(fmi3Instance instance);

/* Clocks (2.2.9). */
YAMSC_FMI3_EXPORT fmi3Status fmi3GetIntervalDecimal(fmi3Instance instance,
                                                    const fmi3ValueReference valueReferences[],
                                                    size_t nValueReferences,
                                                    fmi3Float64 intervals[],
                                                    fmi3IntervalQualifier qualifiers[]);
YAMSC_FMI3_EXPORT fmi3Status fmi3GetIntervalFraction(fmi3Instance instance,
                                                     const fmi3ValueReference valueReferences[],
                                                     size_t nValueReferences, fmi3UInt64 counters[],
                                                     fmi3UInt64 resolutions[],
                                                     fmi3IntervalQualifier qualifiers[]);
YAMSC_FMI3_EXPORT fmi3Status fmi3GetShiftDecimal(fmi3Instance instance,
                                                 const fmi3ValueReference valueReferences[],
                                                 size_t nValueReferences, fmi3Float64 shifts[]);
YAMSC_FMI3_EXPORT fmi3Status fmi3GetShiftFraction(fmi3Instance instance,
                                                  const fmi3ValueReference valueReferences[],
                                                  size_t nValueReferences, fmi3UInt64 counters[],
                                                  fmi3UInt64 resolutions[]);
YAMSC_FMI3_EXPORT fmi3Status fmi3SetIntervalDecimal(fmi3Instance instance,
                                                    const fmi3ValueReference valueReferences[],
                                                    size_t nValueReferences,
                                                    const fmi3Float64 intervals[]);
YAMSC_FMI3_EXPORT fmi3Status fmi3SetIntervalFraction(fmi3Instance instance,
                                                     const fmi3ValueReference valueReferences[],
                                                     size_t nValueReferences,
                                                     const fmi3UInt64 counters[],
                                                     const fmi3UInt64 resolutions[]);
YAMSC_FMI3_EXPORT fmi3Status fmi3SetShiftDecimal(fmi3Instance instance,
                                                 const fmi3ValueReference valueReferences[],
                                                 size_t nValueReferences,
                                                 const fmi3Float64 shifts[]);
YAMSC_FMI3_EXPORT fmi3Status fmi3SetShiftFraction(fmi3Instance instance,
                                                  const fmi3ValueReference valueReferences[],
                                                  size_t nValueReferences,
                                                  const fmi3UInt64 counters[],
                                                  const fmi3UInt64 resolutions[]);
YAMSC_FMI3_EXPORT fmi3Status fmi3EvaluateDiscreteStates(fmi3Instance instance);
YAMSC_FMI3_EXPORT fmi3Status fmi3UpdateDiscreteStates(
    fmi3Instance instance, fmi3Boolean* discreteStatesNeedUpdate, fmi3Boolean* terminateSimulation,
    fmi3Boolean* nominalsOfContinuousStatesChanged, fmi3Boolean* valuesOfContinuousStatesChanged,
    fmi3Boolean* nextEventTimeDefined, fmi3Float64* nextEventTime);

/* Model exchange (3.2). */
YAMSC_FMI3_EXPORT fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance instance);
YAMSC_FMI3_EXPORT fmi3Status
fmi3CompletedIntegratorStep(fmi3Instance instance, fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                            fmi3Boolean* enterEventMode, fmi3Boolean* terminateSimulation);
YAMSC_FMI3_EXPORT fmi3Status fmi3SetTime(fmi3Instance instance, fmi3Float64 time);
YAMSC_FMI3_EXPORT fmi3Status fmi3SetContinuousStates(fmi3Instance instance,
                                                     const fmi3Float64 continuousStates[],
                                                     size_t nContinuousStates);
YAMSC_FMI3_EXPORT fmi3Status fmi3GetContinuousStateDerivatives(fmi3Instance instance,
                                                               fmi3Float64 derivatives[],
                                                               size_t nContinuousStates);
YAMSC_FMI3_EXPORT fmi3Status fmi3GetEventIndicators(fmi3Instance instance,
                                                    fmi3Float64 eventIndicators[],
                                                    size_t nEventIndicators);
YAMSC_FMI3_EXPORT fmi3Status fmi3GetContinuousStates(fmi3Instance instance,
                                                     fmi3Float64 continuousStates[],
                                                     size_t nContinuousStates);
YAMSC_FMI3_EXPORT fmi3Status fmi3GetNominalsOfContinuousStates(fmi3Instance instance,
                                                               fmi3Float64 nominals[],
                                                               size_t nContinuousStates);
YAMSC_FMI3_EXPORT fmi3Status fmi3GetNumberOfEventIndicators(fmi3Instance instance,
                                                            size_t* nEventIndicators);
YAMSC_FMI3_EXPORT fmi3Status fmi3GetNumberOfContinuousStates(fmi3Instance instance,
                                                             size_t* nContinuousStates);

/* Co-simulation (4.2). */
YAMSC_FMI3_EXPORT fmi3Status fmi3EnterStepMode(fmi3Instance instance);
YAMSC_FMI3_EXPORT fmi3Status fmi3GetOutputDerivatives(fmi3Instance instance,
                                                      const fmi3ValueReference valueReferences[],
                                                      size_t nValueReferences,
                                                      const fmi3Int32 orders[],
                                                      fmi3Float64 values[], size_t nValues);
YAMSC_FMI3_EXPORT fmi3Status fmi3DoStep(
    fmi3Instance instance, fmi3Float64 currentCommunicationPoint, fmi3Float64 communicationStepSize,
    fmi3Boolean noSetFMUStatePriorToCurrentPoint, fmi3Boolean* eventHandlingNeeded,
    fmi3Boolean* terminateSimulation, fmi3Boolean* earlyReturn, fmi3Float64* lastSuccessfulTime);

/* Scheduled execution (5.2). */
YAMSC_FMI3_EXPORT fmi3Status fmi3ActivateModelPartition(fmi3Instance instance,
                                                        fmi3ValueReference clockReference,
                                                        fmi3Float64 activationTime);

#ifdef __cplusplus
}
#endif

#endif
