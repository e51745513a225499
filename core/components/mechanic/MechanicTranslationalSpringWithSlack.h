#pragma once
#include "core/Component.h"

namespace tlmhub {

// C-type spring that only transmits force when engaged: disconnected (c = Zc = 0)
// while the sum of the port positions is positive (slack).
class MechanicTranslationalSpringWithSlack : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    Port* mpP2 = nullptr;
    double* mpK = nullptr;
    double *mpP1_x = nullptr, *mpP1_v = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpP2_x = nullptr, *mpP2_v = nullptr, *mpP2_c = nullptr, *mpP2_Zc = nullptr;
};

} // namespace tlmhub
