#pragma once
#include "core/Component.h"

namespace tlmhub {

// Q-type ideal on/off switch; conducting when state > 0.5.
class ElectricSwitch : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpPel1 = nullptr, *mpPel2 = nullptr;
    double* mpIn = nullptr;
    double *mpPel1_u = nullptr, *mpPel1_i = nullptr, *mpPel1_c = nullptr, *mpPel1_Zc = nullptr;
    double *mpPel2_u = nullptr, *mpPel2_i = nullptr, *mpPel2_c = nullptr, *mpPel2_Zc = nullptr;
};

} // namespace tlmhub
