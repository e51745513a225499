/* A hand-written FMI 2.0 co-simulation FMU with a tlmhub power port of kind C: an ideal
 * hydraulic pressure source. It takes the port's wave variable c and impedance Zc and gives
 * back the pressure p = p0 and the flow q = (p0 - c) / Zc (the TLM relation p = c + Zc q
 * solved for q). Value references: P1.c 0, P1.Zc 1 (inputs), P1.p 2, P1.q 3 (outputs),
 * p0 4 (parameter). Compiled as C++ too, as integrator.c says. */
#include "CommonFunctions.h"

#include <string.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    double c, Zc, p, q, p0;
} Source;

static double* variable(fmi2Component component, fmi2ValueReference reference)
{
    Source* self = (Source*)component;
    switch (reference) {
    case 0: return &self->c;
    case 1: return &self->Zc;
    case 2: return &self->p;
    case 3: return &self->q;
    case 4: return &self->p0;
    default: return NULL;
    }
}

static void solve(Source* self)
{
    self->p = self->p0;
    self->q = self->Zc > 0.0 ? (self->p0 - self->c) / self->Zc : 0.0;
}

EXPORT fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type type, fmi2String guid,
                                     fmi2String resourceLocation, const fmi2CallbackFunctions* functions,
                                     fmi2Boolean visible, fmi2Boolean loggingOn)
{
    (void)instanceName; (void)visible; (void)loggingOn; (void)resourceLocation; (void)functions;
    if (type != fmi2CoSimulation || strcmp(guid, "{0f5d2c55-6a3e-4c2b-9e38-5b1d2f7a9c01}") != 0) return NULL;
    return calloc(1, sizeof(Source));
}

EXPORT fmi2Status fmi2ExitInitializationMode(fmi2Component c)
{
    solve((Source*)c);
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
        if (!v || vr[i] == 2 || vr[i] == 3) return fmi2Error;
        *v = value[i];
    }
    return fmi2OK;
}

EXPORT fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint, fmi2Real communicationStepSize,
                             fmi2Boolean noSetFMUStatePriorToCurrentCommunicationPoint)
{
    (void)currentCommunicationPoint; (void)communicationStepSize; (void)noSetFMUStatePriorToCurrentCommunicationPoint;
    solve((Source*)c);
    return fmi2OK;
}

#ifdef __cplusplus
}
#endif
