// A component library loaded at run time (tlmhub-server --component-lib): one signal
// component, out = in * in. It is built as a shared object against the core's headers only;
// the core's symbols come from the server binary that loads it.
#include "core/Component.h"
#include "core/ComponentFactory.h"

namespace tlmhub {

class ExampleSquare : public ComponentSignal {
public:
    void configure() override
    {
        addInputVariable("in", "Input", "", 0.0, &mpIn);
        addOutputVariable("out", "Square of the input", "", &mpOut);
    }
    void initialize() override { simulateOneTimestep(); }
    void simulateOneTimestep() override { *mpOut = *mpIn * *mpIn; }

private:
    double* mpIn = nullptr;
    double* mpOut = nullptr;
};

TLMHUB_REGISTER_COMPONENT(ExampleSquare, "Signal")

} // namespace tlmhub
