/* A hand-written FMI 2.0 co-simulation FMU for the import tests: an integrator
 *   y' = k * u,  y(0) = y0
 * stepped exactly for an input held over the step: y += k * u * h. Value references:
 * u 0 (input), y 1 (output), k 2 and y0 3 (parameters). Built as integrator.so, and once
 * more without fmi2DoStep (TLMHUB_TEST_WITHOUT_DO_STEP) for the broken-FMU tests.
 * Plain C that also compiles as C++ (the build compiles it with the project's one compiler,
 * sanitizers included), hence the casts from void* and the extern "C" block. */
#include "fmu/Fmi2.h"

#include <stdlib.h>
#include <string.h>

#define EXPORT __attribute__((visibility("default")))

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    double u, y, k, y0;
    fmi2CallbackFunctions callbacks;
    char name[64];
} Instance;

static double* variable(fmi2Component c, fmi2ValueReference reference)
{
    Instance* self = (Instance*)c;
    switch (reference) {
    case 0: return &self->u;
    case 1: return &self->y;
    case 2: return &self->k;
    case 3: return &self->y0;
    default: return NULL;
    }
}

EXPORT const char* fmi2GetTypesPlatform(void) { return "default"; }
EXPORT const char* fmi2GetVersion(void) { return "2.0"; }
EXPORT fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean on, size_t n, const fmi2String categories[])
{
    (void)c; (void)on; (void)n; (void)categories;
    return fmi2OK;
}

EXPORT fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type type, fmi2String guid,
                                     fmi2String resourceLocation, const fmi2CallbackFunctions* functions,
                                     fmi2Boolean visible, fmi2Boolean loggingOn)
{
    (void)visible; (void)loggingOn; (void)resourceLocation;
    if (type != fmi2CoSimulation || strcmp(guid, "{8c4e810f-3df3-4a00-8276-176fa3c9f000}") != 0) return NULL;
    Instance* self = (Instance*)calloc(1, sizeof(Instance));
    if (!self) return NULL;
    self->k = 1.0;
    self->callbacks = *functions;
    strncpy(self->name, instanceName, sizeof self->name - 1);
    /* The importer shows this; the format arguments prove it formats them. */
    if (functions->logger)
        functions->logger(functions->componentEnvironment, instanceName, fmi2OK, "logStatusAll",
                          "integrator %s instantiated", instanceName);
    return self;
}

EXPORT void fmi2FreeInstance(fmi2Component c) { free(c); }

EXPORT fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined, fmi2Real tolerance,
                                      fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime)
{
    (void)c; (void)toleranceDefined; (void)tolerance; (void)startTime; (void)stopTimeDefined; (void)stopTime;
    return fmi2OK;
}

EXPORT fmi2Status fmi2EnterInitializationMode(fmi2Component c) { (void)c; return fmi2OK; }

EXPORT fmi2Status fmi2ExitInitializationMode(fmi2Component c)
{
    Instance* self = (Instance*)c;
    self->y = self->y0;
    return fmi2OK;
}

EXPORT fmi2Status fmi2Terminate(fmi2Component c) { (void)c; return fmi2OK; }
EXPORT fmi2Status fmi2Reset(fmi2Component c) { (void)c; return fmi2Error; }

EXPORT fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Real value[])
{
    for (size_t i = 0; i < nvr; ++i) {
        double* v = variable(c, vr[i]);
        if (!v) return fmi2Error;
        value[i] = *v;
    }
    return fmi2OK;
}

EXPORT fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Real value[])
{
    for (size_t i = 0; i < nvr; ++i) {
        double* v = variable(c, vr[i]);
        if (!v || vr[i] == 1) return fmi2Error;
        *v = value[i];
    }
    return fmi2OK;
}

#define UNSUPPORTED(...) { return fmi2Error; }
EXPORT fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Integer v[]) UNSUPPORTED()
EXPORT fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Boolean v[]) UNSUPPORTED()
EXPORT fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2String v[]) UNSUPPORTED()
EXPORT fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Integer v[]) UNSUPPORTED()
EXPORT fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Boolean v[]) UNSUPPORTED()
EXPORT fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2String v[]) UNSUPPORTED()
EXPORT fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate* s) UNSUPPORTED()
EXPORT fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate s) UNSUPPORTED()
EXPORT fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate* s) UNSUPPORTED()
EXPORT fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate s, size_t* n) UNSUPPORTED()
EXPORT fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate s, fmi2Byte b[], size_t n) UNSUPPORTED()
EXPORT fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte b[], size_t n, fmi2FMUstate* s) UNSUPPORTED()
EXPORT fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference u[], size_t nu,
                                               const fmi2ValueReference k[], size_t nk, const fmi2Real dk[],
                                               fmi2Real du[]) UNSUPPORTED()
EXPORT fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                                              const fmi2Integer order[], const fmi2Real v[]) UNSUPPORTED()
EXPORT fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                                               const fmi2Integer order[], fmi2Real v[]) UNSUPPORTED()
EXPORT fmi2Status fmi2CancelStep(fmi2Component c) UNSUPPORTED()
EXPORT fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind k, fmi2Status* s) UNSUPPORTED()
EXPORT fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind k, fmi2Real* v) UNSUPPORTED()
EXPORT fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind k, fmi2Integer* v) UNSUPPORTED()
EXPORT fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind k, fmi2Boolean* v) UNSUPPORTED()
EXPORT fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind k, fmi2String* v) UNSUPPORTED()

#ifndef TLMHUB_TEST_WITHOUT_DO_STEP
EXPORT fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint, fmi2Real communicationStepSize,
                             fmi2Boolean noSetFMUStatePriorToCurrentCommunicationPoint)
{
    (void)currentCommunicationPoint; (void)noSetFMUStatePriorToCurrentCommunicationPoint;
    Instance* self = (Instance*)c;
    self->y += self->k * self->u * communicationStepSize;
    return fmi2OK;
}
#endif

#ifdef __cplusplus
}
#endif
