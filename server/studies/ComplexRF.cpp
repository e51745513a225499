#include "server/studies/ComplexRF.h"

#include "server/studies/ParameterSampling.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tlmhub::server {

namespace {

// Box's rule of thumb is twice as many points as parameters; fewer than three cannot
// reflect one point through the centroid of the others and still move off a line.
std::size_t defaultComplexSize(std::size_t parameters)
{
    return std::max<std::size_t>(2 * parameters, 3);
}

} // namespace

ComplexRF::ComplexRF(const OptimiserSettings& settings)
    : mParameters(settings.parameters),
      mMaxEvaluations(settings.maxEvaluations),
      mTolerance(settings.tolerance),
      mAlpha(optionOr(settings, "alpha", kDefaultAlpha)),
      mRandomisation(optionOr(settings, "randomisation", kDefaultRandomisation)),
      mRandom(splitMix64(settings.seed))
{
    const auto size = static_cast<std::size_t>(
        optionOr(settings, "points", static_cast<double>(defaultComplexSize(mParameters.size()))));
    const double forgetting = optionOr(settings, "forgetting", kDefaultForgetting);
    mAgingShare = 1.0 - std::pow(mAlpha / 2.0, forgetting / static_cast<double>(size));

    for (std::size_t i = 0; i < size; ++i) mPoints.push_back(randomPointInBounds(mRandom, mParameters, i == 0));
    mValues.assign(size, std::numeric_limits<double>::infinity());
    mBatch.assign(mPoints.begin(), mPoints.begin() + static_cast<std::ptrdiff_t>(std::min(size, mMaxEvaluations)));
}

std::vector<Point> ComplexRF::ask()
{
    if (finished() || mBatchAsked) return {};
    mBatchAsked = true;
    return mBatch;
}

void ComplexRF::tell(const std::vector<double>& values)
{
    if (!mBatchAsked) throw std::invalid_argument("Complex-RF was told values without an untold batch");
    const std::vector<double> told = mRecord.record(mBatch, values);
    mBatchAsked = false;

    if (mStep == Step::InitialComplex) {
        std::copy(told.begin(), told.end(), mValues.begin());
        mStep = Step::Reflection;
    } else {
        mPoints[mReplaced] = mBatch.front();
        mValues[mReplaced] = told.front();
        // A candidate that is still the worst point would be reflected straight back: move
        // it towards the centroid (and, the more often this happens, the best point) instead.
        mStep = isWorst(mReplaced) ? Step::Retraction : Step::Reflection;
    }
    prepareNextStep();
}

void ComplexRF::prepareNextStep()
{
    if (mRecord.evaluations() >= mMaxEvaluations) {
        mFinishReason = "evaluation budget used";
        return;
    }
    if (convergedWithin(mPoints, mValues, mParameters, mTolerance)) {
        mFinishReason = "converged";
        return;
    }
    if (mStep == Step::Reflection) {
        forgetOldValues();
        mReplaced = worstIndex();
        mRetractions = 0;
        mBatch = {reflectWorst()};
    } else {
        mBatch = {retractTowardsCentroidAndBest()};
        ++mRetractions;
    }
}

void ComplexRF::forgetOldValues()
{
    double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
    for (double v : mValues) {
        if (!std::isfinite(v)) continue;
        lowest = std::min(lowest, v);
        highest = std::max(highest, v);
    }
    if (!(lowest <= highest)) return;   // no finite values yet
    const double increase = (highest - lowest) * mAgingShare;
    for (double& v : mValues)
        if (std::isfinite(v)) v += increase;
}

Point ComplexRF::reflectWorst()
{
    const std::size_t n = mParameters.size();
    mCentroid.assign(n, 0.0);
    for (std::size_t i = 0; i < mPoints.size(); ++i) {
        if (i == mReplaced) continue;
        for (std::size_t j = 0; j < n; ++j) mCentroid[j] += mPoints[i][j];
    }
    for (double& c : mCentroid) c /= static_cast<double>(mPoints.size() - 1);

    const double spread = relativeParameterSpread(mPoints, mParameters);
    Point candidate(n);
    for (std::size_t j = 0; j < n; ++j)
        candidate[j] = mCentroid[j] + mAlpha * (mCentroid[j] - mPoints[mReplaced][j]) + randomTerm(j, spread);
    return clampIntoBounds(std::move(candidate), mParameters);
}

Point ComplexRF::retractTowardsCentroidAndBest()
{
    // Halfway from the last candidate to a target that starts at the centroid and moves
    // towards the best point as retractions repeat (weight 1 - e^(-k/5) after k of them); the
    // random term shrinks by 10 / (9 + k).
    const double k = static_cast<double>(mRetractions);
    const double towardsBest = 1.0 - std::exp(-k / 5.0);
    const double spread = relativeParameterSpread(mPoints, mParameters) * 10.0 / (9.0 + k);
    const Point& last = mPoints[mReplaced];
    const Point& best = mPoints[bestIndex()];
    Point candidate(mParameters.size());
    for (std::size_t j = 0; j < candidate.size(); ++j) {
        const double target = (1.0 - towardsBest) * mCentroid[j] + towardsBest * best[j];
        candidate[j] = (target + last[j]) / 2.0 + randomTerm(j, spread);
    }
    return clampIntoBounds(std::move(candidate), mParameters);
}

double ComplexRF::randomTerm(std::size_t j, double scale)
{
    const double range = mParameters[j].max - mParameters[j].min;
    return mRandomisation * range * scale * (uniformUnit(mRandom) - 0.5);
}

std::size_t ComplexRF::worstIndex() const
{
    return static_cast<std::size_t>(std::max_element(mValues.begin(), mValues.end()) - mValues.begin());
}

std::size_t ComplexRF::bestIndex() const
{
    return static_cast<std::size_t>(std::min_element(mValues.begin(), mValues.end()) - mValues.begin());
}

bool ComplexRF::isWorst(std::size_t index) const
{
    return std::all_of(mValues.begin(), mValues.end(), [&](double v) { return v <= mValues[index]; });
}

} // namespace tlmhub::server
