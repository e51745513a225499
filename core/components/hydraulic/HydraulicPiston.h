#pragma once
#include "core/Component.h"

namespace tlmhub {

// C-type double-acting piston without mass: two oil chambers (P1, P2) whose volumes
// follow the rod position, coupled as TLM volumes to the mechanic port Pm1.
class HydraulicPiston : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpP1 = nullptr, *mpP2 = nullptr, *mpPm1 = nullptr;
    double *mpA1 = nullptr, *mpA2 = nullptr, *mpV01 = nullptr, *mpV02 = nullptr;
    double *mpSL = nullptr, *mpBetae = nullptr, *mpAlpha = nullptr;

    double *mpP1_q = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpP2_q = nullptr, *mpP2_c = nullptr, *mpP2_Zc = nullptr;
    double *mpPm1_x = nullptr, *mpPm1_v = nullptr, *mpPm1_c = nullptr, *mpPm1_Zc = nullptr;

    // Waves at the oil ports (c1, c2) and at the piston faces (cp1, cp2), filtered.
    double mC1 = 0.0, mC2 = 0.0, mCp1 = 0.0, mCp2 = 0.0;
};

} // namespace tlmhub
