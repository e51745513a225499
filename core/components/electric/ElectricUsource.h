#pragma once
#include "core/Component.h"

namespace tlmhub {

// C-type ideal voltage source (zero internal impedance).
class ElectricUsource : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpPel1 = nullptr;
    double* mpUin = nullptr;
    double *mpPel1_c = nullptr, *mpPel1_Zc = nullptr;
};

} // namespace tlmhub
