#pragma once
#include "core/Component.h"

namespace tlmhub {

// Adds white Gaussian noise (C library rand(), never seeded here) to a signal.
class SignalAdditiveNoise : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn = nullptr;
    double* mpStd_dev = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
