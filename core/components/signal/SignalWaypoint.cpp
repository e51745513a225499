#include "core/components/signal/SignalWaypoint.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"
#include "core/numerics/MathematicaWrappers.h"

namespace tlmhub {

void SignalWaypoint::configure()
{
    addInputVariable("s1", "Activation of this leg", "", 0.0, &mpS1);
    addInputVariable("xc", "Current longitude (degrees)", "m", 0.0, &mpXc);
    addInputVariable("yc", "Current latitude (degrees)", "m", 0.0, &mpYc);
    addInputVariable("R", "Earth radius", "m", 6367500.0, &mpR);
    addInputVariable("alt1", "Altitude reference", "m", 0.0, &mpAlt1);
    addInputVariable("v1", "Speed reference", "m/s", 200.0, &mpV1);
    addInputVariable("wptol", "Waypoint tolerance", "m", 500.0, &mpWptol);
    addInputVariable("xcWp1", "Waypoint longitude", "deg", 15.1669, &mpXcWp1);
    addInputVariable("ycWp1", "Waypoint latitude", "deg", 58.3812, &mpYcWp1);
    addOutputVariable("set1", "Waypoint reached flag", "", 1.0, &mpSet1);
    addOutputVariable("altitudeRef", "Altitude reference", "m", 0.0, &mpAltitudeRef);
    addOutputVariable("headingRef", "Heading reference", "rad", 0.0, &mpHeadingRef);
    addOutputVariable("velocityRef", "Speed reference", "m", 0.0, &mpVelocityRef);
    addOutputVariable("distanceWp", "Distance to waypoint", "m", 0.0, &mpDistanceWp);
}

void SignalWaypoint::initialize()
{
    simulateOneTimestep();
}

void SignalWaypoint::simulateOneTimestep()
{
    const double s1 = *mpS1, xc = *mpXc, yc = *mpYc, R = *mpR;
    const double xcWp1 = *mpXcWp1, ycWp1 = *mpYcWp1;
    const double d = 0.0174533
                     * Sqrt(Power(R, 2) * Power(yc - ycWp1, 2)
                            + Power(R, 2) * Power(xc - xcWp1, 2) * Power(Cos(0.0174533 * yc), 2));
    *mpSet1 = s1 * onPositive(*mpWptol - d);
    *mpAltitudeRef = *mpAlt1 * s1;
    *mpHeadingRef = s1 * Atan2L(R * (-xc + xcWp1) * Cos(0.0174533 * yc), R * (-yc + ycWp1));
    *mpVelocityRef = s1 * (*mpV1);
    *mpDistanceWp = d;
}

TLMHUB_REGISTER_COMPONENT(SignalWaypoint, "Signal")

} // namespace tlmhub
