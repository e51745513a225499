#pragma once
#include "core/Component.h"

namespace tlmhub {

// C-type torsional spring shaft with first-order filtered waves (numerical damping).
class MechanicRotShaft : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpPmr1 = nullptr;
    Port* mpPmr2 = nullptr;
    double *mpKs = nullptr, *mpAlpha = nullptr;
    double *mpPmr1_w = nullptr, *mpPmr1_c = nullptr, *mpPmr1_Zc = nullptr;
    double *mpPmr2_w = nullptr, *mpPmr2_c = nullptr, *mpPmr2_Zc = nullptr;
    double mCmr1 = 0.0, mCmr2 = 0.0, mCmr1f = 0.0, mCmr2f = 0.0;
};

} // namespace tlmhub
