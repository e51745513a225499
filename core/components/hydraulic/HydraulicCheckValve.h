#pragma once
#include "core/Component.h"
#include "core/numerics/TurbulentFlowFunction.h"

namespace tlmhub {

// Q-type ideal check valve: turbulent flow from P1 to P2 only.
class HydraulicCheckValve : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    Port* mpP2 = nullptr;
    double* mpKs = nullptr;
    double* mpX = nullptr;
    TurbulentFlowFunction mQTurb;
    double *mpP1_p = nullptr, *mpP1_q = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpP2_p = nullptr, *mpP2_q = nullptr, *mpP2_c = nullptr, *mpP2_Zc = nullptr;
};

} // namespace tlmhub
