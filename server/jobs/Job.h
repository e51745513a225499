#pragma once
// A simulation job: what was asked (JobRequest), what the server knows about it (JobInfo) and
// the limits every job is held to (JobLimits).
#include "server/jobs/ModelLimits.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <map>
#include <optional>
#include <string>

namespace tlmhub::server {

// queued -> running -> done | failed | cancelled | interrupted | dead; queued -> cancelled;
// running -> queued when its node's lease expires (JobLeaseStore.h).
// interrupted: the server stopped (shutdown) while the job was running.
// dead: its node stopped answering (lease expired) as often as a job may be claimed.
enum class JobState { Queued, Running, Done, Failed, Cancelled, Interrupted, Dead };

const char* jobStateName(JobState state);
// False for a name that is not a state.
bool jobStateFromName(const std::string& name, JobState& out);
// Done, failed, cancelled and interrupted jobs never change again.
bool isFinished(JobState state);
// A job done with a message was ended by its model (a SignalStopSimulation component): the
// message is its stop reason (`stop_reason`), not an error.
bool endedByModel(JobState state, const std::string& message);

// Settings that override the model's own; unset ones come from the model.
struct JobSettings {
    std::optional<double> start, step, stop;   // s
    std::optional<std::size_t> logSamples;
};

struct JobRequest {
    std::int64_t ownerId = 0;
    std::optional<std::int64_t> modelId;   // recorded only; `hmf` is what runs
    std::string hmf;                       // the model file text
    // "Comp.Param", "Sub$Comp.Param" or a bare system parameter name -> value string.
    std::map<std::string, std::string> parameters;
    JobSettings settings;
    // Directory relative paths in the model resolve against (data files); empty for none.
    std::string modelDirectory;
    // Every parameter's value text as the run used it ("Comp.param" -> text, ParameterTexts.h),
    // taken when the job is prepared: what its run history compares with the model's text.
    std::map<std::string, std::string> usedParameters;
    // A run of an assignment's locked copy: `settings` may only repeat the model's own (the
    // template's). Checked when the job is submitted; not stored.
    bool settingsFixed = false;
    // False: its results are given once (the first read of them drops them), so a script's
    // runs do not fill the owner's quota.
    bool keep = true;
    // A live session's recording (live.record): {"session_id", "changes":[{time,name,value}]};
    // such a job was never run as a job, its results are the session's samples.
    std::optional<nlohmann::json> live;

    // Stored with the job so that it can be run again (rerun, restart).
    nlohmann::json toJson() const;
    static bool fromJson(const nlohmann::json& j, JobRequest& out);
};

struct JobInfo {
    std::int64_t id = 0, ownerId = 0;
    std::optional<std::int64_t> modelId;
    JobState state = JobState::Queued;
    double progress = 0.0;                  // 0..1
    std::string error;                      // why it failed; of a done run, the reason a component of
                                            // the model ended it (stop_reason); empty otherwise
    std::int64_t createdAt = 0, startedAt = 0, finishedAt = 0;   // unix s; 0 = not yet
    std::uint64_t steps = 0;                // planned steps; taken steps once finished
    double start = 0.0, step = 0.0, stop = 0.0;   // s, as resolved at submit
    std::size_t logSamples = 0;
    std::string name;                       // the user's name for the run; empty: none
    bool pinned = false;                    // kept whole, whatever the model's other runs do
    bool resultsDropped = false;            // its results went to keep the model's unpinned runs few
    // Only in a model's history (JobStore::listForModel): the overrides the job was submitted
    // with (JobRequest::parameters).
    std::optional<std::map<std::string, std::string>> parameters;
    // Only in a model's history: JobRequest::usedParameters; nullopt for a job stored without.
    std::optional<std::map<std::string, std::string>> usedParameters;
    // Only in GET /jobs/{id} of a run live.record stored: JobRequest::live (the session, its
    // changes, whether the recording was full).
    std::optional<nlohmann::json> live;

    // {id, model_id, state, progress, error, created_at, started_at, finished_at, steps,
    //  settings:{start,step,stop,log_samples}, name, pinned, results_dropped[, parameters]};
    // unset times and model_id are null.
    nlohmann::json toJson() const;
};

struct JobLimits {
    std::uint64_t maxSteps = 50'000'000;      // ceil((stop-start)/step) per job
    std::size_t maxLogSamples = 100'000;
    double maxWallSeconds = 300;              // s a job runs (its time slices; not time parked)
    std::size_t maxResultBytes = 64u << 20;   // ResultTable::byteSize()
    int maxQueuedPerUser = 20;
    // A model's finished runs that keep their results unless pinned (newest first).
    int maxUnpinnedRunsPerModel = 20;
    int maxRunningPerUser = 2;
    // Results kept per user (all their finished jobs); new jobs wait for old ones to be deleted.
    std::size_t maxStoredBytesPerUser = std::size_t(1) << 30;
    ModelLimits model;   // also for models stored through the API
};

} // namespace tlmhub::server
