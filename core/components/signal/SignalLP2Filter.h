#pragma once
#include "core/Component.h"
#include "core/numerics/SecondOrderTransferFunction.h"

namespace tlmhub {

// Second-order low-pass filter G(s) = 1 / (1 + 2 delta s/omega + s^2/omega^2) with limits.
class SignalLP2Filter : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn = nullptr;
    double* mpOut = nullptr;
    double mOmega = 1000.0;
    double mDelta = 1.0;
    double mY_min = -1.5e+300;
    double mY_max = 1.5e+300;
    SecondOrderTransferFunction mTF;
};

} // namespace tlmhub
