#include "core/components/aero/AeroWind.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <cmath>

namespace tlmhub {

namespace {

constexpr double kSqrt2OverPi = 0.7978848977752073;       // sqrt(2/pi)
constexpr double kSqrt3Times4Sqrt2OverPi = 5.5279087261542355;   // 4 sqrt(3) sqrt(2/pi)

// Denominator of the bilinear second-order turbulence filter with scale length L.
double secondOrderDenominator(double L, double h, double Ve)
{
    return 16.0 * L * L + 8.0 * L * h * Ve + h * h * Ve * Ve;
}

} // namespace

void AeroWind::configure()
{
    addInputVariable("V", "Speed", "m/s", 100.0, &mpV);
    addInputVariable("h", "Altitude", "m", 100.0, &mpH);
    addInputVariable("noiseu", "Noise input (along wind)", "", 0.0, &mpNoiseU);
    addInputVariable("noisev", "Noise input (lateral)", "", 0.0, &mpNoiseV);
    addInputVariable("noisew", "Noise input (vertical)", "", 0.0, &mpNoiseW);
    addInputVariable("U0", "Wind speed at h0", "m/s", 10.0, &mpU0);
    addInputVariable("heading", "Wind heading", "rad", 0.0, &mpHeading);
    addInputVariable("h0", "Reference height", "m", 6.0, &mpH0);
    addInputVariable("alpha", "Exponent of the boundary layer profile", "", 1.0, &mpAlpha);
    addInputVariable("au", "Lateral turbulence factor (not used by the equations)", "", 0.2, &mpAu);
    addInputVariable("aw", "Vertical turbulence factor", "", 0.2, &mpAw);
    addInputVariable("wh", "Filter frequency of the altitude", "rad/s", 0.1, &mpWh);
    addOutputVariable("du", "Turbulent along-wind speed", "m/s", 0.0, &mpDu);
    addOutputVariable("dv", "Turbulent lateral speed", "m/s", 0.0, &mpDv);
    addOutputVariable("uw", "Wind speed, x", "m/s", 0.0, &mpUw);
    addOutputVariable("vw", "Wind speed, y", "m/s", 0.0, &mpVw);
    addOutputVariable("ww", "Wind speed, vertical (turbulent)", "m/s", 0.0, &mpWw);
    addOutputVariable("hf", "Filtered altitude", "m", 0.0, &mpHf);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"U0", "heading", "h0", "alpha", "au", "aw", "wh"}, false);
}

void AeroWind::updateLocalScales()
{
    mUw = std::pow(mHf / mH0, mAlpha) * mU0;
    mSw = mAw * mUw;
    mSu = mSw / std::pow(0.177 + 0.0002469 * mHf, 0.4);
    mSv = mSu;
    mLu = 0.3 * mHf / std::pow(0.177 + 0.0002469 * mHf, 1.2);
    mLv = mLu;
    mLw = limit(mHf, 0.0, 525.0);
    mVe = lowLimit(std::fabs(mUw + *mpV), 10.0);
}

void AeroWind::computeDelayedParts()
{
    const double h = mTimestep, Ve = mVe;
    const double hIn = lowLimit(*mpH, 0.0);
    mDelayHf = (-2.0 * mHf + mHf * h * mWh - h * mWh * hIn) / (2.0 + h * mWh);

    const double gu = *mpNoiseU * mSu * std::sqrt(mLu / Ve) * Ve;
    mDelayDu = (-2.0 * mDu * mLu + mDu * h * Ve - kSqrt2OverPi * h * gu) / (2.0 * mLu + h * Ve);

    const double gv = *mpNoiseV * mSv * std::sqrt(mLv / Ve) * Ve;
    const double Nv = secondOrderDenominator(mLv, h, Ve);
    mDelayDv1 = (-32.0 * mDv * mLv * mLv + 2.0 * mDv * h * h * Ve * Ve - 2.0 * kSqrt2OverPi * h * h * gv * Ve) / Nv;
    const double nextDv2 = (16.0 * mDv * mLv * mLv - 8.0 * mDv * mLv * h * Ve + kSqrt3Times4Sqrt2OverPi * mLv * h * gv
                            + mDv * h * h * Ve * Ve - kSqrt2OverPi * h * h * gv * Ve) / Nv;

    const double gw = *mpNoiseW * mSw * std::sqrt(mLw / Ve) * Ve;
    const double Nw = secondOrderDenominator(mLw, h, Ve);
    mDelayWw1 = (-2.0 * kSqrt2OverPi * h * h * gw * Ve - 32.0 * mLw * mLw * mWw + 2.0 * h * h * Ve * Ve * mWw) / Nw;
    const double nextWw2 = (kSqrt3Times4Sqrt2OverPi * mLw * h * gw - kSqrt2OverPi * h * h * gw * Ve
                            + 16.0 * mLw * mLw * mWw - 8.0 * mLw * h * Ve * mWw + h * h * Ve * Ve * mWw) / Nw;

    // The second parts reach the equations one step later than the first ones.
    mDelayDv2 = mPendingDv2;
    mPendingDv2 = nextDv2;
    mDelayWw2 = mPendingWw2;
    mPendingWw2 = nextWw2;
}

void AeroWind::initialize()
{
    // As in Hopsan's generated code, the wind parameters are read only here.
    mU0 = *mpU0;
    mHeading = *mpHeading;
    mH0 = *mpH0;
    mAlpha = *mpAlpha;
    mAw = *mpAw;
    mWh = *mpWh;
    mDu = *mpDu;
    mDv = *mpDv;
    mWw = *mpWw;
    mHf = *mpHf;
    updateLocalScales();
    // Before the first step both second parts are the ones computed from the start values.
    computeDelayedParts();
    mDelayDv2 = mPendingDv2;
    mDelayWw2 = mPendingWw2;
}

void AeroWind::simulateOneTimestep()
{
    const double h = mTimestep;
    updateLocalScales();
    const double Ve = mVe;

    // Bilinear (trapezoidal) discretisations of: a first-order low-pass of the altitude;
    // a first-order Dryden filter for du; second-order ones for dv and ww.
    mHf = h * mWh * lowLimit(*mpH, 0.0) / (2.0 + h * mWh) - mDelayHf;
    const double gu = *mpNoiseU * mSu * std::sqrt(mLu / Ve) * Ve;
    mDu = kSqrt2OverPi * h * gu / (2.0 * mLu + h * Ve) - mDelayDu;
    const double gv = *mpNoiseV * mSv * std::sqrt(mLv / Ve) * Ve;
    mDv = h * gv * (kSqrt3Times4Sqrt2OverPi * mLv + kSqrt2OverPi * h * Ve) / secondOrderDenominator(mLv, h, Ve)
          - mDelayDv1 - mDelayDv2;
    const double gw = *mpNoiseW * mSw * std::sqrt(mLw / Ve) * Ve;
    mWw = h * gw * (kSqrt3Times4Sqrt2OverPi * mLw + kSqrt2OverPi * h * Ve) / secondOrderDenominator(mLw, h, Ve)
          - mDelayWw1 - mDelayWw2;

    computeDelayedParts();

    *mpDu = mDu;
    *mpDv = mDv;
    *mpUw = mDu + mUw * std::cos(mHeading);
    *mpVw = mDv + mUw * std::sin(mHeading);
    *mpWw = mWw;
    *mpHf = mHf;
}

TLMHUB_REGISTER_COMPONENT(AeroWind, "Aero")

} // namespace tlmhub
