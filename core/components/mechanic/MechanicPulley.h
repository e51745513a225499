#pragma once
#include "core/Component.h"
#include "core/numerics/FirstOrderTransferFunction.h"
#include "core/numerics/SecondOrderTransferFunction.h"

namespace tlmhub {

// Q-type movable pulley of mass m: the rope end P1 moves twice as far as the pulley P2
// and the force is doubled.
class MechanicPulley : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port *mpP1 = nullptr, *mpP2 = nullptr;
    double mMass = 1.0;
    double* mpB = nullptr;
    double *mpP1_f = nullptr, *mpP1_x = nullptr, *mpP1_v = nullptr, *mpP1_c = nullptr,
           *mpP1_Zx = nullptr, *mpP1_me = nullptr;
    double *mpP2_f = nullptr, *mpP2_x = nullptr, *mpP2_v = nullptr, *mpP2_c = nullptr,
           *mpP2_Zx = nullptr, *mpP2_me = nullptr;
    double mNumX[3] = {1.0, 0.0, 0.0};
    double mDenX[3] = {0.0, 0.0, 0.0};
    double mNumV[2] = {1.0, 0.0};
    double mDenV[2] = {0.0, 0.0};
    SecondOrderTransferFunction mFilterX;
    FirstOrderTransferFunction mFilterV;
};

} // namespace tlmhub
