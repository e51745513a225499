#pragma once
// Complex-RF: Box's complex method with a randomisation factor and a forgetting factor, as
// Hopsan's Ops library implements it (docs/optimisation.md). The first batch is the whole
// initial complex; after it every batch is one point, since each step depends on the last.
#include "server/studies/Optimiser.h"

#include <random>

namespace tlmhub::server {

class ComplexRF final : public Optimiser {
public:
    static constexpr double kDefaultAlpha = 1.3;
    static constexpr double kDefaultRandomisation = 0.3;
    static constexpr double kDefaultForgetting = 0.0;

    explicit ComplexRF(const OptimiserSettings& settings);

    std::vector<Point> ask() override;
    void tell(const std::vector<double>& values) override;
    bool finished() const override { return !mFinishReason.empty(); }
    std::string finishReason() const override { return mFinishReason; }
    Point best() const override { return mRecord.best(); }
    double bestValue() const override { return mRecord.bestValue(); }
    std::size_t evaluations() const override { return mRecord.evaluations(); }

private:
    enum class Step { InitialComplex, Reflection, Retraction };

    // After a tell: stop, or choose the next candidate.
    void prepareNextStep();
    // Raises every value by the same share of their spread, so a value grows older (worse)
    // with every iteration it survives and a lucky old point does not stay best for ever.
    void forgetOldValues();
    Point reflectWorst();
    Point retractTowardsCentroidAndBest();
    // Uniform in ±(randomisation × range of parameter j × scale) / 2, where scale is the
    // complex's relative spread: noise that keeps the complex from collapsing onto a line.
    double randomTerm(std::size_t j, double scale);
    std::size_t worstIndex() const;
    std::size_t bestIndex() const;
    bool isWorst(std::size_t index) const;

    std::vector<ParameterBounds> mParameters;
    std::size_t mMaxEvaluations;
    double mTolerance;
    double mAlpha, mRandomisation;
    double mAgingShare;   // Hopsan's kf = 1 - (alpha / 2)^(forgetting / points)
    std::mt19937_64 mRandom;

    std::vector<Point> mPoints;
    std::vector<double> mValues;   // aged by forgetOldValues; +infinity for a failed run
    Step mStep = Step::InitialComplex;
    std::size_t mReplaced = 0;     // the point the candidate replaces
    std::size_t mRetractions = 0;  // since the last reflection
    Point mCentroid;               // of the complex without the replaced point

    std::vector<Point> mBatch;
    bool mBatchAsked = false;
    EvaluationRecord mRecord;
    std::string mFinishReason;
};

} // namespace tlmhub::server
