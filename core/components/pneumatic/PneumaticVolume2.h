#pragma once
#include "core/Component.h"
#include "core/components/pneumatic/PneumaticPortData.h"

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
    PneumaticPortData mPp1, mPp2;
};

} // namespace tlmhub
