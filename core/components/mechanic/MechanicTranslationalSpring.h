#pragma once
#include "core/Component.h"

namespace tlmhub {

// C-type linear spring (TLM element) with optional first-order filtering of the waves.
class MechanicTranslationalSpring : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    Port* mpP2 = nullptr;
    double mAlpha = 0.0;
    double* mpK = nullptr;
    double *mpP1_f = nullptr, *mpP1_v = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpP2_f = nullptr, *mpP2_v = nullptr, *mpP2_c = nullptr, *mpP2_Zc = nullptr;
};

} // namespace tlmhub
