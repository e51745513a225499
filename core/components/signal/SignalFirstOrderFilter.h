#pragma once
#include "core/Component.h"
#include "core/numerics/FirstOrderTransferFunction.h"

namespace tlmhub {

// First-order lead/lag filter with gain and output limits:
// G(s) = k (1 + s/omega_num) / (1 + s/omega_den).
class SignalFirstOrderFilter : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn = nullptr;
    double* mpOut = nullptr;
    double mK = 1.0;
    double mOmega_num = 10000000000.0;
    double mOmega_den = 1000.0;
    double mY_min = -1.5e+300;
    double mY_max = 1.5e+300;
    FirstOrderTransferFunction mTF;
};

} // namespace tlmhub
