#pragma once
#include "core/Component.h"
#include "core/numerics/FirstOrderTransferFunction.h"

namespace tlmhub {

// First-order low-pass filter G(s) = 1 / (1 + s/omega) with output limits.
// The state starts from out#Value, not from the input (reference behaviour).
class SignalLP1Filter : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn = nullptr;
    double* mpOut = nullptr;
    double mOmega = 1000.0;
    double mY_min = -1.5e+300;
    double mY_max = 1.5e+300;
    FirstOrderTransferFunction mTF;
};

} // namespace tlmhub
