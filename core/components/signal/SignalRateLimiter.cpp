#include "core/components/signal/SignalRateLimiter.h"

#include "core/ComponentFactory.h"
#include <cmath>

namespace tlmhub {

void SignalRateLimiter::configure()
{
    addInputVariable("c_up", "Maximum rising rate", "1/s", 1.0, &mpC_up);
    addInputVariable("c_down", "Maximum falling rate (negative)", "1/s", -1.0, &mpC_down);
    addInputVariable("in", "Input signal", "", 0.0, &mpIn);
    addOutputVariable("out", "Output signal", "", &mpOut);
}

void SignalRateLimiter::initialize()
{
    *mpOut = *mpIn;
}

void SignalRateLimiter::simulateOneTimestep()
{
    const double u = *mpIn;
    const double prev = *mpOut;
    const double diff = u - prev;
    const double c = (diff >= 0.0) ? *mpC_up : *mpC_down;
    if (std::fabs(diff) / mTimestep > std::fabs(c)) {
        *mpOut = prev + c * mTimestep;
    } else {
        *mpOut = u;
    }
}

TLMHUB_REGISTER_COMPONENT(SignalRateLimiter, "Signal")

} // namespace tlmhub
