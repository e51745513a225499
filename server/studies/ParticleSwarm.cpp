#include "server/studies/ParticleSwarm.h"

#include "server/studies/ParameterSampling.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace tlmhub::server {

ParticleSwarm::ParticleSwarm(const OptimiserSettings& settings)
    : mParameters(settings.parameters),
      mMaxEvaluations(settings.maxEvaluations),
      mTolerance(settings.tolerance),
      mOmega(optionOr(settings, "omega", kDefaultOmega)),
      mC1(optionOr(settings, "c1", kDefaultC1)),
      mC2(optionOr(settings, "c2", kDefaultC2)),
      mRandom(splitMix64(settings.seed))
{
    const auto particles = static_cast<std::size_t>(optionOr(settings, "particles", kDefaultParticles));
    for (std::size_t i = 0; i < particles; ++i) {
        mPositions.push_back(randomPointInBounds(mRandom, mParameters, i == 0));
        Point velocity(mParameters.size());
        for (std::size_t j = 0; j < velocity.size(); ++j) {
            const double maxSpeed = kMaxSpeed * (mParameters[j].max - mParameters[j].min);
            velocity[j] = maxSpeed * (2.0 * uniformUnit(mRandom) - 1.0);
        }
        mVelocities.push_back(std::move(velocity));
    }
    mValues.assign(particles, std::numeric_limits<double>::infinity());
    mPersonalBest = mPositions;
    mPersonalBestValue = mValues;
    mBatch.assign(mPositions.begin(),
                  mPositions.begin() + static_cast<std::ptrdiff_t>(std::min(particles, mMaxEvaluations)));
}

std::vector<Point> ParticleSwarm::ask()
{
    if (finished() || mBatchAsked) return {};
    mBatchAsked = true;
    return mBatch;
}

void ParticleSwarm::tell(const std::vector<double>& values)
{
    if (!mBatchAsked) throw std::invalid_argument("the particle swarm was told values without an untold batch");
    const std::vector<double> told = mRecord.record(mBatch, values);
    mBatchAsked = false;
    for (std::size_t i = 0; i < told.size(); ++i) {
        mValues[i] = told[i];
        if (told[i] < mPersonalBestValue[i]) {
            mPersonalBest[i] = mPositions[i];
            mPersonalBestValue[i] = told[i];
        }
    }

    if (mRecord.evaluations() >= mMaxEvaluations) {
        mFinishReason = "evaluation budget used";
        return;
    }
    if (convergedWithin(mPositions, mValues, mParameters, mTolerance)) {
        mFinishReason = "converged";
        return;
    }
    moveParticles();
    const std::size_t remaining = mMaxEvaluations - mRecord.evaluations();
    mBatch.assign(mPositions.begin(),
                  mPositions.begin() + static_cast<std::ptrdiff_t>(std::min(mPositions.size(), remaining)));
}

void ParticleSwarm::moveParticles()
{
    const Point swarmBestPoint = mPersonalBest[swarmBest()];
    for (std::size_t i = 0; i < mPositions.size(); ++i) {
        Point& x = mPositions[i];
        Point& v = mVelocities[i];
        for (std::size_t j = 0; j < x.size(); ++j) {
            const auto& p = mParameters[j];
            const double r1 = uniformUnit(mRandom), r2 = uniformUnit(mRandom);
            const double maxSpeed = kMaxSpeed * (p.max - p.min);
            v[j] = mOmega * v[j] + mC1 * r1 * (mPersonalBest[i][j] - x[j]) + mC2 * r2 * (swarmBestPoint[j] - x[j]);
            v[j] = std::clamp(v[j], -maxSpeed, maxSpeed);
            x[j] += v[j];
            // A particle that reaches a bound stops there in that direction.
            if (x[j] < p.min || x[j] > p.max) {
                x[j] = std::clamp(x[j], p.min, p.max);
                v[j] = 0.0;
            }
        }
    }
}

std::size_t ParticleSwarm::swarmBest() const
{
    return static_cast<std::size_t>(std::min_element(mPersonalBestValue.begin(), mPersonalBestValue.end()) -
                                    mPersonalBestValue.begin());
}

} // namespace tlmhub::server
