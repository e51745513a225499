#pragma once
#include "core/Component.h"

namespace tlmhub {

// Q-type ideal current source.
class ElectricIsource : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpPel1 = nullptr;
    double* mpIin = nullptr;
    double *mpPel1_u = nullptr, *mpPel1_i = nullptr, *mpPel1_c = nullptr, *mpPel1_Zc = nullptr;
};

} // namespace tlmhub
