#pragma once
#include "core/Component.h"

namespace tlmhub {

// Zero-order hold sampling at f_s. f_s is read only at initialisation.
class SignalSampleAndHold : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpF_s = nullptr;
    double* mpIn = nullptr;
    double* mpOut = nullptr;
    double mTnext = 0.0;
    double mTs = 0.0;
};

} // namespace tlmhub
