// AeroWind (issue 21): mean wind over the boundary layer and the steady response of its
// Dryden turbulence filters to constant noise inputs.
#include "TestHelpers.h"

#include "core/Results.h"

#include <cmath>

using namespace tlmhub;
using namespace tlmhub::test;

namespace lcaero {

std::vector<double> loggedOutput(System& s, const std::string& comp, const std::string& port)
{
    Port* p = s.component(comp)->port(port);
    return loggedData(*p, NodeSignal::Value, s.numLoggedSamples());
}

} // namespace lcaero

using namespace lcaero;

TEST(LibraryCompletionAeroWind, MeanWindFollowsTheFilteredAltitude)
{
    // No noise: hf -> h through a first-order low-pass (wh = 10 rad/s), the mean wind is
    // Uw = (hf / h0)^alpha U0 along the heading. hf(t) = h (1 - exp(-wh t)) within 1e-4
    // relative (bilinear discretisation, h = 1 ms); the steady values within 1e-9.
    System s;
    add(s, "AeroWind", "Wind");
    setParam(s, "Wind", "wh#Value", "10");
    setParam(s, "Wind", "heading#Value", "0.5");
    setParam(s, "Wind", "alpha#Value", "0.5");
    ASSERT_TRUE(run(s, 0, 5, 1e-3, 501));
    const auto hf = loggedOutput(s, "Wind", "hf");
    const auto uw = loggedOutput(s, "Wind", "uw");
    const auto vw = loggedOutput(s, "Wind", "vw");
    const auto& t = s.logTime();
    for (std::size_t k = 1; k < t.size(); ++k) {
        EXPECT_NEAR(hf[k], 100.0 * (1.0 - std::exp(-10.0 * t[k])), 1e-2) << "t=" << t[k];
        EXPECT_DOUBLE_EQ(loggedOutput(s, "Wind", "du")[k], 0.0);
        EXPECT_DOUBLE_EQ(loggedOutput(s, "Wind", "ww")[k], 0.0);
    }
    const double Uw = std::sqrt(100.0 / 6.0) * 10.0;
    EXPECT_NEAR(hf.back(), 100.0, 1e-9);
    EXPECT_NEAR(uw.back(), Uw * std::cos(0.5), 1e-9);
    EXPECT_NEAR(vw.back(), Uw * std::sin(0.5), 1e-9);
}

TEST(LibraryCompletionAeroWind, ConstantNoiseGivesTheDrydenDcGain)
{
    // Constant noise n on all three channels: each filter settles at sqrt(2/pi) n sigma
    // sqrt(L / Ve), with sigma_w = aw Uw, sigma_u = sigma_v = sigma_w / (0.177 + 0.0002469 h)^0.4,
    // L_u = L_v = 0.3 h / (0.177 + 0.0002469 h)^1.2, L_w = h, Ve = |Uw + V|. 1e-6 relative.
    System s;
    add(s, "AeroWind", "Wind");
    setParam(s, "Wind", "wh#Value", "10");
    setParam(s, "Wind", "hf#Value", "100");   // start at the altitude: the scales are steady
    setParam(s, "Wind", "noiseu#Value", "1");
    setParam(s, "Wind", "noisev#Value", "-2");
    setParam(s, "Wind", "noisew#Value", "0.5");
    ASSERT_TRUE(run(s, 0, 40, 1e-3, 201));   // the slowest filter (dv) has a double time constant 2 L / Ve = 1.5 s
    const double Uw = 100.0 / 6.0 * 10.0, Ve = Uw + 100.0;
    const double sw = 0.2 * Uw;
    const double su = sw / std::pow(0.177 + 0.0002469 * 100.0, 0.4);
    const double Lu = 0.3 * 100.0 / std::pow(0.177 + 0.0002469 * 100.0, 1.2);
    const double k = std::sqrt(2.0 / 3.14159265358979323846);
    const double du = k * 1.0 * su * std::sqrt(Lu / Ve);
    const double dv = k * -2.0 * su * std::sqrt(Lu / Ve);
    const double ww = k * 0.5 * sw * std::sqrt(100.0 / Ve);
    EXPECT_NEAR(loggedOutput(s, "Wind", "du").back(), du, 1e-6 * std::fabs(du));
    EXPECT_NEAR(loggedOutput(s, "Wind", "dv").back(), dv, 1e-6 * std::fabs(dv));
    EXPECT_NEAR(loggedOutput(s, "Wind", "ww").back(), ww, 1e-6 * std::fabs(ww));
    EXPECT_NEAR(loggedOutput(s, "Wind", "uw").back(), du + Uw, 1e-6 * Uw);
    for (double v : loggedOutput(s, "Wind", "vw")) EXPECT_TRUE(std::isfinite(v));
}

TEST(LibraryCompletionAeroWind, RunsOnWhiteNoiseInAModel)
{
    System s;
    add(s, "SignalNoiseGenerator", "Noise");
    add(s, "AeroWind", "Wind");
    connectOk(s, "Noise", "out", "Wind", "noisew");
    ASSERT_TRUE(run(s, 0, 10, 1e-3, 1001));
    for (double v : loggedOutput(s, "Wind", "ww")) EXPECT_TRUE(std::isfinite(v));
}
