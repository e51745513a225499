#include "server/studies/StudyStatistics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tlmhub::server {

bool SeriesBands::add(const std::vector<double>& samples)
{
    if (mCount == 0) {
        mMean.assign(samples.size(), 0.0);
        mM2.assign(samples.size(), 0.0);
    } else if (samples.size() != mMean.size()) {
        return false;
    }
    ++mCount;
    const double n = static_cast<double>(mCount);
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const double delta = samples[i] - mMean[i];
        mMean[i] += delta / n;
        mM2[i] += delta * (samples[i] - mMean[i]);
    }
    return true;
}

std::vector<double> SeriesBands::mean() const
{
    return mMean;
}

std::vector<double> SeriesBands::standardDeviation() const
{
    std::vector<double> sd(mM2.size(), 0.0);
    if (mCount < 2) return sd;
    const double degreesOfFreedom = static_cast<double>(mCount - 1);
    for (std::size_t i = 0; i < sd.size(); ++i) sd[i] = std::sqrt(mM2[i] / degreesOfFreedom);
    return sd;
}

double pearsonCorrelation(const std::vector<double>& x, const std::vector<double>& y)
{
    constexpr double notANumber = std::numeric_limits<double>::quiet_NaN();
    if (x.size() != y.size()) return notANumber;

    std::vector<std::size_t> finitePairs;
    for (std::size_t i = 0; i < x.size(); ++i)
        if (std::isfinite(x[i]) && std::isfinite(y[i])) finitePairs.push_back(i);
    if (finitePairs.size() < 2) return notANumber;

    // Two passes (means first, then the centred sums): no cancellation of large sums.
    double meanX = 0.0, meanY = 0.0;
    for (std::size_t i : finitePairs) {
        meanX += x[i];
        meanY += y[i];
    }
    meanX /= static_cast<double>(finitePairs.size());
    meanY /= static_cast<double>(finitePairs.size());

    double sxx = 0.0, syy = 0.0, sxy = 0.0;
    for (std::size_t i : finitePairs) {
        const double dx = x[i] - meanX, dy = y[i] - meanY;
        sxx += dx * dx;
        syy += dy * dy;
        sxy += dx * dy;
    }
    if (sxx == 0.0 || syy == 0.0) return notANumber;
    // Rounding can put |r| a hair above 1.
    return std::clamp(sxy / std::sqrt(sxx * syy), -1.0, 1.0);
}

} // namespace tlmhub::server
