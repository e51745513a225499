#pragma once
#include "core/Component.h"

namespace tlmhub {

// C-type source writing an externally supplied wave variable and impedance.
class HydraulicCSource : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    double *mpInC = nullptr, *mpInZ = nullptr;
    double *mpP1_c = nullptr, *mpP1_Zc = nullptr;
};

} // namespace tlmhub
