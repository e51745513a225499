#include "core/components/signal/SignalConstant.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalConstant::configure()
{
    addOutputVariable("y", "Constant output", "", 1.0, &mpY);
}

TLMHUB_REGISTER_COMPONENT(SignalConstant, "Signal")

} // namespace tlmhub
