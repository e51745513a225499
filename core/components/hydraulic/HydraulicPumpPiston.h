#pragma once
#include "core/Component.h"

namespace tlmhub {

// C-type single piston chamber: a hydraulic volume whose size follows the piston
// position, modelled as a three-port TLM volume (piston, leakage, external port).
class HydraulicPumpPiston : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpP1 = nullptr, *mpP3 = nullptr;
    double *mpA1 = nullptr, *mpSl = nullptr, *mpV1 = nullptr, *mpBp = nullptr;
    double *mpBetae = nullptr, *mpCleak = nullptr, *mpF0 = nullptr;

    double *mpP1_p = nullptr, *mpP1_q = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpP3_x = nullptr, *mpP3_v = nullptr, *mpP3_c = nullptr, *mpP3_Zc = nullptr,
           *mpP3_me = nullptr;

    const double mWfak = 0.1, mAlpha = 0.1;
    double mCi1 = 0.0; // wave variable of the internal piston-side port
    double mCl1 = 0.0; // wave variable of the internal leakage port
};

} // namespace tlmhub
