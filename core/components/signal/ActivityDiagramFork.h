#pragma once
#include "core/Component.h"
#include <vector>

namespace tlmhub {

class ActivityDiagramActionN;

// Activity-diagram fork transition: one token from Ppn1 into both Ppn2 and Ppn3. Q-type.
class ActivityDiagramFork : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpEvent = nullptr;
    double* mpDiffEvent = nullptr;
    Port* mpPpn1 = nullptr;
    Port* mpPpn2 = nullptr;
    Port* mpPpn3 = nullptr;
    double* mpS1 = nullptr;
    double* mpQ1 = nullptr;
    double* mpS2 = nullptr;
    double* mpQ2 = nullptr;
    double* mpS3 = nullptr;
    double* mpQ3 = nullptr;
        std::vector<ActivityDiagramActionN*> mLock1, mLock2, mLock3;
        double mOldEvent = 0.0;
};

} // namespace tlmhub
