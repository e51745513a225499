#pragma once
#include "core/Component.h"

namespace tlmhub {

// C-type ideal torsional spring (undamped, unfiltered TLM element).
class MechanicTorsionalSpring : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    Port* mpP2 = nullptr;
    double mK = 100.0;
    double mZx = 0.0;
    double *mpP1_w = nullptr, *mpP1_c = nullptr, *mpP1_Zx = nullptr;
    double *mpP2_w = nullptr, *mpP2_c = nullptr, *mpP2_Zx = nullptr;
};

} // namespace tlmhub
