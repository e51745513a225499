#pragma once
#include "core/Component.h"

namespace tlmhub {

// Signal sensor exposing every variable of a translational node.
class MechanicNodeSensor : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    double *mpP1_f = nullptr, *mpP1_v = nullptr, *mpP1_x = nullptr, *mpP1_c = nullptr,
           *mpP1_Zc = nullptr, *mpP1_me = nullptr;
    double *mpOutF = nullptr, *mpOutV = nullptr, *mpOutX = nullptr, *mpOutC = nullptr,
           *mpOutZ = nullptr, *mpOutEm = nullptr;
};

} // namespace tlmhub
