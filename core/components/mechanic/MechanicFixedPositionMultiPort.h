#pragma once
#include "core/Component.h"

#include <vector>

namespace tlmhub {

// Q-type immovable wall accepting any number of translational connections.
class MechanicFixedPositionMultiPort : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpPm1 = nullptr;
    double mMe = 1.0;
    std::vector<double*> mF, mC;
};

} // namespace tlmhub
