#pragma once
#include "core/Component.h"

namespace tlmhub {

// Q-type hydraulic motor with its own rotating inertia and viscous friction: the
// displacement turns the pressure drop P1 -> P2 into torque on the shaft Pm1.
class HydraulicMotorJload : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpP1 = nullptr, *mpP2 = nullptr, *mpPm1 = nullptr;
    double *mpDm = nullptr, *mpCim = nullptr, *mpBm = nullptr, *mpJm = nullptr;

    double *mpP1_p = nullptr, *mpP1_q = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpP2_p = nullptr, *mpP2_q = nullptr, *mpP2_c = nullptr, *mpP2_Zc = nullptr;
    double *mpPm1_t = nullptr, *mpPm1_a = nullptr, *mpPm1_w = nullptr, *mpPm1_c = nullptr, *mpPm1_Zc = nullptr;

    // Shaft state and the driving torque of the previous step (trapezoidal rule).
    double mAngle = 0.0, mW = 0.0, mDrive = 0.0;
};

} // namespace tlmhub
