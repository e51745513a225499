#pragma once
// The Nelder-Mead simplex method within bounds (docs/optimisation.md): every new point is
// clamped into the bounds. Batches are the initial simplex, then one point per reflection,
// expansion or contraction, and the n moved vertices of a shrink.
#include "server/studies/Optimiser.h"

namespace tlmhub::server {

class NelderMead final : public Optimiser {
public:
    static constexpr double kDefaultAlpha = 1.0;   // reflection
    static constexpr double kDefaultGamma = 2.0;   // expansion
    static constexpr double kDefaultRho = 0.5;     // contraction
    static constexpr double kDefaultSigma = 0.5;   // shrink
    // The initial simplex: the start plus this share of each parameter's range along its axis.
    static constexpr double kInitialStep = 0.1;

    explicit NelderMead(const OptimiserSettings& settings);

    std::vector<Point> ask() override;
    void tell(const std::vector<double>& values) override;
    bool finished() const override { return !mFinishReason.empty(); }
    std::string finishReason() const override { return mFinishReason; }
    Point best() const override { return mRecord.best(); }
    double bestValue() const override { return mRecord.bestValue(); }
    std::size_t evaluations() const override { return mRecord.evaluations(); }

private:
    enum class Step { InitialSimplex, Reflection, Expansion, OutsideContraction, InsideContraction, Shrink };

    // Orders the vertices best first, stops or asks for the reflection of the worst.
    void startIteration();
    void afterReflection(double value);
    void replaceWorst(const Point& point, double value);
    void shrinkTowardsBest();
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

    std::vector<Point> mBatch;
    bool mBatchAsked = false;
    EvaluationRecord mRecord;
    std::string mFinishReason;
};

} // namespace tlmhub::server
