#pragma once
#include "core/Component.h"

namespace tlmhub {

// Q-type linear resistor given by its conductance (frozen at initialisation).
class ElectricResistor : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpPel1 = nullptr, *mpPel2 = nullptr;
    double* mpConduct = nullptr;
    double mConduct = 0.0;
    double *mpPel1_u = nullptr, *mpPel1_i = nullptr, *mpPel1_c = nullptr, *mpPel1_Zc = nullptr;
    double *mpPel2_u = nullptr, *mpPel2_i = nullptr, *mpPel2_c = nullptr, *mpPel2_Zc = nullptr;
};

} // namespace tlmhub
