#pragma once
// The composition root of a running server: opens the storage, builds the services, the job
// queue and the routes, and answers the transport's requests.
#include "server/api/ApiSupport.h"
#include "server/app/FairTaskQueue.h"
#include "server/app/HandlerPools.h"
#include "server/app/ServerOptions.h"
#include "server/auth/DirectorySignIn.h"
#include "server/auth/lti/LtiTool.h"
#include "server/auth/oidc/OidcSignIn.h"
#include "server/cluster/JobStreams.h"
#include "server/cluster/NodeSecret.h"
#include "server/http/HttpApplication.h"
#include "server/http/StaticFiles.h"
#include "server/http/TrustedProxies.h"
#include "server/jobs/ResultExpiry.h"
#include "server/store/Storage.h"
#include "server/labs/LabService.h"
#include "server/live/LiveSessionRegistry.h"
#include "server/studies/StudyService.h"

#include <memory>

namespace tlmhub::server {

class TlmhubApp : public HttpApplication {
public:
    // Opens (or creates) the data directory and the storage; throws std::runtime_error (or
    // StoreError) naming the problem.
    explicit TlmhubApp(const ServerOptions& options);
    ~TlmhubApp() override;

    // First start: creates 'admin' (returns a generated password to print once, if any)
    // and seeds the example models.
    std::optional<std::string> bootstrap(std::string& log);
    void startJobs();
    // Stops running jobs (marked interrupted; a worker node puts them back in the queue) and
    // the workers.
    void shutdown();

    void handle(const Incoming& in, Reply reply) override;
    std::shared_ptr<WebSocketHandler> acceptWebSocket(const Incoming& in,
                                                      std::shared_ptr<WebSocketSender> sender,
                                                      Response& refusal) override;
    Storage& storage() { return *mStorage; }
    const QueueNode& queueNode() const { return mQueue->node(); }

private:
    struct Route {
        bool needsAuth;
        RouteWork work;
        RouteHandler handler;
    };
    // Authenticates where the route needs it, then runs it; errors become error responses.
    Response callRoute(const Route& route, Call& call);
    // The two halves of callRoute: false with the refusal when the call is not authenticated.
    bool authenticateCall(const Route& route, Call& call, Response& refused);
    Response callHandler(const Route& route, Call& call);
    // RouteWork::LargeReply and Checks: authenticated on the request pool, then the building
    // of the reply is scheduled for the caller, or refused (503 busy, 429 rate_limited).
    void replyScheduled(const Route& route, const Incoming& in, std::string address, RouteParams params, Reply reply);
    Response largeRepliesBusy() const;
    // Check runs take turns between users (mCheckRuns, within each user's caps); refused past
    // the user's waiting limit.
    Response checkRunsRefused() const;
    // Bearer header (a login token or an API token); or, where `queryToken` allows (the
    // WebSocket upgrade), ?token= (a login token only); or, on GET, a signed download link.
    std::optional<User> authenticate(const Request& request, const RouteParams& params,
                                     std::string& token, bool queryToken);
    // The user of a Bearer token, told apart by its form: API tokens have their prefix.
    std::optional<User> bearerUser(const std::string& token);

    ServerOptions mOptions;
    std::optional<NodeSecret> mNodeSecret;   // only with --node-secret-file
    std::unique_ptr<Storage> mStorage;
    std::unique_ptr<Accounts> mUsers;
    std::unique_ptr<TokenService> mTokens;
    std::unique_ptr<ApiTokens> mApiTokens;
    std::unique_ptr<LoginRateLimiter> mLoginLimiter;
    std::unique_ptr<LoginRateLimiter> mAddressLimiter;
    TrustedProxies mTrustedProxies;
    std::unique_ptr<StreamHub> mStreams;
    std::unique_ptr<JobQueue> mQueue;
    std::unique_ptr<JobStreams> mJobStreams;   // after the queue: its relays end first
    std::unique_ptr<StudyProgressHub> mStudyHub;
    std::unique_ptr<StudyService> mStudies;
    std::unique_ptr<LabService> mLabs;
    std::unique_ptr<LoginRateLimiter> mJoinLimiter;
    std::unique_ptr<LoginRateLimiter> mJoinAddressLimiter;
    std::unique_ptr<ResultExpiry> mExpiry;   // only with --result-ttl
    std::unique_ptr<LiveSessions> mLiveSessions;
    std::unique_ptr<DownloadLinks> mDownloadLinks;
    // Before the services (destroyed after them); its sessions end at shutdown().
    std::unique_ptr<LiveSessionRegistry> mLiveSimulations;
    std::unique_ptr<LdapDirectory> mDirectory;          // only with --ldap-url
    std::unique_ptr<DirectorySignIn> mDirectorySignIn;
    std::unique_ptr<OidcSignIn> mOidcSignIn;           // null without --oidc-issuer
    std::unique_ptr<LtiTool> mLtiTool;                 // null without --lti-key-file
    std::unique_ptr<Services> mServices;
    Router<Route> mRouter;
    StaticFiles mStaticFiles;
    // Last: destroyed first, so no handler runs on a store that is gone.
    std::unique_ptr<FairTaskQueue> mCheckRuns;   // lab check runs, users taking turns
    std::unique_ptr<HandlerPools> mPools;
};

} // namespace tlmhub::server
