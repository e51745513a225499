#pragma once
#include "core/Component.h"

namespace tlmhub {

// Selects in1 when route < limit, otherwise in2 (also at t0).
class SignalDualRoute : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn1 = nullptr;
    double* mpIn2 = nullptr;
    double* mpRoute = nullptr;
    double* mpOut = nullptr;
    double mLimit = 0.5;
};

} // namespace tlmhub
