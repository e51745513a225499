#pragma once
#include "core/Component.h"
#include "core/numerics/FirstOrderTransferFunction.h"
#include "core/numerics/SecondOrderTransferFunction.h"

#include <vector>

namespace tlmhub {

// Q-type rotating cylinder block with swash plate: turns the shaft rotation into
// piston strokes (one mechanic sub-port per piston on P1) and the piston forces
// into shaft torque; the block inertia is integrated internally.
class MechanicCylinderBlockWithSwashPlate : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpP1 = nullptr, *mpP2 = nullptr;
    double *mpB = nullptr, *mpR = nullptr, *mpThetaOffset = nullptr, *mpAngle = nullptr;
    double *mpTorque = nullptr, *mpMovement = nullptr;
    double mJ = 0.1, mMp = 0.001, mRp = 0.01;

    std::size_t mN = 0;
    std::vector<double*> mvpP1_f, mvpP1_x, mvpP1_v, mvpP1_c, mvpP1_Zc, mvpP1_me;
    std::vector<double> mC1, mZc1;
    double *mpP2_t = nullptr, *mpP2_a = nullptr, *mpP2_w = nullptr, *mpP2_c = nullptr,
           *mpP2_Zc = nullptr;

    double mStartX = 0.0;
    double mA2 = 0.0; // block angle of the previous step
    SecondOrderTransferFunction mFilterX;
    FirstOrderTransferFunction mFilterV;
};

} // namespace tlmhub
