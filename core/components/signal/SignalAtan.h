#pragma once
#include "core/Component.h"

#include <cmath>

namespace tlmhub {

// out = atan(in), evaluated at t0 and every step.
class SignalAtan : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
