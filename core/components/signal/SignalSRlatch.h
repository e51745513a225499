#pragma once
#include "core/Component.h"

namespace tlmhub {

// Reset-dominant set/reset latch on inputs clamped to [0, 1]; outputs keep their start values at t0.
class SignalSRlatch : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpSet = nullptr;
    double* mpReset = nullptr;
    double* mpQ = nullptr;
    double* mpNotQ = nullptr;
    double mQold = 0.0;
};

} // namespace tlmhub
