#pragma once
#include "core/Component.h"

namespace tlmhub {

// Step from y_0 to y_0 + y_A at t_step (present at the first sample with time >= t_step).
class SignalStep : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpY0 = nullptr;
    double* mpYA = nullptr;
    double* mpTStep = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
