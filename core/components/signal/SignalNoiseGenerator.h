#pragma once
#include "core/Component.h"

namespace tlmhub {

// White Gaussian noise scaled by std_dev; initialize() already draws one sample.
class SignalNoiseGenerator : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    RandomStream* mpRandom = nullptr;
    double* mpStdDev = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
