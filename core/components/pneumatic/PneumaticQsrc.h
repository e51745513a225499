#pragma once
#include "core/Component.h"

namespace tlmhub {

// Q-type ideal mass-flow source carrying energy flow.
class PneumaticQsrc : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpPp1 = nullptr;
    double *mpQminput = nullptr, *mpTinput = nullptr, *mpCv = nullptr;
    double mCv = 0.0;
    double *mpPp1_p = nullptr, *mpPp1_qm = nullptr, *mpPp1_T = nullptr, *mpPp1_dE = nullptr, *mpPp1_c = nullptr,
           *mpPp1_Zc = nullptr;
};

} // namespace tlmhub
