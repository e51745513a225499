#pragma once
#include "core/Component.h"
#include <vector>

namespace tlmhub {

class ActivityDiagramActionN;

// Activity-diagram decision transition: moves the token from Ppn1 to Ppn2 on
// event2 or to Ppn3 on event3 (Ppn2 has priority). Q-type.
class ActivityDiagramDecision : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpEvent2 = nullptr;
    double* mpEvent3 = nullptr;
    double* mpDiffevent = nullptr;
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
        double mOldEvent2 = 0.0, mOldEvent3 = 0.0;
};

} // namespace tlmhub
