#include "core/components/signal/SignalDivide.h"

#include "core/ComponentFactory.h"

#include <string>

namespace tlmhub {

void SignalDivide::configure()
{
    addInputVariable("in1", "Numerator", "", 0.0, &mpIn1);
    addInputVariable("in2", "Denominator", "", 0.0, &mpIn2);
    addOutputVariable("out", "Quotient", "", &mpOut);
}

void SignalDivide::initialize()
{
    // Prepared here so the step function never builds strings.
    mStopMessage = "Division by zero";
    if (*mpIn2 == 0.0) {
        *mpOut = 0.0;
        addWarningMessage("Division by zero at initialization, output set to 0");
    } else {
        *mpOut = *mpIn1 / *mpIn2;
    }
}

void SignalDivide::simulateOneTimestep()
{
    const double den = *mpIn2;
    if (den == 0.0) {
        // The stop takes effect after this step; the IEEE quotient (inf/NaN) is still written.
        stopSimulation(mStopMessage);
    }
    *mpOut = *mpIn1 / den;
}

TLMHUB_REGISTER_COMPONENT(SignalDivide, "Signal")

} // namespace tlmhub
