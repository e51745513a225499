#pragma once
#include "core/Component.h"
#include "core/numerics/FirstOrderTransferFunction.h"
#include "core/numerics/SecondOrderTransferFunction.h"

namespace tlmhub {

// Q-type inertia J (referred to P2) with viscous friction and gear ratio U: w1 = -U*w2.
class MechanicRotationalInertiaWithGearRatio : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    Port* mpP2 = nullptr;
    double mJ = 1.0;
    double *mpOmega = nullptr, *mpB = nullptr;
    double *mpP1_T = nullptr, *mpP1_a = nullptr, *mpP1_w = nullptr, *mpP1_c = nullptr,
           *mpP1_Zx = nullptr;
    double *mpP2_T = nullptr, *mpP2_a = nullptr, *mpP2_w = nullptr, *mpP2_c = nullptr,
           *mpP2_Zx = nullptr;
    double mNumTheta[3] = {1.0, 0.0, 0.0};
    double mDenTheta[3] = {0.0, 0.0, 0.0};
    double mNumOmega[2] = {1.0, 0.0};
    double mDenOmega[2] = {0.0, 0.0};
    SecondOrderTransferFunction mFilterTheta;
    FirstOrderTransferFunction mFilterOmega;
};

} // namespace tlmhub
