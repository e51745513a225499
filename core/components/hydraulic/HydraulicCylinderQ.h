#pragma once
#include "core/Component.h"
#include "core/numerics/FirstOrderTransferFunction.h"
#include "core/numerics/SecondOrderTransferFunction.h"

namespace tlmhub {

// Q-type cylinder with its own load (mass, damping, stiffness) solved with
// transfer functions; position limited to [0, s_l].
class HydraulicCylinderQ : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpP1 = nullptr, *mpP2 = nullptr, *mpP3 = nullptr;
    double *mpA1 = nullptr, *mpA2 = nullptr, *mpBp = nullptr, *mpBl = nullptr, *mpKl = nullptr;
    double mMass = 0.05;
    double mSl = 0.01;
    SecondOrderTransferFunction mPositionTF;
    FirstOrderTransferFunction mVelocityTF;
    double mPosNum[3] = {1.0, 0.0, 0.0};
    double mPosDen[3] = {0.0, 0.0, 0.0};
    double mVelNum[2] = {1.0, 0.0};
    double mVelDen[2] = {0.0, 0.0};
    double *mpP1_p = nullptr, *mpP1_q = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpP2_p = nullptr, *mpP2_q = nullptr, *mpP2_c = nullptr, *mpP2_Zc = nullptr;
    double *mpP3_f = nullptr, *mpP3_x = nullptr, *mpP3_v = nullptr, *mpP3_c = nullptr, *mpP3_Zx = nullptr;
};

} // namespace tlmhub
