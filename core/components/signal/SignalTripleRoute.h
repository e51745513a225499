#pragma once
#include "core/Component.h"

namespace tlmhub {

// Selects in1, in2 or in3 by comparing route with limit12 and limit23 (also at t0).
class SignalTripleRoute : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn1 = nullptr;
    double* mpIn2 = nullptr;
    double* mpIn3 = nullptr;
    double* mpRoute = nullptr;
    double* mpOut = nullptr;
    double mLimit12 = 0.5;
    double mLimit23 = 1.5;
};

} // namespace tlmhub
