#pragma once
#include "core/Component.h"

namespace tlmhub {

// Q-type variable-displacement pump with prescribed speed and leakage.
class HydraulicVariableDisplacementPump : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpP1 = nullptr, *mpP2 = nullptr;
    double *mpEps = nullptr, *mpN = nullptr, *mpDp = nullptr, *mpKcp = nullptr, *mpA = nullptr;
    double *mpP1_p = nullptr, *mpP1_q = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpP2_p = nullptr, *mpP2_q = nullptr, *mpP2_c = nullptr, *mpP2_Zc = nullptr;
};

} // namespace tlmhub
