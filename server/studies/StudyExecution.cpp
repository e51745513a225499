#include "server/studies/StudyExecution.h"

#include "server/jobs/JobRunner.h"
#include "server/store/ResultBlob.h"
#include "server/NumberText.h"
#include "server/studies/RunMeasures.h"

#include "core/ResultView.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tlmhub::server {

namespace {

// JSON has no NaN or infinity: those become null.
nlohmann::json number(double value)
{
    return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json();
}

constexpr auto kEventPeriod = std::chrono::milliseconds(100);

// A summary as stored: text a model put in a run's error may not be UTF-8.
std::string dumped(const nlohmann::json& j)
{
    return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

// `text` cut to at most `bytes` (not inside a UTF-8 sequence), invalid UTF-8 replaced.
std::string boundedText(const std::string& text, std::size_t bytes)
{
    std::string cut = text;
    if (cut.size() > bytes) {
        std::size_t end = bytes;
        while (end > 0 && (static_cast<unsigned char>(cut[end]) & 0xC0) == 0x80) --end;
        cut.resize(end);
        cut += "...";
    }
    return nlohmann::json::parse(dumped(nlohmann::json(cut))).get<std::string>();
}

} // namespace

StudyExecution::StudyExecution(PreparedStudy prepared, const JobLimits& jobLimits, const StudyLimits& studyLimits,
                               unsigned workers, StudyStore& store, StudyProgressHub& hub)
    : mId(prepared.id), mOwnerId(prepared.ownerId), mNode(std::move(prepared.node)), mRequest(std::move(prepared.request)),
      mParameterNames(mRequest.parameterNames()), mModel(std::move(prepared.model)),
      mSettings(prepared.settings), mJobLimits(jobLimits), mStudyLimits(studyLimits), mStore(store), mHub(hub),
      mHubGeneration(hub.generation(mId)),
      mSimulations(workers), mSpare(std::move(prepared.compiled)), mStoredRuns(std::move(prepared.storedRuns)),
      mPlan(mRequest)
{
    if (mRequest.kind == StudyKind::Sensitivity) mBands.resize(mRequest.outputs.variables.size());
}

std::vector<std::string> StudyExecution::tableColumns(const StudyRequest& request)
{
    std::vector<std::string> columns{"run", "ok"};
    for (const std::string& name : request.parameterNames()) columns.push_back(name);
    for (const std::string& name : request.outputs.columnNames()) columns.push_back(name);
    if (request.objective) columns.push_back("objective");
    return columns;
}

std::optional<PlannedRun> StudyExecution::take()
{
    std::lock_guard lock(mMutex);
    if (mStopReason || !mFailure.empty()) return std::nullopt;
    if (!mStarted) {
        mStarted = true;
        if (!mStore.markRunning(mId, mNode)) {
            // No longer queued in the store (cancelled, deleted) or not held here any more
            // (another node took it over while this one stalled): finalise leaves it as it is.
            mStopReason = JobState::Cancelled;
            mNotHeld = true;
            return std::nullopt;
        }
    }
    while (std::optional<PlannedRun> run = mPlan.next()) {
        const auto stored = mStoredRuns.find(run->index);
        if (stored == mStoredRuns.end()) return run;
        replay(*run, stored->second);
        mStoredRuns.erase(stored);
        if (mStopReason || !mFailure.empty()) break;
    }
    return std::nullopt;
}

void StudyExecution::replay(const PlannedRun& run, const StudyRun& stored)
{
    RunOutcome outcome;
    outcome.ok = stored.ok;
    outcome.error = stored.error;
    const nlohmann::json outputs = nlohmann::json::parse(stored.outputs, nullptr, false);
    const auto value = [&](const std::string& name) {
        const bool known = outputs.is_object() && outputs.contains(name) && outputs[name].is_number();
        return known ? outputs[name].get<double>() : std::numeric_limits<double>::quiet_NaN();
    };
    if (stored.ok) {
        for (const std::string& column : mRequest.outputs.columnNames()) outcome.outputs.push_back(value(column));
        if (mRequest.objective) outcome.objective = value("objective");
    }
    if (stored.ok && stored.hasResult && mRequest.kind == StudyKind::Sensitivity) {
        // The bands need the run's curves: a study that kept them (outputs.full) has them.
        const auto blob = mStore.runResult(mId, stored.index);
        const auto table = blob ? decodeResult(*blob, mRequest.outputs.variables) : std::nullopt;
        std::vector<std::vector<double>> curves;
        for (const std::string& name : mRequest.outputs.variables)
            if (const ResultColumn* column = table ? table->column(name) : nullptr) curves.push_back(column->data);
        if (table && curves.size() == mRequest.outputs.variables.size()) addToBands(table->time, curves);
    }
    ++mRunsReused;
    record(run, outcome);
}

void StudyExecution::addToBands(const std::vector<double>& time, const std::vector<std::vector<double>>& curves)
{
    if (mBandTime.empty()) mBandTime = time;
    for (std::size_t v = 0; v < mBands.size(); ++v) mBands[v].add(curves[v]);
}

bool StudyExecution::hasWork()
{
    std::lock_guard lock(mMutex);
    if (mStopReason || !mFailure.empty()) return false;
    return !mStarted || mPlan.hasReady();
}

bool StudyExecution::started()
{
    std::lock_guard lock(mMutex);
    return mStarted;
}

bool StudyExecution::complete()
{
    std::lock_guard lock(mMutex);
    if (mPlan.inFlight() > 0) return false;
    return mStopReason || !mFailure.empty() || mPlan.finished();
}

void StudyExecution::stop(JobState reason)
{
    {
        std::lock_guard lock(mMutex);
        if (!mStopReason) mStopReason = reason;
    }
    mStop.request_stop();
}

Simulation* StudyExecution::simulationFor(unsigned worker, std::string& error)
{
    std::optional<Simulation>& slot = mSimulations.at(worker);
    if (!slot) {
        {
            std::lock_guard lock(mMutex);
            if (mSpare) {
                slot.emplace(std::move(*mSpare));
                mSpare.reset();
            }
        }
        if (!slot) {
            Result<Simulation> compiled = compile(*mModel, mSettings);
            if (!compiled) {
                error = compiled.status().message();
                return nullptr;
            }
            slot.emplace(std::move(*compiled));
        }
    }
    return &*slot;
}

StudyExecution::RunOutcome StudyExecution::simulate(unsigned worker, const PlannedRun& run)
{
    RunOutcome outcome;
    Simulation* simulation = simulationFor(worker, outcome.error);
    if (!simulation) return outcome;
    if (simulation->state() != SimulationState::Compiled) {
        if (const Status reset = simulation->reset(); !reset) {
            outcome.error = reset.message();
            return outcome;
        }
    }
    for (std::size_t i = 0; i < mParameterNames.size(); ++i) {
        if (const Status set = simulation->setParameter(mParameterNames[i], exactNumber(run.values[i])); !set) {
            outcome.error = mParameterNames[i] + ": " + set.message();
            return outcome;
        }
    }
    const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                             std::chrono::duration<double>(mJobLimits.maxWallSeconds));
    bool wallTimeExceeded = false;
    RunOptions options;
    options.threads = 1;
    options.stop = mStop.get_token();
    options.progressInterval = JobRunner::kProgressInterval;
    options.progress = [&](std::size_t, std::size_t) {
        if (!wallTimeExceeded && Clock::now() > deadline) {
            wallTimeExceeded = true;
            simulation->requestStop();
        }
    };
    const Status ran = simulation->run(options);
    // A model that ends its own run (SignalStopSimulation) ran as designed: its outputs count.
    if (!ran && ran.code() != StatusCode::SimulationEnded) {
        outcome.error = wallTimeExceeded ? wallTimeLimitMessage(mJobLimits.maxWallSeconds) : ran.message();
        return outcome;
    }
    const ResultView results = simulation->results();
    if (const std::size_t bytes = uncompressedResultBytes(results); bytes > mJobLimits.maxResultBytes) {
        outcome.error = "the result takes " + std::to_string(bytes >> 20) + " MiB; the limit is " +
                        std::to_string(mJobLimits.maxResultBytes >> 20) + " MiB";
        return outcome;
    }
    auto outputs = runOutputs(mRequest.outputs, results, outcome.error);
    if (!outputs) return outcome;
    outcome.outputs = std::move(*outputs);
    if (mRequest.objective) {
        outcome.objective = runObjective(*mRequest.objective, results, outcome.error);
        if (!outcome.objective) return outcome;
    }
    if (mRequest.kind == StudyKind::Sensitivity) {
        std::vector<std::vector<double>> curves;
        for (const std::string& name : mRequest.outputs.variables) curves.push_back(*results.data(name));
        const std::vector<double> time(results.time().begin(), results.time().end());
        std::lock_guard lock(mMutex);
        addToBands(time, curves);
    }
    if (mRequest.outputs.full) encodeResult(results, outcome.blob);
    outcome.ok = true;
    return outcome;
}

void StudyExecution::execute(unsigned worker, const PlannedRun& run)
{
    RunOutcome outcome = simulate(worker, run);
    const bool stopped = mStop.stop_requested();
    if (!stopped) {
        StudyRun row;
        row.index = run.index;
        row.ok = outcome.ok;
        row.error = outcome.error;
        nlohmann::json parameters = nlohmann::json::object(), outputs = nlohmann::json::object();
        for (std::size_t i = 0; i < mParameterNames.size(); ++i) parameters[mParameterNames[i]] = run.values[i];
        const std::vector<std::string> columns = mRequest.outputs.columnNames();
        for (std::size_t i = 0; i < outcome.outputs.size(); ++i) outputs[columns[i]] = number(outcome.outputs[i]);
        if (outcome.objective) outputs["objective"] = number(*outcome.objective);
        row.parameters = parameters.dump();
        row.outputs = outputs.dump();
        row.hasResult = outcome.ok && mRequest.outputs.full;
        row.node = mNode;
        bool tooLarge = false;
        {
            std::lock_guard lock(mMutex);
            tooLarge = mStoredBytes + outcome.blob.size() > mStudyLimits.maxStoredBytes;
            if (tooLarge && mFailure.empty())
                mFailure = "the study's results would take more than " +
                           std::to_string(mStudyLimits.maxStoredBytes >> 20) + " MiB";
            else
                mStoredBytes += outcome.blob.size();
        }
        if (!tooLarge) mStore.addRun(mId, row, row.hasResult ? &outcome.blob : nullptr);
    }
    std::lock_guard lock(mMutex);
    record(run, outcome);
}

void StudyExecution::record(const PlannedRun& run, const RunOutcome& outcome)
{
    const double objective = outcome.objective.value_or(std::numeric_limits<double>::quiet_NaN());
    mPlan.completed(run.index, outcome.ok ? objective : std::numeric_limits<double>::quiet_NaN());
    if (mStop.stop_requested()) return;
    (outcome.ok ? mRunsDone : mRunsFailed) += 1;
    if (!outcome.ok) countFailure(run.index, outcome.error);
    // max_failed_fraction: once enough runs have finished to judge, too many failures end it.
    const std::int64_t finished = mRunsDone + mRunsFailed;
    if (mFailure.empty() && mRunsFailed > 0 && finished >= StudyRequest::kMinRunsForFailedFraction &&
        static_cast<double>(mRunsFailed) > mRequest.maxFailedFraction * static_cast<double>(finished)) {
        mFailure = std::to_string(mRunsFailed) + " of " + std::to_string(finished) +
                   " finished runs failed, more than max_failed_fraction " + numberText(mRequest.maxFailedFraction) +
                   " allows; most often " + mostCommonFailure();
    }

    nlohmann::json row = nlohmann::json::array({run.index, outcome.ok ? 1 : 0});
    for (double v : run.values) row.push_back(v);
    for (double v : outcome.outputs) row.push_back(number(v));
    if (mRequest.objective) row.push_back(outcome.ok ? number(objective) : nlohmann::json());
    mPendingRows.push_back(std::move(row));

    if (outcome.ok && outcome.objective) {
        const bool better = !mBestRun || (mRequest.objective->maximise ? objective > mBestObjective
                                                                        : objective < mBestObjective);
        if (better && std::isfinite(objective)) {
            mBestRun = run.index;
            mBestObjective = objective;
            mBestValues = run.values;
            mStore.setSummary(mId, dumped(summary()));
            mFailuresChanged = false;
        }
    }
    if (outcome.ok && mRequest.kind == StudyKind::Sensitivity) {
        mSampledParameters.push_back(run.values);
        mSampledOutputs.push_back(outcome.outputs);
    }
    if (Clock::now() - mLastEvent >= kEventPeriod) {
        mLastEvent = Clock::now();
        if (mFailuresChanged) {
            mStore.setSummary(mId, dumped(summary()));
            mFailuresChanged = false;
        }
        mHub.publish(mId, mHubGeneration, progressEvent(false));
    }
}

nlohmann::json StudyExecution::bestRun() const
{
    nlohmann::json parameters = nlohmann::json::object();
    for (std::size_t i = 0; i < mParameterNames.size(); ++i) parameters[mParameterNames[i]] = mBestValues[i];
    return {{"run", *mBestRun}, {"parameters", parameters}, {"objective", number(mBestObjective)}};
}

void StudyExecution::countFailure(std::int64_t run, const std::string& error)
{
    const std::string message = boundedText(error.empty() ? "the run failed without a message" : error,
                                            kMaxFailureMessageBytes);
    mFailuresChanged = true;
    for (FailureReason& reason : mFailureReasons) {
        if (reason.message == message) {
            ++reason.count;
            reason.firstRun = std::min(reason.firstRun, run);
            return;
        }
    }
    if (mFailureReasons.size() < kMaxFailureReasons) {
        mFailureReasons.push_back({message, 1, run});
        return;
    }
    mOtherFailures.firstRun = mOtherFailures.count == 0 ? run : std::min(mOtherFailures.firstRun, run);
    ++mOtherFailures.count;
}

nlohmann::json StudyExecution::failureReasons() const
{
    std::vector<const FailureReason*> sorted;
    for (const FailureReason& reason : mFailureReasons) sorted.push_back(&reason);
    std::sort(sorted.begin(), sorted.end(), [](const FailureReason* a, const FailureReason* b) {
        return a->count != b->count ? a->count > b->count : a->firstRun < b->firstRun;
    });
    nlohmann::json list = nlohmann::json::array();
    for (const FailureReason* reason : sorted)
        list.push_back({{"message", reason->message}, {"count", reason->count}, {"first_run", reason->firstRun}});
    if (mOtherFailures.count > 0)
        list.push_back({{"message", "other reasons"}, {"count", mOtherFailures.count}, {"first_run", mOtherFailures.firstRun}});
    return list;
}

std::string StudyExecution::mostCommonFailure() const
{
    const FailureReason* most = nullptr;
    for (const FailureReason& reason : mFailureReasons) {
        if (!most || reason.count > most->count || (reason.count == most->count && reason.firstRun < most->firstRun))
            most = &reason;
    }
    if (!most) return {};
    return "\"" + most->message + "\" (" + std::to_string(most->count) + (most->count == 1 ? " run" : " runs") +
           ", the first run " + std::to_string(most->firstRun) + ")";
}

nlohmann::json StudyExecution::summary()
{
    nlohmann::json s = nlohmann::json::object();
    if (mBestRun) s["best"] = bestRun();
    if (const std::string reason = mPlan.finishReason(); !reason.empty()) s["finish_reason"] = reason;
    if (mRequest.kind == StudyKind::Sensitivity && !mSampledParameters.empty()) {
        // Pearson's r of each parameter with each output column.
        const std::vector<std::string> columns = mRequest.outputs.columnNames();
        nlohmann::json correlations = nlohmann::json::object();
        for (std::size_t p = 0; p < mParameterNames.size(); ++p) {
            std::vector<double> x;
            for (const auto& values : mSampledParameters) x.push_back(values[p]);
            nlohmann::json perOutput = nlohmann::json::object();
            for (std::size_t c = 0; c < columns.size(); ++c) {
                std::vector<double> y;
                for (const auto& outputs : mSampledOutputs) y.push_back(outputs[c]);
                perOutput[columns[c]] = number(pearsonCorrelation(x, y));
            }
            correlations[mParameterNames[p]] = perOutput;
        }
        s["correlations"] = correlations;
        // The runs they come from: the successful ones (a pair with a value that is not a
        // finite number is left out of its r).
        s["correlations_n"] = mSampledParameters.size();
    }
    if (mRunsFailed > 0) s["failure_reasons"] = failureReasons();
    if (mRunsReused > 0) s["runs_reused"] = mRunsReused;   // resumed: stored runs not run again
    return s;
}

nlohmann::json StudyExecution::progressEvent(bool last)
{
    nlohmann::json event = {{"type", "event.study.progress"},
                            {"study_id", mId},
                            {"state", last ? "" : "running"},
                            {"runs_done", mRunsDone},
                            {"runs_failed", mRunsFailed},
                            {"runs_total", mRequest.plannedRuns()},
                            {"columns", tableColumns(mRequest)},
                            {"rows", std::move(mPendingRows)}};
    mPendingRows.clear();
    if (mBestRun) event["best"] = bestRun();
    if (mRunsFailed > 0) event["failure_reasons"] = failureReasons();
    return event;
}

void StudyExecution::finalise()
{
    std::lock_guard lock(mMutex);
    if (mFinalised) return;
    mFinalised = true;
    JobState state = JobState::Done;
    std::string error;
    if (mStopReason) {
        state = *mStopReason;
    } else if (!mFailure.empty()) {
        state = JobState::Failed;
        error = mFailure;
    } else if (mRunsFailed > 0 && mRunsDone == 0) {
        state = JobState::Failed;
        error = mRunsFailed == 1 ? "the study's run failed: " + mostCommonFailure()
                                 : "all " + std::to_string(mRunsFailed) + " runs failed; most often " + mostCommonFailure();
    } else if (mRequest.kind == StudyKind::Optimise && !mBestRun && mRunsDone > 0) {
        state = JobState::Failed;
        error = "no run's objective was a finite number: the optimisation has no best point";
    }
    nlohmann::json s = summary();
    if (mRequest.kind == StudyKind::Sensitivity && !mBandTime.empty() && mBands.front().count() > 0) {
        nlohmann::json bands = nlohmann::json::object();
        bands["n"] = mBands.front().count();   // the runs they come from
        bands["time"] = mBandTime;
        nlohmann::json variables = nlohmann::json::object();
        for (std::size_t v = 0; v < mBands.size(); ++v) {
            variables[mRequest.outputs.variables[v]] = {{"mean", mBands[v].mean()},
                                                        {"sd", mBands[v].standardDeviation()}};
        }
        bands["variables"] = variables;
        s["bands"] = bands;
    }
    if (mNotHeld) {
        // What the store says it is now, for this node's subscribers.
        const auto stored = mStore.info(mId);
        if (stored) state = stored->state;
    } else {
        mStore.finish(mId, state, error, dumped(s));
    }
    nlohmann::json event = progressEvent(true);
    event["state"] = jobStateName(state);
    if (!error.empty()) event["error"] = error;
    mHub.finish(mId, mHubGeneration, event);
}

} // namespace tlmhub::server
