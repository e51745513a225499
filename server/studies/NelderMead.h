#pragma once
// The Nelder-Mead simplex method within bounds (docs/optimisation.md): every new point is
// clamped into the bounds. Batches are the initial simplex, then one point per reflection,
// expansion or contraction, and the n moved vertices of a shrink. A simplex pressed flat
// against a bound converges where the valley is not; so when it converges with evaluations
// left, it starts again from its best vertex with a fresh simplex, until that finds nothing
// better. Then, a local method in a landscape of several valleys, it starts again from a
// random point ("restarts" times, seeded), and ends with the best of all.
#include "server/studies/Optimiser.h"

#include <random>

namespace tlmhub::server {

class NelderMead final : public Optimiser {
public:
    static constexpr double kDefaultAlpha = 1.0;   // reflection
    static constexpr double kDefaultGamma = 2.0;   // expansion
    static constexpr double kDefaultRho = 0.5;     // contraction
    static constexpr double kDefaultSigma = 0.5;   // shrink
    // The initial simplex: the start plus this share of each parameter's range along its axis.
    static constexpr double kInitialStep = 0.1;
    static constexpr double kDefaultRestarts = 3;

    explicit NelderMead(const OptimiserSettings& settings);

    std::vector<Point> ask() override;
    void tell(const std::vector<double>& values) override;
    bool finished() const override { return !mFinishReason.empty(); }
    std::string finishReason() const override { return mFinishReason; }
    Point best() const override { return mRecord.best(); }
    double bestValue() const override { return mRecord.bestValue(); }
    std::size_t evaluations() const override { return mRecord.evaluations(); }

private:
    enum class Step { InitialSimplex, Reflection, Expansion, OutsideContraction, InsideContraction, Shrink, Restart };

    // Orders the vertices best first, stops or asks for the reflection of the worst.
    void startIteration();
    void afterReflection(double value);
    void replaceWorst(const Point& point, double value);
    void shrinkTowardsBest();
    // A new simplex around the best vertex: the vertices along each axis, as the first one.
    void restartAtBest();
    // A new simplex around a random point.
    void restartAtRandom();
    // The start's neighbour along axis j (into the bounds).
    Point axisNeighbour(const Point& from, std::size_t j) const;
    // centroid + factor × (towards - centroid), clamped into the bounds.
    Point alongLine(const Point& towards, double factor) const;

    std::vector<ParameterBounds> mParameters;
    std::size_t mMaxEvaluations;
    double mTolerance;
    double mAlpha, mGamma, mRho, mSigma;

    std::vector<Point> mVertices;   // best first after startIteration
    std::vector<double> mValues;
    Step mStep = Step::InitialSimplex;
    Point mCentroid;                // of all vertices but the worst
    Point mReflected;
    double mReflectedValue = 0.0;
    double mBestAtLastRestart;      // +infinity before the first
    std::size_t mRandomRestartsLeft;
    std::mt19937_64 mRandom;

    std::vector<Point> mBatch;
    bool mBatchAsked = false;
    EvaluationRecord mRecord;
    std::string mFinishReason;
};

} // namespace tlmhub::server
