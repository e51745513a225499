#pragma once
#include "core/Component.h"
#include "core/numerics/Delay.h"

namespace tlmhub {

// C-type lossless transmission line with given impedance and time delay.
class HydraulicTLMlossless : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    Port* mpP2 = nullptr;
    double* mpAlpha = nullptr;
    double* mpZc = nullptr;
    double mTimeDelay = 0.1;
    Delay mDelayedC1;
    Delay mDelayedC2;
    double *mpP1_p = nullptr, *mpP1_q = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpP2_p = nullptr, *mpP2_q = nullptr, *mpP2_c = nullptr, *mpP2_Zc = nullptr;
};

} // namespace tlmhub
