#pragma once
#include "core/Component.h"

namespace tlmhub {

// Limits the rate of change of a signal with separate rising (c_up) and falling
// (c_down, negative) rates; the sign of the rate is used as given.
class SignalRateLimiter : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpC_up = nullptr;
    double* mpC_down = nullptr;
    double* mpIn = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
