#pragma once
#include "core/Component.h"

namespace tlmhub {

// C-type ideal pressure and temperature source.
class PneumaticPTsrc : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpPp1 = nullptr;
    double *mpPinput = nullptr, *mpTinput = nullptr;
    double *mpPp1_T = nullptr, *mpPp1_c = nullptr, *mpPp1_Zc = nullptr;
};

} // namespace tlmhub
