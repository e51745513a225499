#pragma once
#include "core/Component.h"

namespace tlmhub {

// Q-type ideal voltage source; the subtype "Ground" is this type with U = 0.
class ElectricVoltageSourceQ : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpPel1 = nullptr;
    double* mpU = nullptr;
    double *mpPel1_u = nullptr, *mpPel1_i = nullptr, *mpPel1_c = nullptr, *mpPel1_Zc = nullptr;
};

} // namespace tlmhub
