#pragma once
#include "core/Component.h"
#include "core/numerics/Delay.h"

namespace tlmhub {

// Fixed transport delay of round(deltat/h) steps (at least one step).
class SignalTimeDelay : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn = nullptr;
    double* mpOut = nullptr;
    double mDeltat = 1.0;
    Delay mDelay;
};

} // namespace tlmhub
