#pragma once
#include "core/Component.h"

namespace tlmhub {

// C-type gas volume with two ports: mass balance, energy-based TLM impedance, heat exchange.
class PneumaticVolume2 : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpPp1 = nullptr, *mpPp2 = nullptr;
    double *mpV = nullptr, *mpR = nullptr, *mpCv = nullptr, *mpKa = nullptr, *mpT0 = nullptr, *mpAlpha = nullptr,
           *mpPmin = nullptr;
    double* mpMass = nullptr;
    double mV = 0.0, mR = 0.0, mCv = 0.0, mKa = 0.0, mT0 = 0.0, mPmin = 0.0, mFak = 0.0;
    double mMass = 0.0, mC1 = 0.0, mC2 = 0.0, mDelayed1 = 0.0;
    double *mpPp1_p = nullptr, *mpPp1_qm = nullptr, *mpPp1_T = nullptr, *mpPp1_dE = nullptr, *mpPp1_c = nullptr,
           *mpPp1_Zc = nullptr;
    double *mpPp2_p = nullptr, *mpPp2_qm = nullptr, *mpPp2_T = nullptr, *mpPp2_dE = nullptr, *mpPp2_c = nullptr,
           *mpPp2_Zc = nullptr;
};

} // namespace tlmhub
