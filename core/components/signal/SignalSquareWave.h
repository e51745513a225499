#pragma once
#include "core/Component.h"

#include <cmath>

namespace tlmhub {

// Square wave y_0 +/- y_A: the sign of a sine, so the first half period is high.
class SignalSquareWave : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpY0 = nullptr;
    double* mpYA = nullptr;
    double* mpF = nullptr;
    double* mpTStart = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
