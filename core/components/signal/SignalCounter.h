#pragma once
#include "core/Component.h"

namespace tlmhub {

// Counts rising (r) and/or falling (f) edges of a boolean input (true when > 0.5).
class SignalCounter : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn = nullptr;
    double* mpOut = nullptr;
    bool mRising = true;
    bool mFalling = true;
    bool mPrev = false;
};

} // namespace tlmhub
