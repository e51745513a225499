#pragma once
#include "core/Component.h"

#include <cmath>

namespace tlmhub {

// Four-quadrant arc tangent, out = atan2(inY, inX).
class SignalAtan2 : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpInY = nullptr;
    double* mpInX = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
