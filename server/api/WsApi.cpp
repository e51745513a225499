#include "server/api/WsApi.h"

#include "server/api/QueuedFrame.h"
#include "server/app/HandlerPools.h"
#include "server/auth/AccessPolicy.h"
#include "server/http/JsonText.h"
#include "server/protocol/SchemaValidator.h"
#include "server/protocol/UntrustedJson.h"
#include "server/store/ModelName.h"

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

constexpr std::size_t kMaxStreamedVariables = 16;

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

} // namespace

WsApi::WsApi(Services& services, User user, const std::string& token, std::shared_ptr<WebSocketSender> sender)
    : mServices(services), mUser(std::move(user)), mSender(std::move(sender)),
      mLiveSession(services.liveSessions.add(token, mUser.id, mSender))
{
    mSender->send(toJsonText({{"type", "hello"}, {"protocol", "tlmhub.v1"}, {"user", userJson(mUser)}}));
}

WsApi::~WsApi() = default;

void WsApi::onClose()
{
    mClosed = true;
    mServices.liveSessions.remove(mLiveSession);
    for (std::uint64_t id : mSubscriptions) mServices.streams.unsubscribe(id);
    mSubscriptions.clear();
}

void WsApi::sendError(const nlohmann::json& id, const std::string& code, const std::string& message)
{
    mSender->send(toJsonText({{"id", id}, {"type", "error"}, {"error", {{"code", code}, {"message", message}}}}));
}

void WsApi::onMessage(const std::string& text)
{
    UntrustedJson parsed = parseUntrustedJson(text);
    if (!parsed.ok()) return sendError(nullptr, "bad_json", "message: " + parsed.error);
    const nlohmann::json& msg = parsed.value;
    const nlohmann::json id = echoableId(msg);
    std::string code, why;
    if (!SchemaValidator::protocol().validateMessage(msg, code, why)) return sendError(id, code, why);
    Reply reply;
    try {
        reply = dispatch(msg["type"].get<std::string>(), msg);
    } catch (const std::exception& e) {
        reply = failure("internal", e.what());
    }
    if (std::exchange(mReplyDeferred, false) && reply.ok) return;
    if (!reply.ok) {
        mAfterReply = nullptr;
        return sendError(id, reply.code, reply.message);
    }
    mSender->send(toJsonText({{"id", id}, {"type", "reply"}, {"ok", true}, {"data", reply.data}}));
    // Stream events start after the reply, so a client always knows the job id first.
    if (mAfterReply) std::exchange(mAfterReply, nullptr)();
}

WsApi::Reply WsApi::dispatch(const std::string& type, const nlohmann::json& msg)
{
    if (type == "ping") return success();
    if (type == "model.open") return openModel(msg);
    if (type == "model.create") return createModel(msg);
    if (type == "model.save") return saveModel(msg);
    if (type == "simulate.start") return startSimulation(msg);
    if (type == "simulate.stop") return stopSimulation(msg);
    if (type == "log.subscribe") return subscribe(msg);
    if (!mSession.isOpen()) return failure("not_open", "open or create a model first (model.open)");
    return mSession.handle(msg);
}

WsApi::Reply WsApi::openModel(const nlohmann::json& msg)
{
    const auto model = readableModel(mServices, mUser, msg["model_id"].get<std::int64_t>());
    if (!model) return failure("not_found", "no such model");
    std::string error;
    if (!mSession.openHmf(mServices.models.hmf(model->id).value_or(""), model->name, error))
        return failure("invalid_model", error);
    mModelId = model->id;
    mModelName = model->name;
    nlohmann::json data = mSession.handle({{"type", "model.get"}}).data;
    data["model_id"] = model->id;
    data["writable"] = canWrite(mUser, model->ownerId, model->isExample);
    return success(data);
}

WsApi::Reply WsApi::createModel(const nlohmann::json& msg)
{
    const std::string name = msg["name"];
    if (const std::string problem = modelNameProblem(name); !problem.empty())
        return failure("bad_request", "model name: " + problem);
    mSession.createEmpty(name);
    mModelId = mServices.models.create(mUser.id, name, mSession.saveHmf(), false);
    mModelName = name;
    nlohmann::json data = mSession.handle({{"type", "model.get"}}).data;
    data["model_id"] = *mModelId;
    data["writable"] = true;
    return success(data);
}

WsApi::Reply WsApi::saveModel(const nlohmann::json& msg)
{
    if (!mSession.isOpen() || !mModelId) return failure("not_open", "open or create a model first");
    const auto model = mServices.models.summary(*mModelId);
    const bool asCopy = msg.value("as_copy", false) || !model ||
                        !canWrite(mUser, model->ownerId, model->isExample);
    const std::string name = msg.value("name", mModelName);
    if (const std::string problem = modelNameProblem(name); !problem.empty())
        return failure("bad_request", "model name: " + problem);
    if (asCopy) {
        mModelId = mServices.models.create(mUser.id, name, mSession.saveHmf(), false);
    } else {
        mServices.models.update(*mModelId, name, mSession.saveHmf());
    }
    mModelName = name;
    const auto saved = mServices.models.summary(*mModelId);
    return success({{"model_id", *mModelId}, {"name", name}, {"updated_at", saved ? saved->updatedAt : 0},
                    {"copied", asCopy}});
}

void WsApi::subscribeToJob(std::int64_t jobId, const nlohmann::json& msg)
{
    std::vector<std::string> variables;
    if (msg.contains("variables"))
        for (const auto& v : msg["variables"]) variables.push_back(v.get<std::string>());
    if (variables.size() > kMaxStreamedVariables) variables.resize(kMaxStreamedVariables);
    const double rate = msg.value("rate", 30.0);
    // The sink runs on the job's thread: it only queues, never waits. Frames stay numbers
    // until written, so the socket's queue can merge them (QueuedFrame).
    std::weak_ptr<WebSocketSender> weakSender = mSender;
    auto stream = std::make_shared<FrameStream>();
    stream->id = ++mStreams;
    if (msg.value("frames", std::string("json")) == "binary") stream->encoding = FrameEncoding::Binary;
    StreamSink sink;
    sink.event = [weakSender](nlohmann::json event) {
        if (auto sender = weakSender.lock()) sender->send(toJsonText(event));
    };
    sink.frame = [weakSender, stream](StreamFrame frame) {
        auto sender = weakSender.lock();
        // After event.resync the client reads the stored result: no more frames for it.
        if (!sender || stream->givenUp.load()) return;
        sender->sendFrame(std::make_unique<QueuedFrame>(std::move(frame), stream));
    };
    mSubscriptions.push_back(mServices.queue.subscribe(jobId, variables, rate, std::move(sink)));
}

WsApi::Reply WsApi::startSimulation(const nlohmann::json& msg)
{
    if (!mSession.isOpen()) return failure("not_open", "open or create a model first (model.open)");
    JobRequest request;
    request.ownerId = mUser.id;
    request.modelId = mModelId;
    request.hmf = mSession.saveHmf();
    if (msg.contains("start")) request.settings.start = msg["start"].get<double>();
    if (msg.contains("step")) request.settings.step = msg["step"].get<double>();
    if (msg.contains("stop")) request.settings.stop = msg["stop"].get<double>();
    if (msg.contains("log_samples")) request.settings.logSamples = msg["log_samples"].get<std::size_t>();
    // Compiling a large model takes a while: it happens on the request pool, and the reply
    // comes back through the connection's strand. Other messages are answered meanwhile.
    mReplyDeferred = true;
    mServices.pools.runRequest([weak = weak_from_this(), sender = mSender, &queue = mServices.queue,
                                request = std::move(request), id = echoableId(msg), msg] {
        JobQueue::Submitted submitted = queue.submit(request);
        sender->runOnConnection([weak, submitted = std::move(submitted), id, msg] {
            if (auto self = weak.lock()) self->finishStart(id, submitted, msg);
        });
    });
    return success();
}

void WsApi::finishStart(const nlohmann::json& id, const JobQueue::Submitted& submitted, const nlohmann::json& msg)
{
    if (mClosed) return;   // the job runs on; nobody is here to stream it to
    if (!submitted.id) return sendError(id, submitted.code, submitted.message);
    mSender->send(toJsonText({{"id", id}, {"type", "reply"}, {"ok", true}, {"data", {{"job_id", *submitted.id}}}}));
    subscribeToJob(*submitted.id, msg);
}

bool WsApi::ownsJob(std::int64_t jobId) const
{
    const auto job = mServices.queue.store().info(jobId);
    return job && canControlJob(mUser, job->ownerId);
}

WsApi::Reply WsApi::stopSimulation(const nlohmann::json& msg)
{
    const std::int64_t jobId = msg["job_id"];
    if (!ownsJob(jobId)) return failure("not_found", "no such job");
    // The reply never waits for the job: event.done (cancelled) follows once it has stopped.
    switch (mServices.queue.requestCancel(jobId)) {
    case JobQueue::CancelRequest::Cancelling:
        return success({{"state", "cancelling"}});
    case JobQueue::CancelRequest::Cancelled:
        return success({{"state", jobStateName(JobState::Cancelled)}});
    case JobQueue::CancelRequest::NotActive:
        break;
    }
    return success({{"state", jobStateName(mServices.queue.store().info(jobId)->state)}});
}

WsApi::Reply WsApi::subscribe(const nlohmann::json& msg)
{
    const std::int64_t jobId = msg["job_id"];
    if (!ownsJob(jobId)) return failure("not_found", "no such job");
    mAfterReply = [this, jobId, msg] { subscribeToJob(jobId, msg); };
    return success();
}

} // namespace tlmhub::server
