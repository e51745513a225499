#pragma once
// Particle swarm optimisation within bounds (docs/optimisation.md): each batch is the whole
// swarm at its current positions; the swarm moves once the batch is told.
#include "server/studies/Optimiser.h"

#include <random>

namespace tlmhub::server {

class ParticleSwarm final : public Optimiser {
public:
    static constexpr double kDefaultParticles = 20;
    static constexpr double kDefaultOmega = 0.7;   // inertia
    static constexpr double kDefaultC1 = 1.5;      // pull towards the particle's own best
    static constexpr double kDefaultC2 = 1.5;      // pull towards the swarm's best
    // A velocity component is at most this share of its parameter's range per step.
    static constexpr double kMaxSpeed = 0.2;

    explicit ParticleSwarm(const OptimiserSettings& settings);

    std::vector<Point> ask() override;
    void tell(const std::vector<double>& values) override;
    bool finished() const override { return !mFinishReason.empty(); }
    std::string finishReason() const override { return mFinishReason; }
    Point best() const override { return mRecord.best(); }
    double bestValue() const override { return mRecord.bestValue(); }
    std::size_t evaluations() const override { return mRecord.evaluations(); }

private:
    void moveParticles();
    std::size_t swarmBest() const;

    std::vector<ParameterBounds> mParameters;
    std::size_t mMaxEvaluations;
    double mTolerance;
    double mOmega, mC1, mC2;
    std::mt19937_64 mRandom;

    std::vector<Point> mPositions, mVelocities;
    std::vector<double> mValues;   // at the current positions
    std::vector<Point> mPersonalBest;
    std::vector<double> mPersonalBestValue;

    std::vector<Point> mBatch;
    bool mBatchAsked = false;
    EvaluationRecord mRecord;
    std::string mFinishReason;
};

} // namespace tlmhub::server
