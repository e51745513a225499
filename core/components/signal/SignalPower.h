#pragma once
#include "core/Component.h"

#include <cmath>

namespace tlmhub {

// out = pow(|in|, x): the base is the absolute value, so the sign of `in` is lost.
class SignalPower : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn = nullptr;
    double* mpX = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
