// The FMI 2.0 co-simulation functions the runtime library exports (the only symbols it
// exports: see exports.map). Each checks its arguments, then calls the instance; no
// exception leaves the library.
#include "fmu/Fmi2.h"
#include "fmu/runtime/ExportedModelInstance.h"

#include <exception>
#include <string>
#include <type_traits>

using tlmhub::fmu::ExportedModelInstance;

namespace {

ExportedModelInstance* instanceOf(fmi2Component c)
{
    return static_cast<ExportedModelInstance*>(c);
}

// Runs `body` on the instance; an exception becomes fmi2Error with its text logged.
template <typename Body>
fmi2Status guarded(fmi2Component c, const char* function, Body body)
{
    if (c == nullptr)
        return fmi2Error;
    ExportedModelInstance& instance = *instanceOf(c);
    try {
        return body(instance);
    } catch (const std::exception& e) {
        return instance.error(std::string(function) + ": " + e.what());
    }
}

fmi2Status notSupported(fmi2Component c, const char* function)
{
    return guarded(c, function, [&](ExportedModelInstance& instance) {
        return instance.error(std::string(function) + " is not supported by this FMU");
    });
}

// The FMU has real variables only: a call of another type's function is fine for no
// variables, else an error.
fmi2Status noVariablesOfType(fmi2Component c, const char* function, size_t nvr)
{
    if (nvr == 0)
        return c ? fmi2OK : fmi2Error;
    return guarded(c, function, [&](ExportedModelInstance& instance) {
        return instance.error(std::string(function) + ": this FMU has no variables of this type");
    });
}

} // namespace

// The library is compiled with hidden visibility; these are the exceptions.
#pragma GCC visibility push(default)
extern "C" {

const char* fmi2GetTypesPlatform(void)
{
    return "default";
}

const char* fmi2GetVersion(void)
{
    return "2.0";
}

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t, const fmi2String[])
{
    return guarded(c, "fmi2SetDebugLogging", [&](ExportedModelInstance& instance) {
        instance.setDebugLogging(loggingOn != fmi2False);
        return fmi2OK;
    });
}

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String guid,
                              fmi2String resourceLocation, const fmi2CallbackFunctions* functions,
                              fmi2Boolean, fmi2Boolean loggingOn)
{
    if (functions == nullptr || instanceName == nullptr || guid == nullptr || resourceLocation == nullptr)
        return nullptr;
    if (fmuType != fmi2CoSimulation) {
        if (functions->logger)
            functions->logger(functions->componentEnvironment, instanceName, fmi2Error, "logStatusError",
                              "fmi2Instantiate: this FMU supports co-simulation only");
        return nullptr;
    }
    try {
        return ExportedModelInstance::create(instanceName, guid, resourceLocation, functions, loggingOn != fmi2False);
    } catch (const std::exception& e) {
        if (functions->logger)
            functions->logger(functions->componentEnvironment, instanceName, fmi2Error, "logStatusError",
                              "fmi2Instantiate: %s", e.what());
        return nullptr;
    }
}

void fmi2FreeInstance(fmi2Component c)
{
    delete instanceOf(c);
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean, fmi2Real, fmi2Real startTime,
                               fmi2Boolean stopTimeDefined, fmi2Real stopTime)
{
    return guarded(c, "fmi2SetupExperiment", [&](ExportedModelInstance& instance) {
        return instance.setupExperiment(startTime, stopTimeDefined ? std::optional<double>(stopTime) : std::nullopt);
    });
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c)
{
    return guarded(c, "fmi2EnterInitializationMode", [](ExportedModelInstance& i) { return i.enterInitializationMode(); });
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c)
{
    return guarded(c, "fmi2ExitInitializationMode", [](ExportedModelInstance& i) { return i.exitInitializationMode(); });
}

fmi2Status fmi2Terminate(fmi2Component c)
{
    return guarded(c, "fmi2Terminate", [](ExportedModelInstance& i) { return i.terminate(); });
}

fmi2Status fmi2Reset(fmi2Component c)
{
    return guarded(c, "fmi2Reset", [](ExportedModelInstance& i) { return i.reset(); });
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Real value[])
{
    return guarded(c, "fmi2GetReal", [&](ExportedModelInstance& i) {
        return nvr > 0 && (!vr || !value) ? i.error("fmi2GetReal: null array") : i.getReal(vr, nvr, value);
    });
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Real value[])
{
    return guarded(c, "fmi2SetReal", [&](ExportedModelInstance& i) {
        return nvr > 0 && (!vr || !value) ? i.error("fmi2SetReal: null array") : i.setReal(vr, nvr, value);
    });
}

fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference[], size_t nvr, fmi2Integer[])
{
    return noVariablesOfType(c, "fmi2GetInteger", nvr);
}

fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference[], size_t nvr, fmi2Boolean[])
{
    return noVariablesOfType(c, "fmi2GetBoolean", nvr);
}

fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference[], size_t nvr, fmi2String[])
{
    return noVariablesOfType(c, "fmi2GetString", nvr);
}

fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference[], size_t nvr, const fmi2Integer[])
{
    return noVariablesOfType(c, "fmi2SetInteger", nvr);
}

fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference[], size_t nvr, const fmi2Boolean[])
{
    return noVariablesOfType(c, "fmi2SetBoolean", nvr);
}

fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference[], size_t nvr, const fmi2String[])
{
    return noVariablesOfType(c, "fmi2SetString", nvr);
}

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate*)
{
    return notSupported(c, "fmi2GetFMUstate");
}

fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate)
{
    return notSupported(c, "fmi2SetFMUstate");
}

fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate*)
{
    return notSupported(c, "fmi2FreeFMUstate");
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate, size_t*)
{
    return notSupported(c, "fmi2SerializedFMUstateSize");
}

fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate, fmi2Byte[], size_t)
{
    return notSupported(c, "fmi2SerializeFMUstate");
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte[], size_t, fmi2FMUstate*)
{
    return notSupported(c, "fmi2DeSerializeFMUstate");
}

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference[], size_t,
                                        const fmi2ValueReference[], size_t, const fmi2Real[], fmi2Real[])
{
    return notSupported(c, "fmi2GetDirectionalDerivative");
}

fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference[], size_t, const fmi2Integer[],
                                       const fmi2Real[])
{
    return notSupported(c, "fmi2SetRealInputDerivatives");
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference[], size_t, const fmi2Integer[],
                                        fmi2Real[])
{
    return notSupported(c, "fmi2GetRealOutputDerivatives");
}

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint, fmi2Real communicationStepSize,
                      fmi2Boolean)
{
    return guarded(c, "fmi2DoStep",
                   [&](ExportedModelInstance& i) { return i.doStep(currentCommunicationPoint, communicationStepSize); });
}

fmi2Status fmi2CancelStep(fmi2Component c)
{
    return notSupported(c, "fmi2CancelStep");
}

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind kind, fmi2Status* value)
{
    return guarded(c, "fmi2GetStatus", [&](ExportedModelInstance& i) {
        if (kind != fmi2DoStepStatus || !value)
            return fmi2Discard;
        *value = i.doStepStatus();
        return fmi2OK;
    });
}

fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind kind, fmi2Real* value)
{
    return guarded(c, "fmi2GetRealStatus", [&](ExportedModelInstance& i) {
        if (kind != fmi2LastSuccessfulTime || !value)
            return fmi2Discard;
        *value = i.lastSuccessfulTime();
        return fmi2OK;
    });
}

fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind, fmi2Integer*)
{
    return c ? fmi2Discard : fmi2Error;
}

fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind kind, fmi2Boolean* value)
{
    return guarded(c, "fmi2GetBooleanStatus", [&](ExportedModelInstance& i) {
        if (kind != fmi2Terminated || !value)
            return fmi2Discard;
        *value = i.terminated() ? fmi2True : fmi2False;
        return fmi2OK;
    });
}

fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind, fmi2String*)
{
    return c ? fmi2Discard : fmi2Error;
}

} // extern "C"
#pragma GCC visibility pop

// Every function of the standard is defined here, with the standard's type.
#define TLMHUB_CHECK_FMI2_SIGNATURE(name) static_assert(std::is_same_v<decltype(&name), name##TYPE*>);
TLMHUB_FMI2_COSIMULATION_FUNCTIONS(TLMHUB_CHECK_FMI2_SIGNATURE)
#undef TLMHUB_CHECK_FMI2_SIGNATURE
