#pragma once
#include "core/Component.h"

namespace tlmhub {

// Q-type immovable wall: zero velocity, the force equals the incoming wave.
class MechanicFixedPosition : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpPm1 = nullptr;
    double mMe = 1.0;
    double *mpPm1_f = nullptr, *mpPm1_v = nullptr, *mpPm1_c = nullptr, *mpPm1_me = nullptr;
};

} // namespace tlmhub
