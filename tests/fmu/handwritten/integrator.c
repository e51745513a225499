/* A hand-written FMI 2.0 co-simulation FMU for the import tests: an integrator
 *   y' = k * u,  y(0) = y0
 * stepped exactly for an input held over the step: y += k * u * h. Value references:
 * u 0 (input), y 1 (output), k 2 and y0 3 (parameters). Built as integrator.so, and once
 * more without fmi2DoStep (TLMHUB_TEST_WITHOUT_DO_STEP) for the broken-FMU tests.
 * Plain C that also compiles as C++ (the build compiles it with the project's one compiler,
 * sanitizers included), hence the casts from void* and the extern "C" block. */
#include "CommonFunctions.h"

#include <string.h>

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

EXPORT fmi2Status fmi2ExitInitializationMode(fmi2Component c)
{
    Instance* self = (Instance*)c;
    self->y = self->y0;
    return fmi2OK;
}

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
