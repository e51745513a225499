#pragma once
#include "core/Component.h"

namespace tlmhub {

// Adds white Gaussian noise (the simulation's random stream) to a signal.
class SignalAdditiveNoise : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    RandomStream* mpRandom = nullptr;
    double* mpIn = nullptr;
    double* mpStd_dev = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
