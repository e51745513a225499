#pragma once
#include "core/Component.h"
#include "core/numerics/Delay.h"
#include "core/numerics/ValveHysteresis.h"

namespace tlmhub {

// Backlash element: the held output follows the input only when the input moves
// more than y_h/2 away from it.
class SignalHysteresis : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn = nullptr;
    double* mpY_h = nullptr;
    double* mpOut = nullptr;
    Delay mDelay;
    ValveHysteresis mHyst;
};

} // namespace tlmhub
