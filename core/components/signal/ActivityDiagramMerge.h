#pragma once
#include "core/Component.h"

namespace tlmhub {

// Activity-diagram merge transition: a token from Ppn1 (event1) or Ppn2 (event2)
// goes to Ppn3; Ppn1 has priority. Q-type.
class ActivityDiagramMerge : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpEvent1 = nullptr;
    double* mpEvent2 = nullptr;
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
    double mOldEvent1 = 0.0, mOldEvent2 = 0.0;
};

} // namespace tlmhub
