#pragma once
#include "core/Component.h"

namespace tlmhub {

// Obsolete (0.6.x) Q-type flow source with wave variable/impedance outputs.
class HydraulicQPsrc : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpP1 = nullptr, *mpPqinput = nullptr, *mpPpinput = nullptr;
    double mQinput = 0.0, mPinput = 1.0e5;
    double* mpQ = nullptr;
    double *mpPcout = nullptr, *mpPZcout = nullptr;
    double *mpP1_p = nullptr, *mpP1_q = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
};

} // namespace tlmhub
