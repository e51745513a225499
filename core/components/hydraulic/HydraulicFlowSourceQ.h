#pragma once
#include "core/Component.h"

namespace tlmhub {

// Q-type ideal flow source; positive flow is delivered into the node.
class HydraulicFlowSourceQ : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    double* mpIn = nullptr;
    double *mpP1_p = nullptr, *mpP1_q = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
};

} // namespace tlmhub
