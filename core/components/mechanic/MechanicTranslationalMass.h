#pragma once
#include "core/Component.h"
#include "core/numerics/FirstOrderTransferFunction.h"
#include "core/numerics/SecondOrderTransferFunction.h"

namespace tlmhub {

// Q-type rigid mass with viscous friction, optional spring to ground and end stops on
// the P2 position. Position and velocity come from two separate filters.
class MechanicTranslationalMass : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    Port* mpP2 = nullptr;
    double mMass = 100.0;
    double mLength = 0.0;
    double *mpB = nullptr, *mpK = nullptr, *mpXMin = nullptr, *mpXMax = nullptr;
    double *mpP1_f = nullptr, *mpP1_x = nullptr, *mpP1_v = nullptr, *mpP1_c = nullptr,
           *mpP1_Zx = nullptr, *mpP1_me = nullptr;
    double *mpP2_f = nullptr, *mpP2_x = nullptr, *mpP2_v = nullptr, *mpP2_c = nullptr,
           *mpP2_Zx = nullptr, *mpP2_me = nullptr;
    double mNum[3] = {1.0, 0.0, 0.0};
    double mDen[3] = {0.0, 0.0, 0.0};
    double mNumV[2] = {1.0, 0.0};
    double mDenV[2] = {0.0, 0.0};
    SecondOrderTransferFunction mFilterX;
    FirstOrderTransferFunction mFilterV;
};

} // namespace tlmhub
