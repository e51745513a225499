#pragma once
#include "core/Component.h"

#include <cmath>
#include <algorithm>

namespace tlmhub {

// Staircase from 0 rising by H_step every W_step after T_start; out#Value only sets the t0 sample.
class SignalStaircase : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpTStart = nullptr;
    double* mpHStep = nullptr;
    double* mpWStep = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
