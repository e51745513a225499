#pragma once
#include "core/Component.h"

#include <cmath>

namespace tlmhub {

// Jump to y_0 + y_A at t_step, then exponential decay back to y_0 with time constant tao.
class SignalStepExponentialDelay : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpY0 = nullptr;
    double* mpYA = nullptr;
    double* mpTao = nullptr;
    double* mpTStep = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
