#include "server/jobs/Job.h"

#include "server/protocol/Messages.generated.h"

namespace tlmhub::server {

namespace {

constexpr std::pair<JobState, const char*> kStateNames[] = {
    {JobState::Queued, "queued"},       {JobState::Running, "running"},
    {JobState::Done, "done"},           {JobState::Failed, "failed"},
    {JobState::Cancelled, "cancelled"}, {JobState::Interrupted, "interrupted"},
    {JobState::Dead, "dead"},
};

// A time of a job, none while it has not happened (0).
std::optional<std::int64_t> timeIfSet(std::int64_t t) { return t ? std::optional<std::int64_t>(t) : std::nullopt; }

} // namespace

const char* jobStateName(JobState state)
{
    for (const auto& [s, name] : kStateNames)
        if (s == state) return name;
    return "unknown";
}

bool jobStateFromName(const std::string& name, JobState& out)
{
    for (const auto& [s, n] : kStateNames) {
        if (name == n) {
            out = s;
            return true;
        }
    }
    return false;
}

bool isFinished(JobState state)
{
    return state != JobState::Queued && state != JobState::Running;
}

bool endedByModel(JobState state, const std::string& message)
{
    return state == JobState::Done && !message.empty();
}

nlohmann::json JobRequest::toJson() const
{
    nlohmann::json settingsJson = nlohmann::json::object();
    if (settings.start) settingsJson["start"] = *settings.start;
    if (settings.step) settingsJson["step"] = *settings.step;
    if (settings.stop) settingsJson["stop"] = *settings.stop;
    if (settings.logSamples) settingsJson["log_samples"] = *settings.logSamples;
    nlohmann::json out = {{"owner_id", ownerId},
                          {"model_id", modelId ? nlohmann::json(*modelId) : nlohmann::json(nullptr)},
                          {"hmf", hmf},
                          {"parameters", parameters},
                          {"settings", std::move(settingsJson)},
                          {"model_directory", modelDirectory}};
    if (!usedParameters.empty()) out["used_parameters"] = usedParameters;
    if (!keep) out["keep"] = false;
    if (live) out["live"] = *live;
    return out;
}

bool JobRequest::fromJson(const nlohmann::json& j, JobRequest& out)
{
    try {
        JobRequest r;
        r.ownerId = j.at("owner_id").get<std::int64_t>();
        if (!j.at("model_id").is_null()) r.modelId = j.at("model_id").get<std::int64_t>();
        r.hmf = j.at("hmf").get<std::string>();
        r.parameters = j.at("parameters").get<std::map<std::string, std::string>>();
        const auto& s = j.at("settings");
        if (s.contains("start")) r.settings.start = s.at("start").get<double>();
        if (s.contains("step")) r.settings.step = s.at("step").get<double>();
        if (s.contains("stop")) r.settings.stop = s.at("stop").get<double>();
        if (s.contains("log_samples")) r.settings.logSamples = s.at("log_samples").get<std::size_t>();
        r.modelDirectory = j.value("model_directory", std::string());
        if (j.contains("used_parameters"))
            r.usedParameters = j.at("used_parameters").get<std::map<std::string, std::string>>();
        r.keep = j.value("keep", true);
        if (j.contains("live")) r.live = j.at("live");
        out = std::move(r);
        return true;
    } catch (const nlohmann::json::exception&) {
        return false;
    }
}

nlohmann::json JobInfo::toJson() const
{
    const bool stopped = endedByModel(state, error);
    return protocol::JobInfo{
        .id = id,
        .ownerId = std::nullopt,   // the API does not show it
        .modelId = modelId,
        .state = jobStateName(state),
        .progress = progress,
        .error = stopped ? std::string() : error,
        .stopReason = stopped ? std::optional<std::string>(error) : std::nullopt,
        .createdAt = createdAt,
        .startedAt = timeIfSet(startedAt),
        .finishedAt = timeIfSet(finishedAt),
        .steps = static_cast<std::int64_t>(steps),
        .settings = {.start = start, .step = step, .stop = stop, .logSamples = static_cast<std::int64_t>(logSamples)},
        .name = name,
        .pinned = pinned,
        .resultsDropped = resultsDropped,
        .owner = std::nullopt,
        .parameters = parameters,
        .differingParameters = std::nullopt,
        .differingParametersTruncated = std::nullopt,
        .live = live ? std::optional(live->get<protocol::LiveRecording>()) : std::nullopt};
}

} // namespace tlmhub::server
