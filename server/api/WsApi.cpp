#include "server/api/WsApi.h"

#include "server/api/CoreErrorCodes.h"
#include "server/api/QueuedFrame.h"
#include "server/app/HandlerPools.h"
#include "server/auth/AccessPolicy.h"
#include "server/cluster/JobStreams.h"
#include "server/labs/LabAccess.h"
#include "server/labs/LabService.h"
#include "server/labs/LiveLabAccess.h"
#include "server/live/LiveSessionRegistry.h"
#include "server/app/ServerOptions.h"
#include "server/jobs/PreparedJob.h"
#include "server/http/JsonText.h"
#include "server/protocol/Messages.generated.h"
#include "server/protocol/ProtocolConstants.generated.h"
#include "server/protocol/SchemaValidator.h"
#include "server/studies/StudyService.h"
#include "server/protocol/UntrustedJson.h"
#include "server/store/ModelName.h"

#include "core/Model.h"
#include "core/Parameter.h"
#include "core/Results.h"

namespace tlmhub::server {

namespace {

WsApi::Reply failure(const std::string& code, const std::string& message)
{
    WsApi::Reply r;
    r.ok = false;
    r.code = code;
    r.message = message;
    return r;
}

WsApi::Reply success(nlohmann::json data = nlohmann::json::object())
{
    WsApi::Reply r;
    r.data = std::move(data);
    return r;
}

// The message's id when it is one the protocol allows, else null: an error about a bad
// message must not echo an arbitrarily large or deep value back.
nlohmann::json echoableId(const nlohmann::json& msg)
{
    if (!msg.is_object()) return nullptr;
    const auto id = msg.find("id");
    std::string why;
    if (id == msg.end() || !SchemaValidator::protocol().validate("RequestId", *id, why)) return nullptr;
    return *id;
}

// Requests answered on the connection's strand: they touch neither the model nor storage.
// Everything else (parsing, evaluating, copying or writing a model, reading storage) runs on
// the request pool: an I/O thread serves every connection and must not wait for one model.
bool answeredOnConnection(const std::string& type)
{
    return type == "ping" || type == "study.unsubscribe";
}

// Requests whose reply is a whole model (megabytes for a large one): built on the large-reply
// pool within the user's slots there, as GET /models/{id} is.
bool buildsLargeReply(const std::string& type)
{
    return type == "model.open" || type == "model.get" || type == "live.model";
}

// On a locked copy a system parameter keeps the template's type, unit and description, and no
// new one appears: only values change.
std::string sysparamMetadataProblem(const Model& model, const nlohmann::json& msg)
{
    const System* system = &model.root();
    for (const std::string& name : msg.value("system", std::vector<std::string>{})) {
        system = system->subsystem(name);
        if (!system) return "";   // the edit itself reports the missing subsystem
    }
    const std::string name = msg.at("name").get<std::string>();
    const Parameter* own = system->parameters().find(name);
    if (!own) return "an assignment's copy cannot add system parameters (" + name + ")";
    const auto differs = [&msg](const char* key, const std::string& kept) {
        return msg.contains(key) && msg[key].get<std::string>() != kept;
    };
    if (differs("param_type", parameterTypeName(own->type)) || differs("unit", own->unit) ||
        differs("description", own->description))
        return "an assignment's copy changes only the value of " + name + ", not its type, unit or description";
    return "";
}

FrameEncoding frameEncoding(const std::optional<std::string>& frames)
{
    return frames == "binary" ? FrameEncoding::Binary : FrameEncoding::Json;
}

// A LiveSpeed (checked by the schema): a number, or "max" (none).
std::optional<double> liveSpeed(const nlohmann::json& speed)
{
    return speed.is_string() ? std::nullopt : std::optional(speed.get<double>());
}

WsApi::Reply liveReply(const LiveSession::Reply& reply)
{
    return reply.ok() ? success(reply.state) : failure(reply.code, reply.message);
}

} // namespace

WsApi::WsApi(Services& services, User user, const std::string& token, std::shared_ptr<WebSocketSender> sender)
    : mServices(services), mUser(std::move(user)), mSender(std::move(sender)),
      mLiveSession(services.liveSessions.add(token, mUser.id, mSender))
{
    mSender->send(toJsonText(protocol::Hello{.user = publicUser(mUser)}));
}

WsApi::WsApi(Services& services, NodePrincipal, std::shared_ptr<WebSocketSender> sender)
    : mServices(services), mUser{.id = 0, .username = "tlmhub-node", .role = ""}, mSender(std::move(sender)),
      mNode(true)
{
}

WsApi::~WsApi() = default;

void WsApi::onClose()
{
    mClosed = true;
    if (mLiveSession) mServices.liveSessions.remove(mLiveSession);
    {
        std::lock_guard lock(mLiveRunsMutex);
        for (const auto& weak : mLiveRuns)
            if (auto session = weak.lock()) session->stop(std::nullopt);
        mLiveRuns.clear();
        for (const auto& [weak, watchId] : mLiveWatches)
            if (auto session = weak.lock()) session->unwatch(watchId);
        mLiveWatches.clear();
        mLiveRunsClosed = true;
    }
    for (std::uint64_t id : mSubscriptions) mServices.jobStreams.unsubscribe(id);
    mSubscriptions.clear();
    for (const auto& [study, id] : mStudySubscriptions) mServices.studies.hub().unsubscribe(id);
    mStudySubscriptions.clear();
}

void WsApi::sendError(const nlohmann::json& id, const std::string& code, const std::string& message)
{
    mSender->send(answerText(id, failure(code, message)));
}

void WsApi::onMessage(const std::string& text)
{
    if (!mBusy) return handle(text);
    if (mWaiting.size() >= kMaxWaitingMessages)
        return sendError(nullptr, "busy", "too many messages waiting for the previous request's reply");
    mWaiting.push_back(text);
}

void WsApi::handle(const std::string& text)
{
    UntrustedJson parsed = parseUntrustedJson(text);
    if (!parsed.ok()) return sendError(nullptr, "bad_json", "message: " + parsed.error);
    const nlohmann::json& msg = parsed.value;
    const nlohmann::json id = echoableId(msg);
    std::string code, why;
    if (!SchemaValidator::protocol().validateMessage(msg, code, why)) return sendError(id, code, why);
    const std::string type = msg["type"].get<std::string>();
    if (mNode && type != "log.subscribe") return sendError(id, "forbidden", "a node may only send log.subscribe");
    {
        // Any message from the owner keeps its live sessions from the idle timeout.
        std::lock_guard lock(mLiveRunsMutex);
        for (const auto& weak : mLiveRuns)
            if (auto session = weak.lock()) session->touch();
    }
    if (!answeredOnConnection(type)) {
        // On the request pool (a whole model: the large-reply pool); this connection's later
        // messages wait for its reply, so the open model is only ever touched by one thread
        // and replies keep their order.
        mBusy = true;
        // `largeReplySlot`: held while a whole model's reply is built (null on the request pool).
        auto work = [self = shared_from_this(), type, msg = parsed.value, id](PerUserSlots::Slot largeReplySlot) {
            Reply reply = self->dispatchSafely(type, msg);
            const bool ok = reply.ok;
            // simulate.start answers later, once its job is submitted (finishStart).
            const bool deferred = std::exchange(self->mReplyDeferred, false) && ok;
            // A large model's reply is megabytes of JSON: it is written here too.
            std::string text = deferred ? std::string() : answerText(id, std::move(reply));
            largeReplySlot.reset();
            self->mSender->runOnConnection([self, deferred, ok, text = std::move(text)]() mutable {
                if (self->mClosed) return;
                if (!deferred) self->sendAnswer(ok, std::move(text));
                self->mBusy = false;
                while (!self->mBusy && !self->mWaiting.empty()) {
                    const std::string next = std::move(self->mWaiting.front());
                    self->mWaiting.pop_front();
                    self->handle(next);
                }
            });
        };
        if (!buildsLargeReply(type)) return mServices.pools.runRequest([work = std::move(work)] { work(nullptr); });
        if (mServices.pools.runLargeReply(mUser.id, std::move(work))) return;
        mBusy = false;
        return sendError(id, "busy", mServices.pools.largeRepliesBusyMessage());
    }
    Reply reply = dispatchSafely(type, msg);
    const bool ok = reply.ok;
    sendAnswer(ok, answerText(id, std::move(reply)));
}

WsApi::Reply WsApi::dispatchSafely(const std::string& type, const nlohmann::json& msg)
{
    try {
        return dispatch(type, msg);
    } catch (const StoreError& e) {
        return failure(storeErrorCode(e), e.what());
    } catch (const std::exception& e) {
        return failure("internal", e.what());
    }
}

std::string WsApi::answerText(const nlohmann::json& id, Reply reply)
{
    if (!reply.ok) return toJsonText(protocol::ErrorReply{.id = id, .error = {.code = reply.code, .message = reply.message}});
    // A model's data is megabytes of JSON: moved into the envelope, where the protocol struct
    // would copy it twice (into the struct, then out of it).
    nlohmann::json envelope = protocol::Reply{.id = id};
    envelope["data"] = std::move(reply.data);
    return toJsonText(envelope);
}

void WsApi::sendAnswer(bool ok, std::string text)
{
    mSender->send(std::move(text));
    // Stream events start after the reply, so a client always knows the job id first.
    if (auto after = std::exchange(mAfterReply, nullptr); ok && after) after();
}

WsApi::Reply WsApi::dispatch(const std::string& type, const nlohmann::json& msg)
{
    if (type == "ping") return success();
    if (type == "model.open") return openModel(msg.get<protocol::ModelOpenRequest>());
    if (type == "model.create") return createModel(msg.get<protocol::ModelCreateRequest>());
    if (type == "model.save") return saveModel(msg.get<protocol::ModelSaveRequest>());
    if (type == "simulate.start") return startSimulation(msg.get<protocol::SimulateStartRequest>());
    if (type == "simulate.stop") return stopSimulation(msg.get<protocol::SimulateStopRequest>());
    if (type == "log.subscribe") return subscribe(msg.get<protocol::LogSubscribeRequest>());
    if (type == "study.subscribe") return subscribeStudy(msg.get<protocol::StudySubscribeRequest>());
    if (type == "study.unsubscribe") return unsubscribeStudy(msg.get<protocol::StudyUnsubscribeRequest>());
    if (type == "live.start") return startLive(msg.get<protocol::LiveStartRequest>());
    if (type == "live.subscribe") return watchLive(msg.get<protocol::LiveSubscribeRequest>());
    if (type == "live.model") return liveModel(msg.get<protocol::LiveModelRequest>());
    if (type.rfind("live.", 0) == 0) {
        // Only the owner controls a session: to a watcher (a class member) it is not there.
        const auto session = ownLiveSession(msg.at("session_id").get<std::int64_t>());
        if (!session) return failure("not_found", "no such live session");
        session->touch();
        if (type == "live.set") {
            const auto set = msg.get<protocol::LiveSetRequest>();
            if (session->config().labCopy) {
                const std::string problem = liveSetLockProblem(mServices.labs.store(), mUser,
                                                               *session->config().job.modelId, set.name, set.value);
                if (!problem.empty()) return failure("locked", problem);
            }
            const LiveSession::Reply reply = session->set(set.name, set.value);
            return reply.ok() ? success() : failure(reply.code, reply.message);
        }
        if (type == "live.pause") return liveReply(session->pause());
        if (type == "live.resume") return liveReply(session->resume());
        if (type == "live.speed") return liveReply(session->setSpeed(liveSpeed(msg.get<protocol::LiveSpeedRequest>().speed)));
        if (type == "live.step")
            return liveReply(session->step(static_cast<std::uint64_t>(msg.get<protocol::LiveStepRequest>().steps)));
        if (type == "live.stop") return liveReply(session->stop("requested"));
        if (type == "live.record") return recordLive(session);
        if (type == "live.share") return shareLive(session, msg.get<protocol::LiveShareRequest>().classId, true);
        if (type == "live.unshare") return shareLive(session, msg.get<protocol::LiveUnshareRequest>().classId, false);
    }
    if (!mSession.isOpen()) return failure("not_open", "open or create a model first (model.open)");
    if (mModelIsCopy) {
        const std::string problem = copyEditProblem(type, msg);
        if (!problem.empty()) return failure("locked", problem);
    }
    return mSession.handle(msg);
}

std::string WsApi::copyEditProblem(const std::string& type, const nlohmann::json& msg)
{
    if (type == "parameter.get" || type == "model.get") return "";
    const CopyAccess access = copyAccess(mServices.labs.store(), mUser, *mModelId);
    // Read: a supervisor's or an archived class's copy; edits stay in this editor (saved as
    // a new model), as with any read-only model.
    if (access.kind == CopyAccess::Kind::Read) return "";
    if (access.kind == CopyAccess::Kind::None) return "you are no longer in this assignment's class";
    if (!access.lock) return "";
    const auto valueText = [&msg] {
        const nlohmann::json& value = msg.at("value");
        return value.is_string() ? value.get<std::string>() : value.dump();
    };
    const std::vector<std::string> system = msg.value("system", std::vector<std::string>{});
    if (type == "parameter.set")
        return access.lock->valueProblem(
            parameterPath(system, msg.at("component").get<std::string>(), msg.at("parameter").get<std::string>()),
            valueText());
    if (type == "sysparam.set") {
        const std::string problem =
            access.lock->valueProblem(parameterPath(system, "", msg.at("name").get<std::string>()), valueText());
        return problem.empty() ? sysparamMetadataProblem(*mSession.openModel(), msg) : problem;
    }
    return "this assignment lets you change only its listed parameters (" + type + " is not allowed)";
}

WsApi::Reply WsApi::openModel(const protocol::ModelOpenRequest& request)
{
    const auto model = readableModel(mServices, mUser, request.modelId);
    if (!model) return failure("not_found", "no such model");
    std::string error;
    if (!mSession.openHmf(mServices.models.hmf(model->id).value_or(""), model->name, error))
        return failure("invalid_model", error);
    mModelId = model->id;
    mModelName = model->name;
    mModelIsCopy = mServices.labs.store().copyByModel(model->id).has_value();
    return success(protocol::ModelOpenedData{
        .modelId = model->id, .model = mSession.model(), .writable = writableModel(mServices, mUser, *model)});
}

WsApi::Reply WsApi::createModel(const protocol::ModelCreateRequest& request)
{
    const std::string& name = request.name;
    if (const std::string problem = modelNameProblem(name); !problem.empty())
        return failure("bad_request", "model name: " + problem);
    mSession.createEmpty(name);
    mModelId = mServices.models.create(mUser.id, name, mSession.saveHmf(), false);
    if (!mModelId) return failure("not_found", "the account that would own the model does not exist");
    mModelName = name;
    mModelIsCopy = false;
    return success(protocol::ModelOpenedData{.modelId = *mModelId, .model = mSession.model(), .writable = true});
}

WsApi::Reply WsApi::saveModel(const protocol::ModelSaveRequest& request)
{
    if (!mSession.isOpen() || !mModelId) return failure("not_open", "open or create a model first");
    const auto model = mServices.models.summary(*mModelId);
    const bool asCopy = request.asCopy.value_or(false) || !model || !writableModel(mServices, mUser, *model);
    const std::string name = request.name.value_or(mModelName);
    if (const std::string problem = modelNameProblem(name); !problem.empty())
        return failure("bad_request", "model name: " + problem);
    if (asCopy) {
        mModelId = mServices.models.create(mUser.id, name, mSession.saveHmf(), false);
        if (!mModelId) return failure("not_found", "the account that would own the model does not exist");
    } else {
        if (mModelIsCopy && name != mModelName) return failure("locked", "an assignment's copy keeps its name");
        mServices.models.update(*mModelId, name, mSession.saveHmf());
    }
    mModelIsCopy = mModelIsCopy && !asCopy;
    mModelName = name;
    const auto saved = mServices.models.summary(*mModelId);
    return success(protocol::ModelSavedData{
        .modelId = *mModelId, .name = name, .updatedAt = saved ? saved->updatedAt : 0, .copied = asCopy});
}

void WsApi::subscribeToJob(std::int64_t jobId, std::vector<std::string> variables, double rate, FrameEncoding encoding)
{
    if (variables.size() > protocol::kMaxStreamVariables) variables.resize(protocol::kMaxStreamVariables);
    // The sink runs on the job's thread: it only queues, never waits. Frames stay numbers
    // until written, so the socket's queue can merge them (QueuedFrame).
    std::weak_ptr<WebSocketSender> weakSender = mSender;
    auto stream = std::make_shared<FrameStream>();
    stream->id = ++mStreams;
    stream->encoding = encoding;
    StreamSink sink;
    // A newer progress of the job replaces one still waiting for a slow socket.
    sink.progress = [weakSender, key = "event.progress " + std::to_string(jobId)](nlohmann::json event) {
        if (auto sender = weakSender.lock()) sender->sendReplaceable(key, toJsonText(event));
    };
    sink.done = [weakSender](nlohmann::json event) {
        if (auto sender = weakSender.lock()) sender->send(toJsonText(event));
    };
    sink.frame = [weakSender, stream](StreamFrame frame) {
        auto sender = weakSender.lock();
        // After event.resync the client reads the stored result: no more frames for it.
        if (!sender || stream->givenUp.load()) return;
        sender->sendFrame(std::make_unique<QueuedFrame>(std::move(frame), stream));
    };
    // Subscribing reads the job's state from storage, and a finished job's stored result:
    // on the request pool. The subscription is recorded on the connection's strand, or ended
    // at once if the connection is gone by then.
    mServices.pools.runRequest([weak = weak_from_this(), sender = mSender, &services = mServices, jobId,
                                fromNode = mNode,
                                variables = std::move(variables), rate, sink = std::move(sink)] {
        const std::uint64_t id = services.jobStreams.subscribe(jobId, variables, rate, sink, fromNode);
        if (weak.expired()) return services.jobStreams.unsubscribe(id);
        sender->runOnConnection([weak, &services, id] {
            auto self = weak.lock();
            if (!self || self->mClosed) return services.jobStreams.unsubscribe(id);
            self->mSubscriptions.push_back(id);
        });
    });
}

WsApi::Reply WsApi::startSimulation(const protocol::SimulateStartRequest& start)
{
    if (!mSession.isOpen()) return failure("not_open", "open or create a model first (model.open)");
    // The job runs a copy of the model as it is now; later edits do not reach it.
    Result<Model> copy = mSession.openModel()->copy();
    if (!copy) return failure(protocolErrorCode(copy.status().code()), copy.status().message());
    JobRequest request;
    request.ownerId = mUser.id;
    request.modelId = mModelId;
    if (start.start) request.settings.start = *start.start;
    if (start.step) request.settings.step = *start.step;
    if (start.stop) request.settings.stop = *start.stop;
    if (start.logSamples) request.settings.logSamples = static_cast<std::size_t>(*start.logSamples);
    if (mModelIsCopy && mModelId && copyAccess(mServices.labs.store(), mUser, *mModelId).lock)
        request.settingsFixed = true;
    // Saving the model's text (the store keeps it for reruns) and compiling take a while on
    // a large model: both happen on the request pool, and the reply comes back through the
    // connection's strand. Other messages are answered meanwhile.
    mReplyDeferred = true;
    mServices.pools.runRequest([weak = weak_from_this(), sender = mSender, &queue = mServices.queue,
                                request = std::move(request), start,
                                model = std::make_shared<Model>(std::move(*copy))]() mutable {
        request.hmf = model->toHmf();
        JobQueue::Submitted submitted = queue.submit(request, std::move(*model));
        sender->runOnConnection([weak, submitted = std::move(submitted), start] {
            if (auto self = weak.lock()) self->finishStart(start, submitted);
        });
    });
    return success();
}

void WsApi::finishStart(const protocol::SimulateStartRequest& start, const JobQueue::Submitted& submitted)
{
    if (mClosed) return;   // the job runs on; nobody is here to stream it to
    if (!submitted.id) return sendError(start.id, submitted.code, submitted.message);
    mSender->send(toJsonText(protocol::Reply{.id = start.id, .data = protocol::SimulateStartedData{.jobId = *submitted.id}}));
    subscribeToJob(*submitted.id, start.variables.value_or(std::vector<std::string>{}),
                   start.rate.value_or(protocol::kDefaultFrameRate), frameEncoding(start.frames));
}

bool WsApi::ownsJob(std::int64_t jobId) const
{
    const auto job = mServices.queue.store().info(jobId);
    return job && (mNode || canControlJob(mUser, job->ownerId));
}

WsApi::Reply WsApi::stopSimulation(const protocol::SimulateStopRequest& request)
{
    const std::int64_t jobId = request.jobId;
    if (!ownsJob(jobId)) return failure("not_found", "no such job");
    // The reply never waits for the job: event.done (cancelled) follows once it has stopped.
    switch (mServices.queue.requestCancel(jobId)) {
    case JobQueue::CancelRequest::Cancelling:
        return success(protocol::SimulateStoppedData{.state = "cancelling"});
    case JobQueue::CancelRequest::Cancelled:
        return success(protocol::SimulateStoppedData{.state = jobStateName(JobState::Cancelled)});
    case JobQueue::CancelRequest::NotActive:
        break;
    }
    return success(protocol::SimulateStoppedData{.state = jobStateName(mServices.queue.store().info(jobId)->state)});
}

WsApi::Reply WsApi::subscribe(const protocol::LogSubscribeRequest& request)
{
    const std::int64_t jobId = request.jobId;
    if (!ownsJob(jobId)) return failure("not_found", "no such job");
    mAfterReply = [this, jobId, variables = request.variables.value_or(std::vector<std::string>{}),
                   rate = request.rate.value_or(protocol::kDefaultFrameRate), encoding = frameEncoding(request.frames)] {
        subscribeToJob(jobId, variables, rate, encoding);
    };
    return success();
}

WsApi::Reply WsApi::subscribeStudy(const protocol::StudySubscribeRequest& request)
{
    const std::int64_t studyId = request.studyId;
    const auto study = mServices.studies.store().info(studyId);
    if (!study || !canControlJob(mUser, study->ownerId)) return failure("not_found", "no such study");
    if (isFinished(study->state)) {
        // Finished before this server's time, or long ago: its last event from the store.
        nlohmann::json event = {{"type", "event.study.progress"}, {"study_id", studyId},
                                {"state", jobStateName(study->state)}, {"runs_done", study->runsDone},
                                {"runs_failed", study->runsFailed}, {"runs_total", study->runsTotal},
                                {"rows", nlohmann::json::array()}};
        if (!study->error.empty()) event["error"] = study->error;
        mAfterReply = [sender = mSender, text = event.dump()] { sender->send(text); };
        return success();
    }
    mAfterReply = [this, studyId] {
        // Subscribed again (the study ended and was resumed, or a client that lost track):
        // the old subscription gives way, so the study's events come once.
        if (const auto old = mStudySubscriptions.find(studyId); old != mStudySubscriptions.end()) {
            mServices.studies.hub().unsubscribe(old->second);
            mStudySubscriptions.erase(old);
        }
        std::weak_ptr<WebSocketSender> weakSender = mSender;
        const std::uint64_t id = mServices.studies.hub().subscribe(studyId, [weakSender](const nlohmann::json& event) {
            if (auto sender = weakSender.lock()) sender->send(event.dump());
        });
        if (id) mStudySubscriptions.emplace(studyId, id);
    };
    return success();
}

WsApi::Reply WsApi::unsubscribeStudy(const protocol::StudyUnsubscribeRequest& request)
{
    const auto found = mStudySubscriptions.find(request.studyId);
    if (found != mStudySubscriptions.end()) {
        mServices.studies.hub().unsubscribe(found->second);
        mStudySubscriptions.erase(found);
    }
    return success();
}

std::shared_ptr<LiveSession> WsApi::ownLiveSession(std::int64_t sessionId)
{
    if (sessionId <= 0) return nullptr;
    auto session = mServices.liveSimulations.find(static_cast<std::uint64_t>(sessionId));
    // Another user's session is not there for this one (not even an administrator's).
    return session && session->ownerId() == mUser.id ? session : nullptr;
}

WsApi::Reply WsApi::startLive(const protocol::LiveStartRequest& request)
{
    if (mServices.options.role == "worker")
        return failure("forbidden", "this node is a worker (--role worker): live sessions run on the API node a client is connected to");
    const auto model = readableModel(mServices, mUser, request.modelId);
    if (!model) return failure("not_found", "no such model");
    if (const auto refused = mServices.liveSimulations.reserve(mUser.id)) return failure(refused->code, refused->message);
    // The place goes back on every way out (refusals, exceptions) but a created session.
    struct Place {
        LiveSessionRegistry& registry;
        std::int64_t userId;
        bool taken = false;
        ~Place()
        {
            if (!taken) registry.release(userId);
        }
    } place{mServices.liveSimulations, mUser.id};
    // Compiled once, as a job's model is (the same limits); the session steps it from then on.
    JobRequest job;
    job.ownerId = mUser.id;
    job.modelId = model->id;
    job.hmf = mServices.models.hmf(model->id).value_or("");
    PreparedJob prepared;
    PrepareError error;
    // A session streams its node values and records its frames (live.record): the model's own
    // log is not read, and its log samples are held to the limit rather than refused for it.
    JobRequest compiled = job;
    compiled.settings.logSamples = std::min(kDefaultLogSamples, mServices.options.limits.maxLogSamples);
    if (!prepareJob(compiled, mServices.options.limits, prepared, error)) return failure(error.code, error.message);
    job.usedParameters = prepared.usedParameters;
    Simulation& simulation = *prepared.simulation;
    // Named variables: as many as an animated diagram of a large model needs; none named: the
    // first logged ones, as a job stream shows.
    std::vector<std::string> names = request.variables.value_or(std::vector<std::string>{});
    if (names.size() > protocol::kMaxLiveVariables)
        return failure("limit_exceeded", "variables: a live session streams at most " +
                                             std::to_string(protocol::kMaxLiveVariables) + " variables, " +
                                             std::to_string(names.size()) + " were named");
    if (names.empty()) {
        for (const LoggedVariable& v : listLoggedVariables(simulation.system())) names.push_back(v.fullName);
        if (names.size() > protocol::kMaxStreamVariables) names.resize(protocol::kMaxStreamVariables);
    }
    std::vector<LiveVariable> variables;
    for (const std::string& name : names) {
        Result<VariableRef> ref = resolveVariable(simulation.system(), name);
        if (!ref || !ref->port->node())
            return failure("bad_request", "variables: " + (ref ? name + " has no value to show" : ref.status().message()));
        variables.push_back({name, *ref});
    }

    LiveSessionSink sink = liveSink(request.frames);
    LiveSessionConfig config;
    config.ownerId = mUser.id;
    config.speed = request.speed ? liveSpeed(*request.speed) : std::optional(1.0);
    config.paused = request.paused.value_or(false);
    config.rate = std::min(request.rate.value_or(protocol::kDefaultFrameRate), protocol::kMaxFrameRate);
    const double start = prepared.start, step = prepared.step, stop = prepared.stop;
    // A recorded sample holds its time and a value per variable: a recording stays within what
    // a job may store, however many variables the session streams.
    const JobLimits& limits = mServices.options.limits;
    const std::size_t samplesWithinResultBytes = limits.maxResultBytes / ((variables.size() + 1) * sizeof(double));
    config.maxRecordedSamples = std::min(limits.maxLogSamples, samplesWithinResultBytes);
    if (samplesWithinResultBytes < limits.maxLogSamples)
        config.recordLimit = "the job result limit of " + std::to_string(limits.maxResultBytes >> 20) + " MiB";
    config.job = std::move(job);
    config.labCopy = mServices.labs.store().copyByModel(model->id).has_value();
    config.resolved.start = start;
    config.resolved.step = step;
    config.resolved.stop = stop;
    auto session =
        mServices.liveSimulations.create(std::move(config), std::move(simulation), std::move(variables), std::move(sink));
    place.taken = true;
    {
        std::lock_guard lock(mLiveRunsMutex);
        std::erase_if(mLiveRuns, [](const std::weak_ptr<LiveSession>& weak) { return weak.expired(); });
        mLiveRuns.push_back(session);
        if (mLiveRunsClosed) session->stop(std::nullopt);   // nobody is here to watch it
    }
    // On a locked copy its student sees only what the assignment lets them change.
    protocol::LiveStartedData data{
        .sessionId = static_cast<std::int64_t>(session->id()), .variables = names,
        .liveValues = changeableLiveValues(mServices.labs.store(), mUser, model->id, session->liveValues()),
        .start = start, .step = step, .stop = stop};
    // Its frames start after the reply, so the client knows the session's id first.
    mAfterReply = [session] { session->start(); };
    return success(data);
}

LiveSessionSink WsApi::liveSink(const std::optional<std::string>& frames)
{
    // Frames queue on the connection as a job's do (merged for a slow reader); a connection
    // that gives the stream up stops getting them (LiveSession ends or unwatches it). Frames
    // and states leave through the registry's outbox, in order, with the other sessions' of
    // the same tick.
    std::weak_ptr<WebSocketSender> weakSender = mSender;
    auto stream = std::make_shared<FrameStream>();
    stream->id = ++mStreams;
    stream->encoding = frameEncoding(frames);
    ConnectionOutbox& outbox = mServices.liveSimulations.outbox();
    LiveSessionSink sink;
    sink.frame = [weakSender, stream, &outbox](StreamFrame frame) {
        auto sender = weakSender.lock();
        if (!sender || stream->givenUp.load()) return false;
        sender->sendFrameVia(outbox, std::make_unique<QueuedFrame>(std::move(frame), stream));
        return true;
    };
    sink.event = [weakSender, &outbox](std::string text) {
        if (auto sender = weakSender.lock()) sender->sendVia(outbox, std::move(text));
    };
    return sink;
}

WsApi::Reply WsApi::recordLive(const std::shared_ptr<LiveSession>& session)
{
    const LiveSessionConfig& config = session->config();
    LiveRecording recording = session->recording();
    const JobLimits& limits = mServices.options.limits;
    const std::size_t bytes = recording.samples.byteSize();
    if (mServices.queue.results().storedBytes(mUser.id) + bytes > limits.maxStoredBytesPerUser)
        return failure("limit_exceeded", "your stored results would pass the limit of " +
                                             std::to_string(limits.maxStoredBytesPerUser) +
                                             " bytes (--max-stored-bytes-per-user): delete old runs first");
    JobRequest job = config.job;
    nlohmann::json changes = nlohmann::json::array();
    for (const LiveChange& c : recording.changes)
        changes.push_back({{"time", c.time}, {"name", c.name}, {"value", c.value}});
    job.live = nlohmann::json{{"session_id", session->id()}, {"changes", changes}, {"full", recording.full}};
    JobInfo resolved = config.resolved;
    resolved.steps = recording.steps;
    resolved.logSamples = recording.samples.time.size();
    // Stored as a job that ran and finished, in one transaction: it is never queued where a
    // node's job workers could claim it. A store failure throws (nothing is stored).
    JobStore& store = mServices.queue.store();
    const std::int64_t jobId =
        store.createFinished(job, resolved, recording.steps, recording.samples.serialize(),
                             "live session " + std::to_string(session->id()) + " (recorded)");
    if (job.modelId) store.dropOldResults(*job.modelId, limits.maxUnpinnedRunsPerModel);
    return success(nlohmann::json{{"job_id", jobId},
                                  {"samples", recording.samples.time.size()},
                                  {"changes", changes},
                                  {"full", recording.full}});
}

std::shared_ptr<LiveSession> WsApi::watchableLiveSession(std::int64_t sessionId, std::int64_t& throughClass)
{
    throughClass = 0;
    auto session = sessionId > 0 ? mServices.liveSimulations.find(static_cast<std::uint64_t>(sessionId)) : nullptr;
    if (!session || session->ownerId() == mUser.id) return session;
    // Another user's session is there only for members of a class it is shared with.
    const auto shared = watchingClass(mServices.labs.store(), mUser, session->sharedClasses());
    if (!shared) return nullptr;
    throughClass = *shared;
    return session;
}

WsApi::Reply WsApi::watchLive(const protocol::LiveSubscribeRequest& request)
{
    std::int64_t throughClass = 0;
    const auto session = watchableLiveSession(request.sessionId, throughClass);
    if (!session) return failure("not_found", "no such live session");
    if (session->ownerId() == mUser.id) session->touch();
    const LiveSession::Reply state = session->state();
    if (!state.ok()) return liveReply(state);
    // The kept samples and then the live ones follow the reply.
    mAfterReply = [this, session, throughClass, sink = liveSink(request.frames)]() mutable {
        const std::uint64_t watchId = session->watch(std::move(sink), throughClass);
        std::lock_guard lock(mLiveRunsMutex);
        if (watchId) mLiveWatches.emplace_back(session, watchId);
    };
    return liveReply(state);
}

WsApi::Reply WsApi::liveModel(const protocol::LiveModelRequest& request)
{
    std::int64_t throughClass = 0;
    const auto session = watchableLiveSession(request.sessionId, throughClass);
    if (!session) return failure("not_found", "no such live session");
    const JobRequest& job = session->config().job;
    const auto summary = job.modelId ? mServices.models.summary(*job.modelId) : std::nullopt;
    const std::string name = summary ? summary->name : std::string();
    // The text the session was compiled from (it loaded then), not the model as it is now.
    EditSession drawing;
    std::string error;
    if (!drawing.openHmf(job.hmf, name, error)) return failure("invalid_model", error);
    return success(protocol::LiveModelData{.modelName = name, .model = drawing.model(), .variables = session->variableNames()});
}

WsApi::Reply WsApi::shareLive(const std::shared_ptr<LiveSession>& session, std::int64_t classId, bool shared)
{
    if (!shared) {
        // Always allowed to its owner (also once they no longer teach the class).
        session->unshare(classId);
        return success(protocol::LiveSharedData{.classIds = session->sharedClasses()});
    }
    if (const auto refused = liveShareRefusal(mServices.labs.store(), mUser, classId))
        return failure(refused->code, refused->message);
    session->share(classId);
    return success(protocol::LiveSharedData{.classIds = session->sharedClasses()});
}

} // namespace tlmhub::server
