#pragma once
// What every REST route handler works with: the services, the authenticated call, and
// helpers for JSON bodies and the protocol's error shape.
#include "server/auth/Accounts.h"
#include "server/auth/ApiTokens.h"
#include "server/auth/DownloadLinks.h"
#include "server/auth/LiveSessions.h"
#include "server/auth/LoginRateLimiter.h"
#include "server/auth/TokenService.h"
#include "server/http/HttpTypes.h"
#include "server/http/Router.h"
#include "server/jobs/JobQueue.h"
#include "server/jobs/StreamHub.h"
#include "server/protocol/Messages.generated.h"
#include "server/store/IdempotencyKeyStore.h"
#include "server/store/ModelStore.h"
#include "server/store/StoreError.h"

#include <chrono>
#include <nlohmann/json.hpp>

#include <functional>
#include <optional>
#include <vector>

namespace tlmhub::server {

struct ServerOptions;
class HandlerPools;
class JobStreams;
class StudyService;
class LabService;
class LiveSessionRegistry;
class DirectorySignIn;
class OidcSignIn;
class LtiTool;
class SignInStore;
class LtiStore;

// The long-lived objects of a running server (owned by TlmhubApp).
struct Services {
    const ServerOptions& options;
    Accounts& users;
    ModelStore& models;
    TokenService& tokens;
    ApiTokens& apiTokens;               // personal tokens for scripts
    LoginRateLimiter& loginLimiter;     // failures per user name
    LoginRateLimiter& addressLimiter;   // failures per client address (looser: a lab shares one)
    JobQueue& queue;
    StreamHub& streams;
    StudyService& studies;
    LabService& labs;                   // classes, assignments, copies, hand-ins
    LoginRateLimiter& joinLimiter;          // wrong class join codes per account
    LoginRateLimiter& joinAddressLimiter;   // and per client address (looser: a lab shares one)
    LiveSessions& liveSessions;         // open WebSockets, ended with their login
    const DownloadLinks& downloadLinks;
    HandlerPools& pools;                // where slow work goes instead of an I/O thread
    JobStreams& jobStreams;             // log.subscribe: the local hub, or relays from other nodes
    IdempotencyKeyStore& idempotencyKeys;   // Idempotency-Key of POST /jobs and /studies
    LiveSessionRegistry& liveSimulations;   // live.start: models run with the wall clock on this node
    DirectorySignIn* directory;             // LDAP sign-in; null without --ldap-url
    OidcSignIn* oidc;                       // OpenID Connect sign-in; null without --oidc-issuer
    LtiTool* lti;                           // LTI 1.3 launches; null without --lti-key-file
    SignInStore& signIns;                   // sign-ins under way and hand-overs to the app
    LtiStore& ltiPlatforms;                 // the registered learning platforms
};

struct Call {
    const Request& request;
    const std::string& clientAddress;
    RouteParams params;
    std::optional<User> user;   // set on every route that needs authentication
    std::string token;          // the bearer token it was authenticated with (login or API)
    std::chrono::system_clock::time_point receivedAt{};   // the request read whole
    const User& who() const { return *user; }
};

using RouteHandler = std::function<Response(Services&, Call&)>;

// Where a route's handler runs. Instant: on the I/O thread (no storage, microseconds: a
// health probe must answer while everything else is busy). Storage: on the request pool.
// PasswordHash: on the bounded hashing pool (an argon2id hash or check per call). Checks: on
// the pool that runs a lab's models (a pretest, a hand-in, a teacher's reference run).
// LargeReply: a reply that may take megabytes and a second to build (a model's JSON, a run's
// results, an FMU): authenticated on the request pool, then built on a pool of its own, at
// most two at a time per user (more answer 503 busy with Retry-After).
enum class RouteWork { Storage, Instant, PasswordHash, Checks, LargeReply };

struct RouteSpec {
    http::verb method;
    std::string pattern;   // below /api/v1
    bool needsAuth;
    RouteHandler handler;
    RouteWork work = RouteWork::Storage;
};

Response jsonResponse(http::status status, const nlohmann::json& body);
Response textResponse(http::status status, std::string body, const std::string& contentType);
Response noContent();
Response apiError(http::status status, const std::string& code, const std::string& message);
// The protocol's error code for a failure of the database: storage_full (disk full), busy
// (unreachable or contended: try again), internal (the rest).
const char* storeErrorCode(const StoreError& e);
// The HTTP status of a refused job, study or check run (SECURITY.md, "Status codes"): 422
// limit_exceeded (can never succeed as sent), 429 rate_limited (try later), 404 not_found,
// 403 locked, else 400.
http::status submitErrorStatus(const std::string& code);
// apiError with submitErrorStatus, and Retry-After on a 429.
Response refusal(const std::string& code, const std::string& message);
// 507 storage_full, 503 busy (with Retry-After) or 500 internal.
Response storeErrorResponse(const StoreError& e);

// Parses the body as JSON and checks it against the protocol definition `definition`
// (empty: no schema check). On failure returns false with the error response in `error`.
bool readJsonBody(const Call& call, const std::string& definition, nlohmann::json& body,
                  Response& error);
// Same, decoded into the definition's generated struct (e.g. protocol::LoginRequest).
template <typename Body>
bool readBody(const Call& call, const std::string& definition, Body& body, Response& error)
{
    nlohmann::json json;
    if (!readJsonBody(call, definition, json, error)) return false;
    body = json.get<Body>();
    return true;
}
std::optional<std::int64_t> parseId(const std::string& text);
// "a,b,,c" -> {a, b, c} (a query's list, e.g. variables=).
std::vector<std::string> commaSeparated(const std::string& text);
bool isXmlRequest(const Request& request);
bool wantsXml(const Call& call);

// Route tables, one per resource.
void addAuthRoutes(std::vector<RouteSpec>& routes);
void addOidcRoutes(std::vector<RouteSpec>& routes);
void addLtiRoutes(std::vector<RouteSpec>& routes);
void addUserRoutes(std::vector<RouteSpec>& routes);
void addModelRoutes(std::vector<RouteSpec>& routes);
void addFmuRoutes(std::vector<RouteSpec>& routes);
void addJobRoutes(std::vector<RouteSpec>& routes);
void addTokenRoutes(std::vector<RouteSpec>& routes);
void addCatalogueRoutes(std::vector<RouteSpec>& routes);
void addStudyRoutes(std::vector<RouteSpec>& routes);
void addClassRoutes(std::vector<RouteSpec>& routes);
void addAssignmentRoutes(std::vector<RouteSpec>& routes);
void addHandInRoutes(std::vector<RouteSpec>& routes);
void addPreferenceRoutes(std::vector<RouteSpec>& routes);
// Every route of the API (below /api/v1), in matching order.
std::vector<RouteSpec> apiRoutes();

// Summaries as the API shows them.
protocol::User publicUser(const User& user);
nlohmann::json modelSummaryJson(const ModelSummary& summary);
// A model the caller may read, or nullopt (also when it does not exist: 404 either way).
// A student's copy of an assignment follows the lab's rules (LabAccess).
std::optional<ModelSummary> readableModel(Services& s, const User& who, std::int64_t id);
// Whether the caller may change the model (a copy: its student, within the assignment's lock).
bool writableModel(Services& s, const User& who, const ModelSummary& model);

} // namespace tlmhub::server
