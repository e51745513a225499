#pragma once
#include "core/Component.h"

namespace tlmhub {

// Guidance to one waypoint: heading, altitude and speed references while the leg
// is active (s1), and set1 = 1 when within wptol of the waypoint. No state.
class SignalWaypoint : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpS1 = nullptr;
    double* mpXc = nullptr;
    double* mpYc = nullptr;
    double* mpR = nullptr;
    double* mpAlt1 = nullptr;
    double* mpV1 = nullptr;
    double* mpWptol = nullptr;
    double* mpXcWp1 = nullptr;
    double* mpYcWp1 = nullptr;
    double* mpSet1 = nullptr;
    double* mpAltitudeRef = nullptr;
    double* mpHeadingRef = nullptr;
    double* mpVelocityRef = nullptr;
    double* mpDistanceWp = nullptr;
};

} // namespace tlmhub
