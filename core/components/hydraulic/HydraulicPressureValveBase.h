#pragma once
#include "core/Component.h"
#include "core/numerics/FirstOrderTransferFunction.h"
#include "core/numerics/TurbulentFlowFunction.h"
#include "core/numerics/ValveHysteresis.h"

namespace tlmhub {

// Shared body of Hopsan's simple pressure-controlled valves P1 -> P2 (reducing
// and drop valve): a static spool equilibrium with hysteresis, a first-order
// spool lag whose break frequency follows the line impedances, and a turbulent
// orifice whose coefficient is the equivalent spool position. The subclasses
// differ only in which pressure the spool compares with p_ref.
class HydraulicPressureValveBase : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

protected:
    // Spool force balance numerator (without the b2 term): what pushes the
    // spool open, in Pa, from the wave variables and the reference.
    virtual double openingPressure(double gamma, double c1, double c2, double pref) const = 0;

private:
    Port *mpP1 = nullptr, *mpP2 = nullptr;
    double *mpPref = nullptr, *mpPh = nullptr, *mpXv = nullptr;
    double mTao = 0.01, mKcs = 1e-8, mKcf = 1e-8, mQnom = 0.001;

    double *mpP1_p = nullptr, *mpP1_q = nullptr, *mpP1_c = nullptr, *mpP1_Zc = nullptr;
    double *mpP2_p = nullptr, *mpP2_q = nullptr, *mpP2_c = nullptr, *mpP2_Zc = nullptr;

    static constexpr double kPnom = 7e6; // nominal pressure drop of q_nom
    double mCs = 0.0, mCf = 0.0, mPrevX0 = 0.0;
    FirstOrderTransferFunction mFilter;
    TurbulentFlowFunction mTurb;
    ValveHysteresis mHyst;
};

} // namespace tlmhub
