#pragma once
#include "core/Component.h"
#include "core/numerics/FirstOrderTransferFunction.h"

namespace tlmhub {

// General first-order transfer function G(s) = (a_0 + a_1 s) / (b_0 + b_1 s), unlimited.
class SignalFirstOrderTransferFunction : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn = nullptr;
    double* mpOut = nullptr;
    double mA_1 = 1.0;
    double mA_0 = 1.0;
    double mB_1 = 1.0;
    double mB_0 = 1.0;
    FirstOrderTransferFunction mTF;
};

} // namespace tlmhub
