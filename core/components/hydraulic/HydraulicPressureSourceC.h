#pragma once
#include "core/Component.h"

namespace tlmhub {

// C-type ideal pressure source (zero impedance), pressure from an input variable.
class HydraulicPressureSourceC : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    double* mpIn = nullptr;
    double *mpP1_p = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
};

} // namespace tlmhub
