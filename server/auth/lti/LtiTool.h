#pragma once
// tlmhub as an LTI 1.3 tool (docs/sign-in.md, "LTI 1.3"): a registered platform's
// third-party-initiated login is answered by sending the browser to the platform's
// authentication address with a new state and nonce (kept in SignInStore, as a provider
// sign-in's), and the platform's launch that comes back is taken once, in that browser only,
// and checked: the ID token against the platform's key set (IdTokenVerifier), then the LTI
// claims (LtiMessage). A valid launch signs the person in to the account linked to the
// platform's issuer and their `sub`, made on their first launch, and puts them in the class
// mapped to the launch's course with the class role their course roles give; a teacher's first
// launch from a course makes that class. The browser then goes to the app's launch page with a
// one-time hand-over key, as after a provider sign-in. A teacher's deep-linking launch leads to
// the app's page for placing one of the class's assignments in the course; the answer is signed
// with the tool's key and holds a link that opens the assignment and a line item for its
// scores. Hand-in scores and teachers' grades then go to that line item through the outbox
// (LtiScoreDelivery).
#include "server/app/ServerOptions.h"
#include "server/auth/LoginRateLimiter.h"
#include "server/auth/User.h"
#include "server/auth/lti/LtiScoreDelivery.h"
#include "server/auth/lti/ToolKeys.h"
#include "server/auth/oidc/ProviderHttp.h"
#include "server/auth/oidc/ProviderKeyCache.h"
#include "server/labs/LabService.h"
#include "server/store/LtiStore.h"
#include "server/store/SignInStore.h"
#include "server/store/UserStore.h"

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

namespace tlmhub::server {

// The parameters of a third-party-initiated login (LTI 1.3 Core §5.1.1.1).
struct LtiLoginRequest {
    std::string issuer, loginHint, targetLinkUri, messageHint, clientId, deploymentId;
};

struct LtiOutcome {
    std::optional<User> user;   // launched: signed in ...
    std::string location;       // ... and sent here (the app's page); login: the platform's address
    std::string browserKey;     // login: the value of the launch cookie
    // else why not: a stable code for the page and the details for the server's log
    std::string code, message;
};

class LtiTool {
public:
    // Reads the tool's keys (throws naming the file when it cannot).
    LtiTool(const ServerOptions& options, UserStore& users, SignInStore& signIns, LtiStore& platforms, LabService& labs);

    LtiOutcome login(const LtiLoginRequest& request, const std::string& clientAddress, std::int64_t nowUnix);
    // The platform's form post (id_token and state, or error) in the browser whose launch
    // cookie holds `browserKey`.
    LtiOutcome launch(const std::string& idToken, const std::string& state, const std::string& platformError,
                      const std::string& browserKey, std::int64_t nowUnix);

    // A teacher's deep-linking launch waiting under `key`, when `userId` made it.
    std::optional<LtiDeepLinkRequest> deepLinkOf(const std::string& key, std::int64_t userId, std::int64_t nowUnix);
    // The signed deep-linking answer placing `assignment` (of the request's class), once per
    // key; nullopt when the key was used or is too old.
    std::optional<std::string> placeAssignment(const LtiDeepLinkRequest& request, const AssignmentInfo& assignment,
                                               std::int64_t nowUnix);

    // A score of `userId` for the assignment, to every platform line item the assignment has at
    // a platform the person launched from. `timestampMs`: when it was given.
    void queueScore(std::int64_t assignmentId, std::int64_t userId, double scoreGiven, double scoreMaximum,
                    const std::string& comment, std::int64_t timestampMs);
    void startDelivery() { mDelivery.start(); }
    void stopDelivery() { mDelivery.stop(); }

    const ToolKeys& keys() const { return mKeys; }
    const std::string& publicUrl() const { return mPublicUrl; }
    std::string loginUrl() const { return mPublicUrl + "/api/v1/lti/login"; }
    std::string launchUrl() const { return mPublicUrl + "/api/v1/lti/launch"; }
    std::string keySetUrl() const { return mPublicUrl + "/api/v1/lti/jwks"; }
    // The origins of the registered platforms' addresses: who may frame the launch pages.
    std::string frameAncestors();

    static constexpr std::int64_t kLaunchSeconds = 600;   // from the login to the platform's launch
    static constexpr int kMaxLoginsPerAddress = 300;      // as a provider sign-in's starts
    static constexpr std::chrono::minutes kLoginWindow{10};

private:
    // The key cache of the platform, made anew when its key set's address changed.
    std::shared_ptr<ProviderKeyCache> keyCache(const LtiPlatform& platform);
    // The class of the launch's course, made on the teacher's first launch; 0 with `refusal`.
    std::int64_t courseClass(const LtiPlatform& platform, const struct LtiMessage& message, const User& user,
                             LtiOutcome& refusal);

    UserStore& mUsers;
    SignInStore& mSignIns;
    LtiStore& mPlatforms;
    LabService& mLabs;
    const std::string mPublicUrl;
    ToolKeys mKeys;
    ProviderHttp mHttp;
    LoginRateLimiter mLoginsPerAddress{kMaxLoginsPerAddress, kLoginWindow};
    LtiScoreDelivery mDelivery{mPlatforms, mKeys, mHttp};
    std::mutex mKeyCachesMutex;
    std::map<std::int64_t, std::pair<std::string, std::shared_ptr<ProviderKeyCache>>> mKeyCaches;
};

} // namespace tlmhub::server
