#include "server/app/TlmhubApp.h"

#include "server/api/WsApi.h"
#include "server/app/Bootstrap.h"
#include "server/auth/SecretFile.h"
#include "server/http/HttpSession.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <thread>

namespace tlmhub::server {

namespace {
const std::string kApiPrefix = "/api/v1";
// An open WebSocket whose login ended (expiry included) closes within this period.
constexpr auto kLoginCheckPeriod = std::chrono::milliseconds(250);
constexpr auto kDownloadLinkTtl = std::chrono::seconds(60);
// Logins and password changes waiting for a hashing thread; more are answered 503 at once.
constexpr std::size_t kHashingQueueLimit = 256;
// Wrong class join codes an account may try in the window (an address: ten times as many).
constexpr int kJoinMaxFailures = 10;
constexpr std::chrono::seconds kJoinWindow{600};
} // namespace

TlmhubApp::TlmhubApp(const ServerOptions& options)
    : mOptions(options), mStaticFiles(options.webRoot)
{
    std::error_code ec;
    std::filesystem::create_directories(mOptions.dataDir, ec);
    if (ec) throw std::runtime_error("cannot create data directory '" + mOptions.dataDir + "': " + ec.message());
    if (!mOptions.nodeSecretFile.empty()) mNodeSecret = NodeSecret::load(mOptions.nodeSecretFile);
    mStorage = openStorage(storageConfig(mOptions));
    mUsers = std::make_unique<Accounts>(mStorage->users());
    mTokens = std::make_unique<TokenService>(mStorage->sessions(), mStorage->users(), mOptions.tokenTtl);
    mApiTokens = std::make_unique<ApiTokens>(mStorage->apiTokens(), mStorage->users());
    mLoginLimiter = std::make_unique<LoginRateLimiter>(mOptions.loginMaxFailures, mOptions.loginWindow);
    mAddressLimiter = std::make_unique<LoginRateLimiter>(mOptions.addressMaxFailures, mOptions.addressWindow);
    for (const std::string& proxy : mOptions.trustedProxies)
        if (!mTrustedProxies.add(proxy)) throw std::runtime_error("--trusted-proxy: not an address or range: " + proxy);
    // A job still running in the store whose node crashed comes back when its lease expires.
    mStreams = std::make_unique<StreamHub>();
    unsigned workers = mOptions.workers ? mOptions.workers : std::max(1u, std::thread::hardware_concurrency());
    mQueue = std::make_unique<JobQueue>(mStorage->jobs(), mStorage->jobLeases(), mStorage->results(), *mStreams,
                                        mOptions.limits, workers, server::queueNode(mOptions, workers));
    mJobStreams = std::make_unique<JobStreams>(*mQueue, mNodeSecret);
    mStudyHub = std::make_unique<StudyProgressHub>();
    mStudies = std::make_unique<StudyService>(mStorage->studies(), mStorage->results(), *mQueue, *mStudyHub,
                                              mOptions.limits, mOptions.studyLimits, workers, mQueue->node());
    if (mOptions.resultTtl.count() > 0) mExpiry = std::make_unique<ResultExpiry>(mStorage->jobs(), mOptions.resultTtl);
    mLiveSessions = std::make_unique<LiveSessions>(
        [this](const std::string& token) { return bearerUser(token).has_value(); }, kLoginCheckPeriod);
    mDownloadLinks = std::make_unique<DownloadLinks>(kDownloadLinkTtl);
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    mPools = std::make_unique<HandlerPools>(std::max(2u, mOptions.ioThreads), std::max(1u, cores / 2),
                                            kHashingQueueLimit, std::max(2u, cores));
    mCheckRuns = std::make_unique<FairTaskQueue>(mOptions.checkThreads ? mOptions.checkThreads : cores,
                                                 mOptions.maxRunningChecksPerUser, mOptions.maxQueuedChecksPerUser);
    mLabs = std::make_unique<LabService>(mStorage->labs(), mStorage->models(), mStorage->jobs(), mStorage->results(),
                                         mOptions.limits);
    mJoinLimiter = std::make_unique<LoginRateLimiter>(kJoinMaxFailures, kJoinWindow);
    mJoinAddressLimiter = std::make_unique<LoginRateLimiter>(kJoinMaxFailures * 10, kJoinWindow);
    mLiveSimulations = std::make_unique<LiveSessionRegistry>(
        LiveSessionRegistry::Limits{mOptions.maxLiveSessionsPerUser, mOptions.maxLiveSessions, mOptions.liveIdleTimeout},
        std::max(1u, cores / 2));
    if (!mOptions.ldap.url.empty()) {
        LdapSettings ldap = mOptions.ldap;
        if (!mOptions.ldapServicePasswordFile.empty()) {
            ldap.servicePassword = readSecretFile(mOptions.ldapServicePasswordFile, "LDAP service password file");
            // An empty password would make the service account's bind an anonymous one.
            if (ldap.servicePassword.empty())
                throw std::runtime_error("LDAP service password file " + mOptions.ldapServicePasswordFile + " is empty");
        }
        mDirectory = std::make_unique<LdapDirectory>(std::move(ldap));
        mDirectorySignIn = std::make_unique<DirectorySignIn>(*mDirectory, mStorage->users(), mOptions.ldapCreateAccounts);
    }
    if (!mOptions.oidcProviders.empty())
        mOidcSignIn = std::make_unique<OidcSignIn>(mOptions, mStorage->users(), mStorage->signIns());
    if (!mOptions.ltiKeyFiles.empty())
        mLtiTool = std::make_unique<LtiTool>(mOptions, mStorage->users(), mStorage->signIns(), mStorage->lti(),
                                             *mLabs);
    mServices.reset(new Services{mOptions, *mUsers, mStorage->models(), *mTokens, *mApiTokens, *mLoginLimiter,
                                 *mAddressLimiter, *mQueue, *mStreams, *mStudies, *mLabs, *mJoinLimiter, *mJoinAddressLimiter,
                                 *mLiveSessions, *mDownloadLinks, *mPools, *mJobStreams,
                                 mStorage->idempotencyKeys(), *mLiveSimulations, mDirectorySignIn.get(), mOidcSignIn.get(),
                                 mLtiTool.get(), mStorage->signIns(), mStorage->lti()});

    for (RouteSpec& r : apiRoutes())
        mRouter.add(r.method, kApiPrefix + r.pattern, Route{r.needsAuth, r.work, std::move(r.handler)});
}

TlmhubApp::~TlmhubApp()
{
    shutdown();
}

std::optional<std::string> TlmhubApp::bootstrap(std::string& log)
{
    // A worker serves no one: the first administrator and the examples are the API nodes'.
    if (mOptions.role == "worker") return std::nullopt;
    const auto generated = ensureAdmin(*mUsers, std::getenv("TLMHUB_ADMIN_PASSWORD"));
    seedExamples(mStorage->models(), mStorage->meta(), *mUsers, mOptions.exampleDirs, log);
    for (const std::string& group : mUsers->namesDifferingOnlyInCase())
        log += "warning: user names differ only in case: " + group +
               " (they keep working; new names are unique regardless of case)\n";
    return generated;
}

void TlmhubApp::startJobs()
{
    mStudies->start();
    mQueue->start();
    if (mLtiTool) mLtiTool->startDelivery();
}

void TlmhubApp::shutdown()
{
    // Studies and jobs first: they stop promptly and record why, while a request that runs on
    // may outlast the grace after a signal (server/app/ShutdownSignals.h).
    if (mStudies) mStudies->stop();
    if (mQueue) mQueue->shutdown();
    if (mLiveSimulations) mLiveSimulations->stopAll();
    if (mLtiTool) mLtiTool->stopDelivery();
    if (mCheckRuns) mCheckRuns->stop();
    if (mPools) mPools->stop();
}

std::optional<User> TlmhubApp::bearerUser(const std::string& token)
{
    return ApiTokens::isApiToken(token) ? mApiTokens->authenticate(token) : mTokens->validate(token);
}

std::optional<User> TlmhubApp::authenticate(const Request& request, const RouteParams& params,
                                            std::string& token, bool queryToken)
{
    const std::string header(request[http::field::authorization]);
    const std::string bearer = "Bearer ";
    if (header.rfind(bearer, 0) == 0) {
        token = header.substr(bearer.size());
        return bearerUser(token);
    }
    // Login sessions only: an API token lives for months, and URLs end up in logs and
    // browser histories.
    if (queryToken) {
        const auto q = params.query.find("token");
        if (q == params.query.end()) return std::nullopt;
        token = q->second;
        return mTokens->validate(token);
    }
    if (request.method() == http::verb::get && params.query.count(DownloadLinks::kParameter)) {
        // Only while the login the link was made in lives (so not after its logout).
        const auto signer = mDownloadLinks->verify(std::string(request.target()));
        auto user = signer ? mTokens->validateSessionKey(signer->sessionKey) : std::nullopt;
        if (user && user->id == signer->userId) return user;
    }
    return std::nullopt;
}

void TlmhubApp::handle(const Incoming& in, Reply reply)
{
    const std::string target(in.request.target());
    if (mOptions.role == "worker" && parseRequestTarget(target).pathOnly != kApiPrefix + "/health")
        return reply(apiError(http::status::not_found, "not_found",
                              "this node is a worker (--role worker): it serves /api/v1/health only; "
                              "clients connect to an API node"));
    if (target.rfind(kApiPrefix + "/", 0) != 0 && target != kApiPrefix) {
        // Static files are read from disk: not on the I/O thread either.
        mPools->runRequest([this, &request = in.request, target, reply = std::move(reply)] {
            reply(mStaticFiles.serve(request, parseRequestTarget(target).pathOnly));
        });
        return;
    }
    const Route* route = nullptr;
    RouteParams params;
    switch (mRouter.find(in.request.method(), target, route, params)) {
    case Router<Route>::Match::None:
        return reply(apiError(http::status::not_found, "not_found", "no API route " + params.pathOnly));
    case Router<Route>::Match::WrongMethod:
        return reply(apiError(http::status::method_not_allowed, "bad_request",
                              std::string(in.request.method_string()) + " is not allowed on " + params.pathOnly));
    case Router<Route>::Match::Found:
        break;
    }
    std::vector<std::string_view> forwardedFor;
    if (!mTrustedProxies.empty())
        for (auto [field, end] = in.request.equal_range("X-Forwarded-For"); field != end; ++field)
            forwardedFor.push_back(field->value());
    std::string address = mTrustedProxies.clientAddress(in.clientAddress, forwardedFor);
    if (route->work == RouteWork::LargeReply || route->work == RouteWork::Checks)
        return replyScheduled(*route, in, std::move(address), std::move(params), std::move(reply));
    auto run = [this, &request = in.request, receivedAt = in.receivedAt, address = std::move(address),
                params = std::move(params), route, reply]() mutable {
        Call call{request, address, std::move(params), std::nullopt, {}, receivedAt};
        reply(callRoute(*route, call));
    };
    switch (route->work) {
    case RouteWork::Instant:
        return run();
    case RouteWork::Storage:
        return mPools->runRequest(std::move(run));
    case RouteWork::Checks:
    case RouteWork::LargeReply:
        return;   // replyScheduled, above
    case RouteWork::PasswordHash:
        if (!mPools->runHashing(std::move(run))) {
            Response busy = apiError(http::status::service_unavailable, "busy",
                                     "too many logins and password changes at once; try again in a moment");
            busy.set(http::field::retry_after, "1");
            reply(std::move(busy));
        }
        return;
    }
}

void TlmhubApp::replyScheduled(const Route& route, const Incoming& in, std::string address, RouteParams params,
                               Reply reply)
{
    mPools->runRequest([this, &route, &request = in.request, receivedAt = in.receivedAt, address = std::move(address),
                        params = std::move(params), reply = std::move(reply)]() mutable {
        Call call{request, address, std::move(params), std::nullopt, {}, receivedAt};
        Response refused;
        if (!authenticateCall(route, call, refused)) return reply(std::move(refused));
        const std::int64_t userId = call.user ? call.user->id : 0;
        // The call refers to this task's address: the scheduled work makes its own.
        auto build = [this, &route, &request, receivedAt, address, params = std::move(call.params),
                      user = call.user, token = std::move(call.token), reply](PerUserSlots::Slot slot) mutable {
            Call scheduled{request, address, std::move(params), std::move(user), std::move(token), receivedAt};
            Response response = callHandler(route, scheduled);
            slot.reset();
            reply(std::move(response));
        };
        if (route.work == RouteWork::LargeReply) {
            if (!mPools->runLargeReply(userId, std::move(build))) reply(largeRepliesBusy());
        } else if (!mCheckRuns->submit(userId, [build = std::move(build)]() mutable { build(nullptr); })) {
            reply(checkRunsRefused());
        }
    });
}

Response TlmhubApp::largeRepliesBusy() const
{
    Response busy = apiError(http::status::service_unavailable, "busy", mPools->largeRepliesBusyMessage());
    busy.set(http::field::retry_after, "1");
    return busy;
}

Response TlmhubApp::checkRunsRefused() const
{
    return refusal("rate_limited", "at most " + std::to_string(mOptions.maxQueuedChecksPerUser) +
                                       " check runs of one user wait at once (--max-queued-checks-per-user): "
                                       "try again when one has run");
}

bool TlmhubApp::authenticateCall(const Route& route, Call& call, Response& refused)
{
    if (!route.needsAuth) return true;
    try {
        call.user = authenticate(call.request, call.params, call.token, false);
    } catch (const StoreError& e) {
        refused = storeErrorResponse(e);
        return false;
    }
    if (call.user) return true;
    refused = apiError(http::status::unauthorized, "unauthorized", "log in first: send 'Authorization: Bearer <token>'");
    return false;
}

Response TlmhubApp::callHandler(const Route& route, Call& call)
{
    try {
        return route.handler(*mServices, call);
    } catch (const StoreError& e) {
        return storeErrorResponse(e);
    } catch (const std::exception& e) {
        return apiError(http::status::internal_server_error, "internal", e.what());
    }
}

Response TlmhubApp::callRoute(const Route& route, Call& call)
{
    Response refused;
    if (!authenticateCall(route, call, refused)) return refused;
    return callHandler(route, call);
}

std::shared_ptr<WebSocketHandler> TlmhubApp::acceptWebSocket(const Incoming& in,
                                                             std::shared_ptr<WebSocketSender> sender,
                                                             Response& refusal)
{
    const RouteParams params = parseRequestTarget(std::string(in.request.target()));
    if (params.pathOnly != kApiPrefix + "/ws") {
        refusal = errorResponse(http::status::not_found, "not_found", "WebSocket endpoint is " + kApiPrefix + "/ws");
        return nullptr;
    }
    // Another node of the deployment: it follows jobs for its own clients (WsApi's node
    // principal). Without a configured secret such a token is just an unknown token.
    const std::string header(in.request[http::field::authorization]);
    const std::string nodeBearer = "Bearer " + std::string(NodeSecret::kTokenPrefix);
    if (mNodeSecret && header.rfind(nodeBearer, 0) == 0) {
        if (mNodeSecret->matches(std::string_view(header).substr(7)))
            return std::make_shared<WsApi>(*mServices, WsApi::NodePrincipal{}, std::move(sender));
        refusal = errorResponse(http::status::unauthorized, "unauthorized", "wrong node secret");
        return nullptr;
    }
    if (mOptions.role == "worker") {
        refusal = errorResponse(http::status::not_found, "not_found",
                                "this node is a worker (--role worker): clients connect to an API node");
        return nullptr;
    }
    std::string token;
    const auto user = authenticate(in.request, params, token, true);
    if (!user) {
        refusal = errorResponse(http::status::unauthorized, "unauthorized",
                                "log in first: connect with ?token=<token> or 'Authorization: Bearer'");
        return nullptr;
    }
    return std::make_shared<WsApi>(*mServices, *user, token, std::move(sender));
}

} // namespace tlmhub::server
