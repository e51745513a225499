#pragma once
// Which runs a study makes, in what order: a sweep's sets and a sensitivity study's samples by
// index, an optimisation's points batch by batch as its optimiser asks for them. Runs are
// handed out one at a time to whichever worker is free and come back in any order; an
// optimiser's next batch is asked for once the last one is complete, so a fixed seed gives
// the same runs however they were scheduled. Not thread-safe (StudyExecution locks it).
#include "server/studies/Optimiser.h"
#include "server/studies/StudyRequest.h"

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace tlmhub::server {

struct PlannedRun {
    std::int64_t index = 0;
    std::vector<double> values;   // one per StudyRequest::parameterNames()
};

class StudyPlan {
public:
    explicit StudyPlan(const StudyRequest& request);

    // The next run to start; nullopt when none is ready (an optimiser waits for its batch) or
    // all have been handed out.
    std::optional<PlannedRun> next();
    // Whether next() would give a run.
    bool hasReady() const;
    // A handed-out run has ended; `objective` (an optimisation's value as the user defined
    // it; +infinity for a failed run) is what the optimiser learns.
    void completed(std::int64_t index, double objective);
    // Every run handed out and completed, and none to come.
    bool finished() const;
    std::size_t inFlight() const { return mOutstanding; }
    // Why an optimisation ended ("converged", ...); empty otherwise.
    std::string finishReason() const;
    const Optimiser* optimiser() const { return mOptimiser.get(); }

private:
    void askNextBatch();

    const StudyRequest& mRequest;
    std::size_t mTotal = 0;          // sweep and sensitivity: the runs
    std::int64_t mNextIndex = 0;
    std::size_t mOutstanding = 0;    // handed out, not completed
    // optimise
    std::unique_ptr<Optimiser> mOptimiser;
    std::vector<Point> mBatch;
    std::int64_t mBatchFirstIndex = 0;
    std::size_t mBatchHandedOut = 0;
    std::vector<double> mBatchValues;
    std::size_t mBatchCompleted = 0;
};

} // namespace tlmhub::server
