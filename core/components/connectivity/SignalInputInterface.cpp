#include "core/components/connectivity/SignalInputInterface.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalInputInterface::configure()
{
    addOutputVariable("out", "Value from outside the model", "", &mpOut);
}

TLMHUB_REGISTER_COMPONENT(SignalInputInterface, "Connectivity")

} // namespace tlmhub
