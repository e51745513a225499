#pragma once
#include "core/Component.h"

namespace tlmhub {

// JK-style latch on inputs clamped to [0, 1]: set, reset, hold, or toggle when both are set.
class SignalJKlatch : public ComponentSignal {
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
