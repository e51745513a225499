#pragma once
#include "core/Component.h"

namespace tlmhub {

// C-type lumped volume between two ports: one-step TLM element with low-pass
// filtered wave variables.
class HydraulicVolume : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    Port* mpP2 = nullptr;
    double* mpAlpha = nullptr;
    double mV = 1.0e-3;
    double mBetae = 1.0e9;
    double mPhigh = 2e7;
    double mZc = 0.0;
    double *mpP1_q = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpP2_q = nullptr, *mpP2_c = nullptr, *mpP2_Zc = nullptr;
};

} // namespace tlmhub
