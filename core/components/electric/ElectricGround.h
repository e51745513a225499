#pragma once
#include "core/Component.h"

namespace tlmhub {

// C-type ideal electric ground: presents c = 0, Zc = 0 to its node.
class ElectricGround : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpPel1 = nullptr;
    double *mpPel1_c = nullptr, *mpPel1_Zc = nullptr;
};

} // namespace tlmhub
