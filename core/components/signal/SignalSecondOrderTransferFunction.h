#pragma once
#include "core/Component.h"
#include "core/numerics/SecondOrderTransferFunction.h"

namespace tlmhub {

// General second-order transfer function
// G(s) = (a_0 + a_1 s + a_2 s^2) / (b_0 + b_1 s + b_2 s^2), unlimited.
class SignalSecondOrderTransferFunction : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn = nullptr;
    double* mpOut = nullptr;
    double mA_2 = 1.0;
    double mA_1 = 1.0;
    double mA_0 = 1.0;
    double mB_2 = 1.0;
    double mB_1 = 1.0;
    double mB_0 = 1.0;
    SecondOrderTransferFunction mTF;
};

} // namespace tlmhub
