#pragma once
#include "core/Component.h"
#include "core/numerics/FirstOrderTransferFunction.h"
#include "core/numerics/SecondOrderTransferFunction.h"

namespace tlmhub {

// Fork lifter head (Hopsan's TMMS04 course component): a traversing carriage driven through
// a pinion on the rotational port P1, and fork arms tilted by two opposing pistons on P2
// and P3. Each motion is a mass (inertia) with viscous friction and a spring between end
// stops, solved with transfer functions as in Hopsan.
class Forks : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double mR = 0.1, mM = 100.0, mSl = 1.0, mRrot = 0.1, mJ = 0.2;
    double *mpB = nullptr, *mpK = nullptr, *mpXMin = nullptr, *mpXMax = nullptr;
    double *mpKfrot = nullptr, *mpBrot = nullptr, *mpKrot = nullptr, *mpAMin = nullptr, *mpAMax = nullptr;
    double *mpX = nullptr, *mpA = nullptr;
    Port *mpP1 = nullptr, *mpP2 = nullptr, *mpP3 = nullptr;
    double *mpP1_a = nullptr, *mpP1_w = nullptr, *mpP1_T = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpP2_x = nullptr, *mpP2_v = nullptr, *mpP2_f = nullptr, *mpP2_c = nullptr, *mpP2_Zc = nullptr;
    double *mpP3_x = nullptr, *mpP3_v = nullptr, *mpP3_f = nullptr, *mpP3_c = nullptr, *mpP3_Zc = nullptr;
    SecondOrderTransferFunction mTraversePosition, mTiltAngle;
    FirstOrderTransferFunction mTraverseSpeed, mTiltSpeed;
};

} // namespace tlmhub
