#pragma once
#include "core/Component.h"

namespace tlmhub {

// Q-type blocked port: zero flow, pressure equals the incoming wave.
class HydraulicPlugQ : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    double *mpP1_p = nullptr, *mpP1_q = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
};

} // namespace tlmhub
