#pragma once
#include "core/Component.h"
#include "core/numerics/SecondOrderTransferFunction.h"

namespace tlmhub {

// Second-order high-pass filter
// G(s) = (s^2/omega^2) / (1 + 2 delta s/omega + s^2/omega^2) with limits.
class SignalHP2Filter : public ComponentSignal {
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
