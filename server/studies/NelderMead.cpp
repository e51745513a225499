#include "server/studies/NelderMead.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace tlmhub::server {

NelderMead::NelderMead(const OptimiserSettings& settings)
    : mParameters(settings.parameters),
      mMaxEvaluations(settings.maxEvaluations),
      mTolerance(settings.tolerance),
      mAlpha(optionOr(settings, "alpha", kDefaultAlpha)),
      mGamma(optionOr(settings, "gamma", kDefaultGamma)),
      mRho(optionOr(settings, "rho", kDefaultRho)),
      mSigma(optionOr(settings, "sigma", kDefaultSigma)),
      mBestAtLastRestart(std::numeric_limits<double>::infinity()),
      mRandomRestartsLeft(static_cast<std::size_t>(optionOr(settings, "restarts", kDefaultRestarts))),
      mRandom(settings.seed)
{
    const std::size_t n = mParameters.size();
    Point first(n);
    for (std::size_t j = 0; j < n; ++j) {
        const auto& p = mParameters[j];
        first[j] = p.start ? *p.start : (p.min + p.max) / 2.0;
    }
    mVertices.push_back(first);
    for (std::size_t j = 0; j < n; ++j) mVertices.push_back(axisNeighbour(first, j));
    mBatch.assign(mVertices.begin(),
                  mVertices.begin() + static_cast<std::ptrdiff_t>(std::min(mVertices.size(), mMaxEvaluations)));
}

std::vector<Point> NelderMead::ask()
{
    if (finished() || mBatchAsked) return {};
    mBatchAsked = true;
    return mBatch;
}

void NelderMead::tell(const std::vector<double>& values)
{
    if (!mBatchAsked) throw std::invalid_argument("Nelder-Mead was told values without an untold batch");
    const std::vector<double> told = mRecord.record(mBatch, values);
    mBatchAsked = false;
    if (mRecord.evaluations() >= mMaxEvaluations) {
        mFinishReason = "evaluation budget used";
        return;
    }

    const double value = told.front();
    switch (mStep) {
    case Step::InitialSimplex:
        mValues = told;
        startIteration();
        return;
    case Step::Reflection:
        afterReflection(value);
        return;
    case Step::Expansion:
        if (value < mReflectedValue) replaceWorst(mBatch.front(), value);
        else replaceWorst(mReflected, mReflectedValue);
        startIteration();
        return;
    case Step::OutsideContraction:
    case Step::InsideContraction: {
        const bool accepted = mStep == Step::OutsideContraction ? value <= mReflectedValue : value < mValues.back();
        if (accepted) {
            replaceWorst(mBatch.front(), value);
            startIteration();
        } else {
            shrinkTowardsBest();
        }
        return;
    }
    case Step::Shrink:
    case Step::Restart:
        for (std::size_t i = 0; i < told.size(); ++i) {
            mVertices[i + 1] = mBatch[i];
            mValues[i + 1] = told[i];
        }
        startIteration();
        return;
    }
}

void NelderMead::startIteration()
{
    // Stable, so equal values (several failed runs) keep an order that depends on nothing else.
    std::vector<std::size_t> order(mVertices.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return mValues[a] < mValues[b]; });
    std::vector<Point> vertices;
    std::vector<double> values;
    for (std::size_t i : order) {
        vertices.push_back(std::move(mVertices[i]));
        values.push_back(mValues[i]);
    }
    mVertices = std::move(vertices);
    mValues = std::move(values);

    if (convergedWithin(mVertices, mValues, mParameters, mTolerance)) {
        const double best = mValues.front();
        const bool improved = !std::isfinite(mBestAtLastRestart) ||
                              mBestAtLastRestart - best > mTolerance * std::max(std::abs(best), 1e-300);
        if (improved && std::isfinite(best)) {
            restartAtBest();
        } else if (mRandomRestartsLeft > 0) {
            --mRandomRestartsLeft;
            restartAtRandom();
        } else {
            mFinishReason = "converged";
        }
        return;
    }

    const std::size_t n = mParameters.size();
    mCentroid.assign(n, 0.0);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) mCentroid[j] += mVertices[i][j] / static_cast<double>(n);
    mReflected = alongLine(mVertices.back(), -mAlpha);
    mBatch = {mReflected};
    mStep = Step::Reflection;
}

void NelderMead::afterReflection(double value)
{
    mReflectedValue = value;
    const std::size_t n = mParameters.size();
    if (value < mValues.front()) {
        mBatch = {alongLine(mReflected, mGamma)};
        mStep = Step::Expansion;
    } else if (value < mValues[n - 1]) {
        replaceWorst(mReflected, value);
        startIteration();
    } else if (value < mValues[n]) {
        mBatch = {alongLine(mReflected, mRho)};
        mStep = Step::OutsideContraction;
    } else {
        mBatch = {alongLine(mVertices.back(), mRho)};
        mStep = Step::InsideContraction;
    }
}

void NelderMead::replaceWorst(const Point& point, double value)
{
    mVertices.back() = point;
    mValues.back() = value;
}

void NelderMead::shrinkTowardsBest()
{
    const Point& best = mVertices.front();
    std::vector<Point> moved;
    for (std::size_t i = 1; i < mVertices.size(); ++i) {
        Point p(best.size());
        for (std::size_t j = 0; j < p.size(); ++j) p[j] = best[j] + mSigma * (mVertices[i][j] - best[j]);
        moved.push_back(std::move(p));
    }
    // Only as many as the budget still allows; the study ends with this batch then.
    moved.resize(std::min(moved.size(), mMaxEvaluations - mRecord.evaluations()));
    mBatch = std::move(moved);
    mStep = Step::Shrink;
}

Point NelderMead::axisNeighbour(const Point& from, std::size_t j) const
{
    // Along axis j, or against it when that would leave the bounds.
    const auto& p = mParameters[j];
    const double step = kInitialStep * (p.max - p.min);
    Point vertex = from;
    vertex[j] = from[j] + step <= p.max ? from[j] + step : from[j] - step;
    return vertex;
}

void NelderMead::restartAtBest()
{
    mBestAtLastRestart = mValues.front();
    std::vector<Point> fresh;
    for (std::size_t j = 0; j < mParameters.size(); ++j) fresh.push_back(axisNeighbour(mVertices.front(), j));
    fresh.resize(std::min(fresh.size(), mMaxEvaluations - mRecord.evaluations()));
    mBatch = std::move(fresh);
    mStep = Step::Restart;
}

void NelderMead::restartAtRandom()
{
    // The best point so far stays in the record; the search goes on from elsewhere.
    const Point start = randomPointInBounds(mRandom, mParameters, false);
    mBestAtLastRestart = std::numeric_limits<double>::infinity();
    std::vector<Point> fresh{start};
    for (std::size_t j = 0; j < mParameters.size(); ++j) fresh.push_back(axisNeighbour(start, j));
    mVertices = fresh;
    fresh.resize(std::min(fresh.size(), mMaxEvaluations - mRecord.evaluations()));
    mBatch = std::move(fresh);
    mStep = Step::InitialSimplex;
}

Point NelderMead::alongLine(const Point& towards, double factor) const
{
    Point p(mCentroid.size());
    for (std::size_t j = 0; j < p.size(); ++j) p[j] = mCentroid[j] + factor * (towards[j] - mCentroid[j]);
    return clampIntoBounds(std::move(p), mParameters);
}

} // namespace tlmhub::server
