#pragma once
#include "core/Component.h"

namespace tlmhub {

// Aircraft attitude autopilot: aileron, elevator and rudder commands from attitude
// errors with speed-dependent gain scheduling (U0) and saturation. No state.
class SignalAttitudeControl : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpPhiref = nullptr;
    double* mpThetaref = nullptr;
    double* mpPsiref = nullptr;
    double* mpPhimax = nullptr;
    double* mpPhi = nullptr;
    double* mpTheta = nullptr;
    double* mpPsi = nullptr;
    double* mpBeta = nullptr;
    double* mpQb = nullptr;
    double* mpRb = nullptr;
    double* mpUb = nullptr;
    double* mpKphi = nullptr;
    double* mpKphipsi = nullptr;
    double* mpKelev = nullptr;
    double* mpKdelev = nullptr;
    double* mpKrud = nullptr;
    double* mpKdrud = nullptr;
    double* mpU1min = nullptr;
    double* mpU1max = nullptr;
    double* mpU2min = nullptr;
    double* mpU2max = nullptr;
    double* mpU3min = nullptr;
    double* mpU3max = nullptr;
    double* mpU0 = nullptr;
    double* mpUaerL = nullptr;
    double* mpUaerR = nullptr;
    double* mpUelev = nullptr;
    double* mpUrud = nullptr;
};

} // namespace tlmhub
