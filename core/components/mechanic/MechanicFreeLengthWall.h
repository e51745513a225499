#pragma once
#include "core/Component.h"
#include "core/numerics/FirstOrderTransferFunction.h"

namespace tlmhub {

// Q-type massless end stop: force free until the port reaches stop_pos, then it holds
// the port at the stop.
class MechanicFreeLengthWall : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpPm1 = nullptr;
    double mMe = 1.0;
    double mStopPos = 0.0;
    double* mpB = nullptr;
    double *mpPm1_f = nullptr, *mpPm1_x = nullptr, *mpPm1_v = nullptr, *mpPm1_c = nullptr,
           *mpPm1_Zx = nullptr, *mpPm1_me = nullptr;
    double mNum[2] = {1.0, 0.0};
    double mDenX[2] = {0.0, 0.0};
    double mDenV[2] = {0.0, 0.0};
    FirstOrderTransferFunction mFilterX;
    FirstOrderTransferFunction mFilterV;
};

} // namespace tlmhub
