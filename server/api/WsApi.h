#pragma once
// The WebSocket side of the protocol (tlmhub.v1) for one connection: checks each message
// against the schema, edits the connection's open model through an EditSession, runs it as
// a job and streams the job's events back.
#include "server/api/ApiSupport.h"
#include "server/edit/EditSession.h"
#include "server/http/HttpApplication.h"
#include "server/jobs/StreamFrame.h"
#include "server/live/LiveSession.h"
#include "server/protocol/Messages.generated.h"

#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>

namespace tlmhub::server {

class WsApi : public WebSocketHandler, public std::enable_shared_from_this<WsApi> {
public:
    // `token`: the login the connection was opened with; the connection ends with it.
    WsApi(Services& services, User user, const std::string& token, std::shared_ptr<WebSocketSender> sender);
    // Another node of the deployment (TlmhubApp checked its secret): it relays jobs to its own
    // clients, so it may log.subscribe to any job and send nothing else. It is no user's login:
    // no hello, and no live session (its token is no user's, so the login check would close it).
    struct NodePrincipal {};
    WsApi(Services& services, NodePrincipal, std::shared_ptr<WebSocketSender> sender);
    ~WsApi() override;

    void onMessage(const std::string& text) override;
    void onClose() override;

    using Reply = EditSession::Result;

private:
    // A client may send this many messages while a request runs on the request pool.
    static constexpr std::size_t kMaxWaitingMessages = 256;

    void handle(const std::string& text);
    Reply dispatch(const std::string& type, const nlohmann::json& msg);
    Reply dispatchSafely(const std::string& type, const nlohmann::json& msg);
    // The reply or error message for `reply` (no state touched: any thread).
    static std::string answerText(const nlohmann::json& id, Reply reply);
    // Sends an answer; after a reply, runs what was to follow it (mAfterReply).
    void sendAnswer(bool ok, std::string text);
    Reply openModel(const protocol::ModelOpenRequest& request);
    Reply createModel(const protocol::ModelCreateRequest& request);
    Reply saveModel(const protocol::ModelSaveRequest& request);
    Reply startSimulation(const protocol::SimulateStartRequest& start);
    Reply stopSimulation(const protocol::SimulateStopRequest& request);
    Reply subscribe(const protocol::LogSubscribeRequest& request);
    Reply subscribeStudy(const protocol::StudySubscribeRequest& request);
    Reply unsubscribeStudy(const protocol::StudyUnsubscribeRequest& request);
    // Live sessions (docs/live-sessions.md): started on this node, streamed to this connection.
    Reply startLive(const protocol::LiveStartRequest& request);
    // live.set, live.pause, ...: the session if this user owns it, else null.
    std::shared_ptr<LiveSession> ownLiveSession(std::int64_t sessionId);
    // live.record: the session's samples and changes so far, stored as a finished job.
    Reply recordLive(const std::shared_ptr<LiveSession>& session);
    // The session this user may watch: their own (`throughClass` 0), or one shared with a class
    // they are in (`throughClass` that class); else null.
    std::shared_ptr<LiveSession> watchableLiveSession(std::int64_t sessionId, std::int64_t& throughClass);
    // live.subscribe: frames and state events of a watchable session (read-only).
    Reply watchLive(const protocol::LiveSubscribeRequest& request);
    // live.model: the model a watchable session runs, for drawing it.
    Reply liveModel(const protocol::LiveModelRequest& request);
    // live.share, live.unshare: the owner's session with a class they teach.
    Reply shareLive(const std::shared_ptr<LiveSession>& session, std::int64_t classId, bool shared);
    // Where a live session's frames and events for this connection go.
    LiveSessionSink liveSink(const std::optional<std::string>& frames);
    // `variables`: at most max_stream_variables are streamed; `rate` in frames per second.
    void subscribeToJob(std::int64_t jobId, std::vector<std::string> variables, double rate, FrameEncoding encoding);
    // On the strand, once a simulate.start's job is compiled and queued (or refused).
    void finishStart(const protocol::SimulateStartRequest& start, const JobQueue::Submitted& submitted);
    bool ownsJob(std::int64_t jobId) const;
    // "" when the open model may take this edit; else why not (a student's copy of a locked
    // assignment, or a copy whose class the student has left).
    std::string copyEditProblem(const std::string& type, const nlohmann::json& msg);
    void sendError(const nlohmann::json& id, const std::string& code, const std::string& message);

    Services& mServices;
    User mUser;
    std::shared_ptr<WebSocketSender> mSender;
    std::uint64_t mLiveSession = 0;   // 0: none (a node)
    bool mNode = false;
    EditSession mSession;
    std::optional<std::int64_t> mModelId;
    std::string mModelName;
    bool mModelIsCopy = false;   // the open model is a student's copy of an assignment
    std::vector<std::uint64_t> mSubscriptions;
    std::map<std::int64_t, std::uint64_t> mStudySubscriptions;   // study -> StudyProgressHub's
    // Started here; they end with the connection. Guarded: live.start adds on the request
    // pool while the connection may be closing.
    std::mutex mLiveRunsMutex;
    std::vector<std::weak_ptr<LiveSession>> mLiveRuns;
    std::vector<std::pair<std::weak_ptr<LiveSession>, std::uint64_t>> mLiveWatches;   // live.subscribe
    bool mLiveRunsClosed = false;
    std::uint64_t mStreams = 0;   // frame streams opened on this connection (QueuedFrame ids)
    std::function<void()> mAfterReply;
    bool mReplyDeferred = false;   // the message being handled is answered later
    // A request runs on the request pool: later messages wait in mWaiting (the pool thread
    // owns the session's state meanwhile).
    bool mBusy = false;
    std::deque<std::string> mWaiting;
    bool mClosed = false;
};

} // namespace tlmhub::server
