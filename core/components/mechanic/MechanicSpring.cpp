#include "core/components/mechanic/MechanicSpring.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void MechanicSpring::configure()
{
    mpPm1 = addPowerPort("Pm1", NodeType::Mechanic);
    mpPm2 = addPowerPort("Pm2", NodeType::Mechanic);
    addInputVariable("Ks", "Spring constant", "N/m", 100.0, &mpKs);
    addInputVariable("x0", "Free length", "m", 0.0, &mpX0);
    addInputVariable("eps", "Drift removal coefficient", "", 0.005, &mpEps);
    addInputVariable("alpha", "Numerical damping", "", 0.05, &mpAlpha);
}

void MechanicSpring::initialize()
{
    mpF1 = getSafeNodeDataPtr(mpPm1, NodeMechanic::Force);
    mpX1 = getSafeNodeDataPtr(mpPm1, NodeMechanic::Position);
    mpV1 = getSafeNodeDataPtr(mpPm1, NodeMechanic::Velocity);
    mpC1 = getSafeNodeDataPtr(mpPm1, NodeMechanic::WaveVariable);
    mpZc1 = getSafeNodeDataPtr(mpPm1, NodeMechanic::CharImpedance);
    mpF2 = getSafeNodeDataPtr(mpPm2, NodeMechanic::Force);
    mpX2 = getSafeNodeDataPtr(mpPm2, NodeMechanic::Position);
    mpV2 = getSafeNodeDataPtr(mpPm2, NodeMechanic::Velocity);
    mpC2 = getSafeNodeDataPtr(mpPm2, NodeMechanic::WaveVariable);
    mpZc2 = getSafeNodeDataPtr(mpPm2, NodeMechanic::CharImpedance);

    const double Ks = *mpKs, x0 = *mpX0, alpha = *mpAlpha;
    const double xm1 = *mpX1, xm2 = *mpX2, vm1 = *mpV1, vm2 = *mpV2;
    // Operation order as in the generated original: (1/(1 - alpha))*Ks*dt, (-x0 + x1 + x2).
    const double Zexpr = (1.0 / (1.0 - alpha)) * Ks * mTimestep;
    mCm1 = Ks * (-x0 + xm1 + xm2) - vm1 * Zexpr;
    mCm2 = Ks * (-x0 + xm1 + xm2) - vm2 * Zexpr;
    mCm1f = *mpF1;
    mCm2f = *mpF2;

    simulateOneTimestep();
}

void MechanicSpring::simulateOneTimestep()
{
    const double fm1 = *mpF1, xm1 = *mpX1, vm1 = *mpV1;
    const double fm2 = *mpF2, xm2 = *mpX2, vm2 = *mpV2;
    const double Ks = *mpKs, x0 = *mpX0, eps = *mpEps, alpha = *mpAlpha;

    const double Zexpr = (1.0 / (1.0 - alpha)) * Ks * mTimestep;
    const double c10 = mCm2 + 2.0 * vm2 * Zexpr;
    const double c20 = mCm1 + 2.0 * vm1 * Zexpr;
    const double drift = eps * ((fm1 + fm2) / 2.0 - Ks * (-x0 + xm1 + xm2));
    mCm1f = (1.0 - alpha) * c10 + alpha * mCm1f - drift;
    mCm2f = (1.0 - alpha) * c20 + alpha * mCm2f - drift;
    mCm1 = mCm1f;
    mCm2 = mCm2f;

    *mpC1 = mCm1;
    *mpZc1 = Zexpr;
    *mpC2 = mCm2;
    *mpZc2 = Zexpr;
}

TLMHUB_REGISTER_COMPONENT(MechanicSpring, "Mechanic")

} // namespace tlmhub
