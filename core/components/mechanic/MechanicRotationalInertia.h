#pragma once
#include "core/Component.h"
#include "core/numerics/FirstOrderTransferFunction.h"
#include "core/numerics/SecondOrderTransferFunction.h"

namespace tlmhub {

// Q-type rotational inertia with viscous friction, optional spring to ground and angle
// limits on P2. P1 turns opposite to P2.
class MechanicRotationalInertia : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    Port* mpP2 = nullptr;
    double mJ = 0.1;
    double *mpB = nullptr, *mpK = nullptr, *mpAMin = nullptr, *mpAMax = nullptr;
    double *mpP1_T = nullptr, *mpP1_a = nullptr, *mpP1_w = nullptr, *mpP1_c = nullptr,
           *mpP1_Zx = nullptr;
    double *mpP2_T = nullptr, *mpP2_a = nullptr, *mpP2_w = nullptr, *mpP2_c = nullptr,
           *mpP2_Zx = nullptr;
    double mNumX[3] = {1.0, 0.0, 0.0};
    double mDenX[3] = {0.0, 0.0, 0.0};
    double mNumV[2] = {1.0, 0.0};
    double mDenV[2] = {0.0, 0.0};
    SecondOrderTransferFunction mFilterX;
    FirstOrderTransferFunction mFilterV;
};

} // namespace tlmhub
