#pragma once
#include "core/Component.h"
#include "core/numerics/SecondOrderTransferFunction.h"

namespace tlmhub {

// Second-order filter with gain and limits:
// G(s) = k (1 + 2 d1 s/w1 + s^2/w1^2) / (1 + 2 d2 s/w2 + s^2/w2^2).
class SignalSecondOrderFilter : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn = nullptr;
    double* mpOut = nullptr;
    double mK = 1.0;
    double mOmega_1 = 10000000000.0;
    double mDelta_1 = 1.0;
    double mOmega_2 = 1000.0;
    double mDelta_2 = 1.0;
    double mY_min = -1.5e+300;
    double mY_max = 1.5e+300;
    SecondOrderTransferFunction mTF;
};

} // namespace tlmhub
