#pragma once
#include "core/Component.h"

namespace tlmhub {

// Pitch/yaw thrust-vector-control autopilot: rate-damped angle loops with a common
// saturation. No state; phi is read but unused (as in the reference).
class SignalAttitudeTVCcontrol : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpThetaref = nullptr;
    double* mpPsiref = nullptr;
    double* mpPhi = nullptr;
    double* mpTheta = nullptr;
    double* mpPsi = nullptr;
    double* mpQb = nullptr;
    double* mpRb = nullptr;
    double* mpKelev = nullptr;
    double* mpKrud = nullptr;
    double* mpKQrud = nullptr;
    double* mpKRrud = nullptr;
    double* mpUmin = nullptr;
    double* mpUmax = nullptr;
    double* mpUelev = nullptr;
    double* mpUrud = nullptr;
};

} // namespace tlmhub
