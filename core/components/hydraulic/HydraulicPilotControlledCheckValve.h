#pragma once
#include "core/Component.h"
#include "core/numerics/TurbulentFlowFunction.h"

namespace tlmhub {

// Q-type check valve that a pilot pressure can force open. The pilot port draws no flow.
class HydraulicPilotControlledCheckValve : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    Port* mpP2 = nullptr;
    TurbulentFlowFunction mQTurb;
    double *mpP1_p = nullptr, *mpP1_q = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpP2_p = nullptr, *mpP2_q = nullptr, *mpP2_c = nullptr, *mpP2_Zc = nullptr;
    Port* mpPilot = nullptr;
    double *mpPilot_p = nullptr, *mpPilot_c = nullptr;
    double* mpPhi = nullptr;
    double* mpPf = nullptr;
    double* mpX = nullptr;
    double mKs = 5e-7;
};

} // namespace tlmhub
