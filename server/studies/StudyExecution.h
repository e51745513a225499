#pragma once
// One study while it is queued or running: its plan, a compiled simulation per worker (the
// model is parsed once per study and compiled once per worker; between runs only parameters
// change: Simulation::setParameter + reset), the counters and what its events carry. The
// job queue schedules it (JobQueue.h): take() under the queue's lock hands out a run,
// execute() runs it on the worker, finalise() stores the end once complete().
#include "server/jobs/Job.h"
#include "server/store/StudyStore.h"
#include "server/studies/StudyPlan.h"
#include "server/studies/StudyProgressHub.h"
#include "server/studies/StudyRequest.h"
#include "server/studies/StudyStatistics.h"

#include "core/Model.h"
#include "core/Simulation.h"

#include <nlohmann/json.hpp>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <stop_token>
#include <string>
#include <vector>

namespace tlmhub::server {

struct StudyLimits {
    std::size_t maxRuns = 10'000;                        // per study
    int maxActivePerUser = 2;                            // queued or running studies
    std::size_t maxStoredBytes = std::size_t(512) << 20;  // run results one study keeps
};

// A study ready to run: the parsed request and the model with its fixed parameters applied.
struct PreparedStudy {
    std::int64_t id = 0, ownerId = 0;
    std::string node;                           // the node that holds it in the store (runs it)
    StudyRequest request;
    std::shared_ptr<const Model> model;
    SimulationSettings settings;                // resolved: start, stop, step, log samples
    std::optional<Simulation> compiled;         // the submit check's compile, for a first worker
    // Resumed: the runs stored before it stopped, by index. They are not run again; the plan
    // takes their stored outcome in their turn, so an optimiser walks the same trace.
    std::map<std::int64_t, StudyRun> storedRuns;
};

class StudyExecution {
public:
    StudyExecution(PreparedStudy prepared, const JobLimits& jobLimits, const StudyLimits& studyLimits,
                   unsigned workers, StudyStore& store, StudyProgressHub& hub);

    std::int64_t id() const { return mId; }
    std::int64_t ownerId() const { return mOwnerId; }

    // --- under the queue's lock ---
    // A run to execute now, or nullopt (none ready, or the study is ending). The first one
    // marks the study running in the store.
    std::optional<PlannedRun> take();
    bool hasWork();
    // Its first run has been taken (it is running in the store).
    bool started();
    // No run in flight, and none to come: finalise() may run.
    bool complete();
    // Ends the study as cancelled (or interrupted, at shutdown): runs in flight stop.
    void stop(JobState reason);

    // --- on a worker ---
    void execute(unsigned worker, const PlannedRun& run);
    // Stores the final state and summary, publishes the last event. Once, after complete().
    void finalise();

    // Columns of the results table: run, ok, the parameters, the outputs[, objective].
    static std::vector<std::string> tableColumns(const StudyRequest& request);

private:
    using Clock = std::chrono::steady_clock;
    struct RunOutcome {
        bool ok = false;
        std::string error;
        std::vector<double> outputs;
        std::optional<double> objective;
        std::string blob;
    };
    RunOutcome simulate(unsigned worker, const PlannedRun& run);
    // A run stored before a resume, counted as it was (caller holds mMutex).
    void replay(const PlannedRun& run, const StudyRun& stored);
    // A sensitivity run's variables added to the bands (caller holds mMutex).
    void addToBands(const std::vector<double>& time, const std::vector<std::vector<double>>& curves);
    Simulation* simulationFor(unsigned worker, std::string& error);
    // Records an ended run (caller holds mMutex); publishes an event when one is due.
    void record(const PlannedRun& run, const RunOutcome& outcome);
    nlohmann::json progressEvent(bool last);   // caller holds mMutex; takes the pending rows
    nlohmann::json summary();                   // caller holds mMutex
    nlohmann::json bestRun() const;             // {run, parameters, objective}; caller holds mMutex
    // Failed runs by reason (caller holds mMutex): counts a failed run's message.
    void countFailure(std::int64_t run, const std::string& error);
    // [{message, count, first_run}], most frequent first, "other reasons" last.
    nlohmann::json failureReasons() const;
    // "N runs: message (first run i)" of the most frequent reason; empty with none.
    std::string mostCommonFailure() const;

    const std::int64_t mId, mOwnerId;
    const std::string mNode;
    const StudyRequest mRequest;
    const std::vector<std::string> mParameterNames;
    const std::shared_ptr<const Model> mModel;
    const SimulationSettings mSettings;
    const JobLimits mJobLimits;
    const StudyLimits mStudyLimits;
    StudyStore& mStore;
    StudyProgressHub& mHub;
    const std::uint64_t mHubGeneration;   // this run of the study's (a resume starts another)
    std::stop_source mStop;   // cancel / shutdown: ends the runs in flight

    // One per worker, touched only by that worker.
    std::vector<std::optional<Simulation>> mSimulations;

    std::mutex mMutex;   // everything below
    std::optional<Simulation> mSpare;   // the submit check's compile
    std::map<std::int64_t, StudyRun> mStoredRuns;   // resumed: runs not to run again
    std::int64_t mRunsReused = 0;                  // of those, taken in their turn so far
    StudyPlan mPlan;
    bool mStarted = false;
    bool mNotHeld = false;   // the store refused to start it here
    std::optional<JobState> mStopReason;
    std::string mFailure;               // a reason the whole study fails
    std::int64_t mRunsDone = 0, mRunsFailed = 0;
    // Failed runs grouped by message: at most kMaxFailureReasons distinct ones, the rest
    // counted together, so that a study cannot grow the list without bound.
    struct FailureReason {
        std::string message;
        std::int64_t count = 0;
        std::int64_t firstRun = 0;   // the lowest run index that failed so
    };
    static constexpr std::size_t kMaxFailureReasons = 20;
    static constexpr std::size_t kMaxFailureMessageBytes = 500;
    std::vector<FailureReason> mFailureReasons;
    FailureReason mOtherFailures;        // message unused
    bool mFailuresChanged = false;       // since the summary was last stored
    std::size_t mStoredBytes = 0;
    std::vector<nlohmann::json> mPendingRows;
    Clock::time_point mLastEvent{};
    // Best run so far (optimise), as the user's objective.
    std::optional<std::int64_t> mBestRun;
    double mBestObjective = 0.0;
    std::vector<double> mBestValues;
    // Sensitivity: per output variable the bands, and every run's parameters and outputs.
    std::vector<SeriesBands> mBands;
    std::vector<double> mBandTime;
    std::vector<std::vector<double>> mSampledParameters, mSampledOutputs;
    bool mFinalised = false;
};

} // namespace tlmhub::server
