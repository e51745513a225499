#include "server/studies/StudyService.h"

#include "server/api/CoreErrorCodes.h"
#include "server/jobs/ModelLimits.h"
#include "server/jobs/PreparedJob.h"
#include "server/jobs/StorageQuota.h"
#include "server/NumberText.h"
#include "server/studies/RunMeasures.h"

#include "core/ResultView.h"

#include <cmath>
#include <iostream>

namespace tlmhub::server {

namespace {

nlohmann::json parseOr(const std::string& text, nlohmann::json fallback)
{
    auto parsed = nlohmann::json::parse(text, nullptr, false);
    return parsed.is_discarded() ? fallback : parsed;
}

} // namespace

StudyService::StudyService(StudyStore& store, ResultStore& results, JobQueue& queue, StudyProgressHub& hub,
                           const JobLimits& jobLimits, StudyLimits limits, unsigned workers, QueueNode node)
    : mStore(store), mResults(results), mQueue(queue), mHub(hub), mJobLimits(jobLimits), mLimits(limits),
      mWorkers(std::max(1u, workers)), mNode(std::move(node))
{
}

StudyService::~StudyService()
{
    stop();
}

void StudyService::start()
{
    if (mNode.role == "worker" || mWatcher.joinable()) return;
    adoptOrphans();
    mWatcher = std::jthread([this](std::stop_token stop) { watchOrphans(stop); });
}

void StudyService::stop()
{
    if (!mWatcher.joinable()) return;
    mWatcher.request_stop();   // wakes its wait
    mWatcher.join();
    try {
        mStore.releaseQueued(mNode.id);
    } catch (const std::exception& e) {
        // The next node adopts them once this one is no longer seen (a lease time).
        std::cerr << "studies: releasing this node's queued studies failed: " << e.what() << "\n";
    }
}

void StudyService::adoptOrphans()
{
    // This node's own heartbeat comes from the job queue, which may not have started yet:
    // the store never counts the adopting node's studies as orphans.
    for (const StudyInfo& info : mStore.adoptOrphans(mNode.id, mNode.leaseTime)) {
        if (const Submitted queued = enqueueStored(info); !queued.code.empty())
            mStore.finish(info.id, JobState::Failed, queued.message, "{}");
    }
}

void StudyService::watchOrphans(std::stop_token stop)
{
    bool failing = false;
    std::unique_lock lock(mWatchMutex);
    for (;;) {
        // Returns early only when stop is requested.
        mWatchWake.wait_for(lock, stop, mNode.leaseTime / 3, [] { return false; });
        if (stop.stop_requested()) return;
        lock.unlock();
        try {
            adoptOrphans();
            if (failing) std::cerr << "studies: the database answers again\n";
            failing = false;
        } catch (const std::exception& e) {
            if (!failing) std::cerr << "studies: taking over the studies of stopped nodes failed: " << e.what() << "\n";
            failing = true;
        }
        lock.lock();
    }
}

StudyService::Submitted StudyService::enqueueStored(const StudyInfo& info)
{
    const auto text = mStore.request(info.id);
    const nlohmann::json body = text ? parseOr(*text, nullptr) : nlohmann::json();
    if (!body.is_object()) return {std::nullopt, 0, "internal", "the stored request is unreadable"};
    PreparedStudy prepared;
    Submitted checked = prepare(info.ownerId, body, body.value("hmf", ""), prepared);
    if (!checked.code.empty()) return checked;
    prepared.id = info.id;
    prepared.ownerId = info.ownerId;
    constexpr std::size_t kPage = 1000;
    for (std::int64_t from = 0;;) {
        std::vector<StudyRun> page = mStore.runs(info.id, from, kPage);
        for (StudyRun& run : page) prepared.storedRuns.emplace(run.index, std::move(run));
        if (page.size() < kPage) break;
        from = prepared.storedRuns.rbegin()->first + 1;
    }
    mQueue.addStudy(std::make_shared<StudyExecution>(std::move(prepared), mJobLimits, mLimits, mWorkers, mStore, mHub));
    checked.id = info.id;
    return checked;
}

std::optional<StudyService::Submitted> StudyService::overActiveLimit(std::int64_t ownerId)
{
    if (mStore.activeCount(ownerId) < mLimits.maxActivePerUser) return std::nullopt;
    // Temporary: room comes as the user's studies end.
    return Submitted{std::nullopt, 0, "rate_limited",
                     "you have " + std::to_string(mLimits.maxActivePerUser) + " studies queued or running; the limit is " +
                         std::to_string(mLimits.maxActivePerUser) +
                         " (--max-studies-per-user): try again when one has ended"};
}

StudyService::Submitted StudyService::resume(const StudyInfo& info)
{
    if (info.state != JobState::Interrupted && info.state != JobState::Cancelled)
        return {std::nullopt, 0, "conflict",
                "the study is " + std::string(jobStateName(info.state)) + ": only an interrupted or cancelled study resumes"};
    if (auto refused = overActiveLimit(info.ownerId)) return *refused;
    if (!mStore.reopen(info.id, mNode.id, mLimits.maxActivePerUser)) {
        // Another of the owner's studies was admitted meanwhile, on any node, or this one changed state.
        if (auto refused = overActiveLimit(info.ownerId)) return *refused;
        return {std::nullopt, 0, "conflict", "the study changed state meanwhile: only an interrupted or cancelled study resumes"};
    }
    mHub.reopen(info.id);
    Submitted queued = enqueueStored(info);
    if (!queued.code.empty()) mStore.finish(info.id, JobState::Failed, queued.message, "{}");
    return queued;
}

StudyService::Submitted StudyService::prepare(std::int64_t ownerId, const nlohmann::json& body, const std::string& hmf,
                                              PreparedStudy& prepared)
{
    StudyRequest& request = prepared.request;
    std::string problem;
    if (!parseStudyRequest(body, request, problem)) return {std::nullopt, 0, "bad_request", problem};
    request.hmf = hmf;
    prepared.node = mNode.id;   // this node holds what it prepares
    const std::size_t runs = request.plannedRuns();
    if (runs == 0) return {std::nullopt, 0, "bad_request", "the study has no runs"};
    if (runs > mLimits.maxRuns)
        return {std::nullopt, 0, "limit_exceeded",
                "the study has " + std::to_string(runs) + " runs; the limit is " + std::to_string(mLimits.maxRuns) +
                    " (--max-study-runs)"};

    // The model is parsed once: a copy compiles now (the check, and a first worker's
    // simulation), the rest are compiled from it by the workers.
    LoadedModel loaded = loadUntrustedModel(hmf, mJobLimits.model, {}, request.modelId ? "model " + std::to_string(*request.modelId) : "model");
    if (const Status status = loaded.status(); !status) return {std::nullopt, 0, protocolErrorCode(status.code()), status.message()};
    Model model(std::move(loaded.root));
    if (const Status set = applyParameterOverrides(model.root(), request.fixedParameters); !set)
        return {std::nullopt, 0, protocolErrorCode(set.code()), set.message()};
    Result<Model> copy = model.copy();
    if (!copy) return {std::nullopt, 0, protocolErrorCode(copy.status().code()), copy.status().message()};

    JobRequest job;
    job.ownerId = ownerId;
    job.modelId = request.modelId;
    job.hmf = hmf;
    job.settings = request.settings;
    PreparedJob compiled;
    PrepareError error;
    if (!prepareJob(job, std::move(*copy), mJobLimits, compiled, error)) return {std::nullopt, 0, error.code, error.message};
    Simulation& simulation = *compiled.simulation;

    // Every varied parameter must take a value, and every variable read must be logged.
    const std::vector<std::string> names = request.parameterNames();
    for (const ParameterBounds& bounds : request.optimiser.parameters) {
        if (const Status set = simulation.setParameter(bounds.name, std::to_string(bounds.min)); !set)
            return {std::nullopt, 0, protocolErrorCode(set.code()), bounds.name + ": " + set.message()};
    }
    if (request.kind != StudyKind::Optimise) {
        StudyPlan plan(request);
        const auto first = plan.next();
        for (std::size_t i = 0; first && i < names.size(); ++i) {
            if (const Status set = simulation.setParameter(names[i], exactNumber(first->values[i])); !set)
                return {std::nullopt, 0, protocolErrorCode(set.code()), names[i] + ": " + set.message()};
        }
    }
    // The logged variables are known once the logs exist (initialised; each run resets it).
    if (const Status initialised = simulation.initialise(); !initialised)
        return {std::nullopt, 0, protocolErrorCode(initialised.code()), initialised.message()};
    const ResultView variables(simulation.system());
    for (const std::string& name : variablesRead(request)) {
        if (!variables.indexOf(name))
            return {std::nullopt, 0, "bad_request", "the model logs no variable '" + name + "'"};
    }

    if (request.outputs.full) {
        // Bounded from above by the uncompressed size, as a job's result limit is.
        const std::size_t perRun = (variables.numVariables() + 1) * (compiled.logSamples + 1) * sizeof(double);
        const double total = static_cast<double>(perRun) * static_cast<double>(runs);
        if (total > static_cast<double>(mLimits.maxStoredBytes))
            return {std::nullopt, 0, "limit_exceeded",
                    "keeping every run's result needs up to " + byteSize(static_cast<std::size_t>(total)) +
                        "; a study may keep " + byteSize(mLimits.maxStoredBytes) +
                        " (--max-study-bytes): fewer runs or log_samples, or outputs.full false"};
        const std::size_t stored = mResults.storedBytes(ownerId);
        if (static_cast<double>(stored) + total > static_cast<double>(mJobLimits.maxStoredBytesPerUser))
            return {std::nullopt, 0, "limit_exceeded",
                    "keeping every run's result needs up to " + byteSize(static_cast<std::size_t>(total)) + "; " +
                        quotaMessage(stored, mJobLimits.maxStoredBytesPerUser)};
    }
    prepared.model = std::make_shared<const Model>(std::move(model));
    prepared.settings = {compiled.start, compiled.stop, compiled.step, compiled.logSamples};
    // Its parameters were set by the checks above; each run sets them again.
    prepared.compiled.emplace(std::move(simulation));
    return {std::nullopt, runs, {}, {}};
}

StudyService::Submitted StudyService::submit(std::int64_t ownerId, const nlohmann::json& body, const std::string& hmf)
{
    if (auto refused = overActiveLimit(ownerId)) return *refused;
    PreparedStudy prepared;
    Submitted checked = prepare(ownerId, body, hmf, prepared);
    if (!checked.code.empty()) return checked;
    nlohmann::json stored = body;
    stored.erase("model_id");
    stored["hmf"] = hmf;   // what runs again after a restart, even if the model changes
    const auto id = mStore.create(ownerId, prepared.request.modelId, studyKindName(prepared.request.kind),
                                  prepared.request.name, stored.dump(), static_cast<std::int64_t>(checked.runsTotal),
                                  mNode.id, mLimits.maxActivePerUser);
    if (!id) {
        // Another of the owner's studies was admitted meanwhile, on any node.
        if (auto refused = overActiveLimit(ownerId)) return *refused;
        return {std::nullopt, 0, "not_found", "no such user"};
    }
    prepared.id = *id;
    prepared.ownerId = ownerId;
    mQueue.addStudy(std::make_shared<StudyExecution>(std::move(prepared), mJobLimits, mLimits, mWorkers, mStore, mHub));
    checked.id = id;
    return checked;
}

bool StudyService::cancel(std::int64_t id)
{
    if (mQueue.stopStudy(id)) return true;
    // Queued in the store but not in the queue (not started yet).
    const auto info = mStore.info(id);
    return info && info->state == JobState::Queued && mStore.finish(id, JobState::Cancelled, {}, "{}");
}

nlohmann::json StudyService::infoJson(const StudyInfo& info)
{
    auto time = [](std::int64_t t) { return t ? nlohmann::json(t) : nlohmann::json(); };
    nlohmann::json summary = info.summary.empty() ? nlohmann::json::object() : parseOr(info.summary, nlohmann::json::object());
    // The bands are long: GET /studies/{id}/bands gives them; here only how many runs they count.
    if (summary.contains("bands") && summary["bands"].is_object() && summary["bands"].contains("n"))
        summary["bands_n"] = summary["bands"]["n"];
    summary.erase("bands");
    const std::int64_t finished = info.runsDone + info.runsFailed;
    double progress = info.runsTotal > 0 ? static_cast<double>(finished) / static_cast<double>(info.runsTotal) : 0.0;
    if (info.state == JobState::Done) progress = 1.0;
    return {{"id", info.id},
            {"kind", info.kind},
            {"name", info.name},
            {"model_id", info.modelId ? nlohmann::json(*info.modelId) : nlohmann::json()},
            {"state", jobStateName(info.state)},
            {"runs_total", info.runsTotal},
            {"runs_done", info.runsDone},
            {"runs_failed", info.runsFailed},
            {"progress", std::min(1.0, progress)},
            {"error", info.error},
            {"created_at", time(info.createdAt)},
            {"started_at", time(info.startedAt)},
            {"finished_at", time(info.finishedAt)},
            {"summary", summary}};
}

std::optional<StudyService::Table> StudyService::table(std::int64_t id)
{
    const auto text = mStore.request(id);
    if (!text) return std::nullopt;
    StudyRequest request;
    std::string problem;
    if (!parseStudyRequest(parseOr(*text, nullptr), request, problem)) return std::nullopt;
    Table table;
    table.columns = StudyExecution::tableColumns(request);
    const std::vector<std::string> parameters = request.parameterNames();
    const std::vector<std::string> outputs = request.outputs.columnNames();
    constexpr std::size_t kPage = 1000;
    for (std::int64_t from = 0;;) {
        const std::vector<StudyRun> page = mStore.runs(id, from, kPage);
        for (const StudyRun& run : page) {
            const nlohmann::json values = parseOr(run.parameters, nlohmann::json::object());
            const nlohmann::json measured = parseOr(run.outputs, nlohmann::json::object());
            nlohmann::json row = nlohmann::json::array({run.index, run.ok ? 1 : 0});
            for (const std::string& name : parameters) row.push_back(values.value(name, nlohmann::json()));
            for (const std::string& name : outputs) row.push_back(measured.value(name, nlohmann::json()));
            if (request.objective) row.push_back(measured.value("objective", nlohmann::json()));
            table.rows.push_back(std::move(row));
            table.nodes.push_back(run.node);
            if (!run.ok) table.errors[run.index] = run.error;
        }
        if (page.size() < kPage) break;
        from = page.back().index + 1;
    }
    return table;
}

std::string StudyService::tableCsv(const Table& table)
{
    std::string csv;
    for (std::size_t c = 0; c < table.columns.size(); ++c) csv += (c ? "," : "") + table.columns[c];
    csv += '\n';
    for (const nlohmann::json& row : table.rows) {
        for (std::size_t c = 0; c < row.size(); ++c) {
            if (c) csv += ',';
            if (row[c].is_number_integer()) csv += std::to_string(row[c].get<std::int64_t>());
            else if (row[c].is_number()) csv += exactNumber(row[c].get<double>());
        }
        csv += '\n';
    }
    return csv;
}

std::optional<nlohmann::json> StudyService::bandsJson(const StudyInfo& info)
{
    const nlohmann::json summary = parseOr(info.summary, nlohmann::json::object());
    if (!summary.contains("bands")) return std::nullopt;
    const nlohmann::json& bands = summary["bands"];
    nlohmann::json out = {{"time", bands["time"]}, {"variables", nlohmann::json::object()}};
    if (bands.contains("n")) out["n"] = bands["n"];   // the runs they come from (not in older studies)
    for (const auto& [name, stats] : bands["variables"].items()) {
        const std::vector<double> mean = stats["mean"].get<std::vector<double>>();
        const std::vector<double> sd = stats["sd"].get<std::vector<double>>();
        nlohmann::json v = {{"mean", mean}, {"sd", sd}};
        for (const auto& [key, k] : {std::pair{"minus_2sd", -2.0}, {"minus_1sd", -1.0}, {"plus_1sd", 1.0}, {"plus_2sd", 2.0}}) {
            std::vector<double> band(mean.size());
            for (std::size_t i = 0; i < mean.size(); ++i) band[i] = mean[i] + k * sd[i];
            v[key] = band;
        }
        out["variables"][name] = v;
    }
    return out;
}

std::optional<std::string> StudyService::bandsCsv(const StudyInfo& info)
{
    const auto bands = bandsJson(info);
    if (!bands) return std::nullopt;
    const std::vector<double> time = (*bands)["time"].get<std::vector<double>>();
    const char* order[] = {"minus_2sd", "minus_1sd", "mean", "plus_1sd", "plus_2sd"};
    const char* labels[] = {"mean-2sd", "mean-sd", "mean", "mean+sd", "mean+2sd"};
    std::string csv = "time";
    std::vector<std::vector<double>> columns;
    for (const auto& [name, v] : (*bands)["variables"].items()) {
        for (std::size_t k = 0; k < 5; ++k) {
            csv += "," + name + ":" + labels[k];
            columns.push_back(v[order[k]].get<std::vector<double>>());
        }
    }
    csv += '\n';
    for (std::size_t i = 0; i < time.size(); ++i) {
        csv += exactNumber(time[i]);
        for (const auto& column : columns) {
            csv += ',';
            if (i < column.size() && std::isfinite(column[i])) csv += exactNumber(column[i]);
        }
        csv += '\n';
    }
    return csv;
}

} // namespace tlmhub::server
