#pragma once
#include "core/Component.h"

namespace tlmhub {

// Q-type source writing externally supplied pressure and flow (no TLM relation).
class HydraulicQSource : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    double *mpInP = nullptr, *mpInQ = nullptr;
    double *mpP1_p = nullptr, *mpP1_q = nullptr;
};

} // namespace tlmhub
