#pragma once
#include "core/Component.h"
#include <vector>

namespace tlmhub {

class ActivityDiagramActionN;

// Activity-diagram transition from Ppn1 to Ppn2 gated by an event. With edge
// triggering the pending edge stays armed until it can fire. Q-type.
class ActivityDiagramEdge : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpEvent = nullptr;
    double* mpDiffEvent = nullptr;
    Port* mpPpn1 = nullptr;
    Port* mpPpn2 = nullptr;
    double* mpS1 = nullptr;
    double* mpQ1 = nullptr;
    double* mpS2 = nullptr;
    double* mpQ2 = nullptr;
        std::vector<ActivityDiagramActionN*> mLock1, mLock2;
        double mOldEvent = 0.0;
};

} // namespace tlmhub
