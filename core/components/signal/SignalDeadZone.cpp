#include "core/components/signal/SignalDeadZone.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalDeadZone::configure()
{
    addInputVariable("in", "Input signal", "", 0.0, &mpIn);
    addInputVariable("u_dstart", "Start of dead zone", "", -1.0, &mpU_dstart);
    addInputVariable("u_dend", "End of dead zone", "", 1.0, &mpU_dend);
    addOutputVariable("out", "Output signal", "", &mpOut);
}

void SignalDeadZone::initialize()
{
    simulateOneTimestep();
}

void SignalDeadZone::simulateOneTimestep()
{
    const double u = *mpIn;
    if (u < *mpU_dstart) {
        *mpOut = u - *mpU_dstart;
    } else if (u > *mpU_dstart && u < *mpU_dend) {
        *mpOut = 0.0;
    } else {
        *mpOut = u - *mpU_dend;
    }
}

TLMHUB_REGISTER_COMPONENT(SignalDeadZone, "Signal")

} // namespace tlmhub
