#include "server/studies/StudyPlan.h"

#include <cmath>
#include <limits>

namespace tlmhub::server {

StudyPlan::StudyPlan(const StudyRequest& request) : mRequest(request), mTotal(request.plannedRuns())
{
    if (request.kind == StudyKind::Optimise) {
        mOptimiser = makeOptimiser(request.optimiser);
        askNextBatch();
    }
}

void StudyPlan::askNextBatch()
{
    mBatch = mOptimiser->finished() ? std::vector<Point>{} : mOptimiser->ask();
    mBatchFirstIndex = mNextIndex;
    mBatchHandedOut = 0;
    mBatchCompleted = 0;
    mBatchValues.assign(mBatch.size(), std::numeric_limits<double>::infinity());
}

std::optional<PlannedRun> StudyPlan::next()
{
    PlannedRun run;
    switch (mRequest.kind) {
    case StudyKind::Sweep:
        if (static_cast<std::size_t>(mNextIndex) >= mTotal) return std::nullopt;
        run.values = sweepPoint(mRequest.axes, mRequest.mode, static_cast<std::size_t>(mNextIndex), mRequest.seed);
        break;
    case StudyKind::Sensitivity:
        if (static_cast<std::size_t>(mNextIndex) >= mTotal) return std::nullopt;
        run.values = monteCarloPoint(mRequest.distributions, static_cast<std::size_t>(mNextIndex), mRequest.seed);
        break;
    case StudyKind::Optimise:
        if (mBatchHandedOut >= mBatch.size()) return std::nullopt;
        run.values = mBatch[mBatchHandedOut++];
        break;
    }
    run.index = mNextIndex++;
    ++mOutstanding;
    return run;
}

bool StudyPlan::hasReady() const
{
    if (mOptimiser) return mBatchHandedOut < mBatch.size();
    return static_cast<std::size_t>(mNextIndex) < mTotal;
}

void StudyPlan::completed(std::int64_t index, double objective)
{
    --mOutstanding;
    if (!mOptimiser) return;
    const std::size_t position = static_cast<std::size_t>(index - mBatchFirstIndex);
    // The optimiser minimises; a run without a value is the worst.
    const double value = mRequest.objective->maximise ? -objective : objective;
    mBatchValues[position] = std::isnan(value) ? std::numeric_limits<double>::infinity() : value;
    if (++mBatchCompleted < mBatch.size()) return;
    mOptimiser->tell(mBatchValues);
    askNextBatch();
}

bool StudyPlan::finished() const
{
    if (mOutstanding > 0) return false;
    if (mOptimiser) return mBatchHandedOut >= mBatch.size();
    return static_cast<std::size_t>(mNextIndex) >= mTotal;
}

std::string StudyPlan::finishReason() const
{
    return mOptimiser && mOptimiser->finished() ? mOptimiser->finishReason() : std::string();
}

} // namespace tlmhub::server
