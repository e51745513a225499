#include "core/components/signal/SignalConstant.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalConstant::configure()
{
    addOutputVariable("y", "Constant output", "", 1.0, &mpY);
    // The node holds the constant and its readers read it every step.
    setLiveChangeable({"y"}, true);
}

TLMHUB_REGISTER_COMPONENT(SignalConstant, "Signal")

} // namespace tlmhub
