#pragma once
#include "core/Component.h"

namespace tlmhub {

// C-type torsional shaft whose stiffness follows from its geometry and shear modulus;
// otherwise as MechanicRotShaft.
class MechanicRotShaftG : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double impedance() const;

    Port* mpPmr1 = nullptr;
    Port* mpPmr2 = nullptr;
    double *mpDy = nullptr, *mpDi = nullptr, *mpLen = nullptr, *mpG = nullptr, *mpAlpha = nullptr;
    double *mpPmr1_w = nullptr, *mpPmr1_c = nullptr, *mpPmr1_Zc = nullptr;
    double *mpPmr2_w = nullptr, *mpPmr2_c = nullptr, *mpPmr2_Zc = nullptr;
    double mCmr1 = 0.0, mCmr2 = 0.0, mCmr1f = 0.0, mCmr2f = 0.0;
};

} // namespace tlmhub
