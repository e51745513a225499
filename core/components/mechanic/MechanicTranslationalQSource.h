#pragma once
#include "core/Component.h"

namespace tlmhub {

// Q-type source writing signal-given force, velocity, position and equivalent mass
// (no TLM relation applied).
class MechanicTranslationalQSource : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    double *mpInF = nullptr, *mpInV = nullptr, *mpInX = nullptr, *mpInEm = nullptr;
    double *mpP1_f = nullptr, *mpP1_v = nullptr, *mpP1_x = nullptr, *mpP1_me = nullptr;
};

} // namespace tlmhub
