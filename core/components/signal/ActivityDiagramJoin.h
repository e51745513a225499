#pragma once
#include "core/Component.h"

namespace tlmhub {

// Activity-diagram join transition: Ppn1 and Ppn2 both marked -> one token to
// Ppn3 while event > 0 (diffEvent has no effect, as in the reference). Q-type.
class ActivityDiagramJoin : public ComponentQ {
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
    double mOldEvent = 0.0;
};

} // namespace tlmhub
