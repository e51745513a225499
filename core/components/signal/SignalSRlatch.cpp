#include "core/components/signal/SignalSRlatch.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void SignalSRlatch::configure()
{
    addInputVariable("setCond", "Set condition", "", 0.0, &mpSet);
    addInputVariable("resetCond", "Reset condition", "", 0.0, &mpReset);
    addOutputVariable("Qstate", "Latch state", "", 0.0, &mpQ);
    addOutputVariable("notQstate", "Inverted latch state", "", 1.0, &mpNotQ);
}

void SignalSRlatch::initialize()
{
    // The outputs already hold their start values; only the state is seeded.
    mQold = *mpQ;
}

void SignalSRlatch::simulateOneTimestep()
{
    const double s = *mpSet;
    const double r = *mpReset;
    const double Q = limit(limit(s * (1.0 - limit(r, 0.0, 1.0)), 0.0, 1.0)
                           - limit(r * (1.0 - limit(s, 0.0, 1.0)), 0.0, 1.0)
                           + limit(mQold * limit((1.0 - limit(r, 0.0, 1.0)) * (1.0 - limit(s, 0.0, 1.0)), 0.0, 1.0), 0.0, 1.0),
                       0.0, 1.0);
    mQold = Q;
    *mpQ = Q;
    *mpNotQ = 1.0 - Q;
}

TLMHUB_REGISTER_COMPONENT(SignalSRlatch, "Signal")

} // namespace tlmhub
