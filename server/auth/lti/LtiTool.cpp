#include "server/auth/lti/LtiTool.h"

#include "server/auth/DirectorySignIn.h"
#include "server/auth/SignInHandOver.h"
#include "server/auth/lti/LtiMessage.h"
#include "server/auth/oidc/AuthorizationRequest.h"
#include "server/auth/oidc/IdTokenVerifier.h"
#include "server/store/ModelName.h"

#include <openssl/crypto.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <set>

namespace tlmhub::server {

namespace {

constexpr const char* kLtiProviderPrefix = "lti:";   // SignInStore's provider of a launch: lti:<platform id>

LtiOutcome ltiRefused(std::string code, std::string message)
{
    return {std::nullopt, {}, {}, std::move(code), std::move(message)};
}

// https://host[:port] of an address; "" when it has none or has characters a policy's source
// may not (a ';' or ',' in it would add directives of its own).
std::string httpsOriginOf(const std::string& url)
{
    if (!url.starts_with("https://")) return {};
    const std::string origin = url.substr(0, url.find_first_of("/?#", 8));
    const bool plain = origin.size() > 8 && std::all_of(origin.begin() + 8, origin.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == ':';
    });
    return plain ? origin : std::string{};
}

std::optional<std::int64_t> assignmentIdOf(const std::string& text)
{
    std::int64_t id = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), id);
    if (error != std::errc{} || end != text.data() + text.size() || id <= 0) return std::nullopt;
    return id;
}

// What the class of a course is called: its title when that is a fine name, else a plain one.
std::string className(const LtiPlatform& platform, const std::string& title)
{
    if (!title.empty() && modelNameProblem(title).empty() && title.size() <= 100) return title;
    return "Course at " + platform.name;
}

} // namespace

LtiTool::LtiTool(const ServerOptions& options, UserStore& users, SignInStore& signIns, LtiStore& platforms,
                 LabService& labs)
    : mUsers(users), mSignIns(signIns), mPlatforms(platforms), mLabs(labs), mPublicUrl(options.publicUrl),
      mKeys(options.ltiKeyFiles), mHttp(options.ltiCaFile)
{
}

LtiOutcome LtiTool::login(const LtiLoginRequest& request, const std::string& clientAddress, std::int64_t nowUnix)
{
    if (request.issuer.empty() || request.loginHint.empty() || request.targetLinkUri.empty())
        return ltiRefused("bad_login", "the login lacks iss, login_hint or target_link_uri");
    // The target is checked again in the launch; refusing here sends no one on to the platform.
    if (!request.targetLinkUri.starts_with(mPublicUrl + "/"))
        return ltiRefused("wrong_target", "the login's target link is not on this server");
    std::optional<LtiPlatform> platform;
    for (LtiPlatform& candidate : mPlatforms.platformsOf(request.issuer))
        if (request.clientId.empty() || candidate.clientId == request.clientId) {
            if (platform) return ltiRefused("unknown_platform", "several registrations of " + request.issuer +
                                                                     " and the login names no client_id");
            platform = std::move(candidate);
        }
    if (!platform) return ltiRefused("unknown_platform", "no platform is registered with that issuer and client id");
    if (!request.deploymentId.empty() &&
        std::find(platform->deploymentIds.begin(), platform->deploymentIds.end(), request.deploymentId) ==
            platform->deploymentIds.end())
        return ltiRefused("unknown_deployment", "the login's deployment is not registered for the platform");
    if (!mLoginsPerAddress.allowed(clientAddress))
        return ltiRefused("busy", "too many launches started from " + clientAddress);
    mLoginsPerAddress.recordFailure(clientAddress);   // counts the login
    if (mSignIns.purge(nowUnix - kLaunchSeconds) >= 10'000)
        return ltiRefused("busy", "10,000 sign-ins are under way");

    const SignInSecrets secrets = newSignInSecrets();
    const std::string browserKey = newSignInSecrets().state;
    mSignIns.add({secrets.state, kLtiProviderPrefix + std::to_string(platform->id), secrets.nonce, "", browserKey,
                  nowUnix, 0});
    std::vector<std::pair<std::string, std::string>> fields{
        {"scope", "openid"},          {"response_type", "id_token"}, {"response_mode", "form_post"},
        {"prompt", "none"},           {"client_id", platform->clientId}, {"redirect_uri", launchUrl()},
        {"login_hint", request.loginHint}, {"state", secrets.state},     {"nonce", secrets.nonce}};
    if (!request.messageHint.empty()) fields.emplace_back("lti_message_hint", request.messageHint);
    const char separator = platform->authUrl.find('?') == std::string::npos ? '?' : '&';
    return {std::nullopt, platform->authUrl + separator + formEncode(fields), browserKey, {}, {}};
}

LtiOutcome LtiTool::launch(const std::string& idToken, const std::string& state, const std::string& platformError,
                           const std::string& browserKey, std::int64_t nowUnix)
{
    // Taken whatever comes next: a launch is used once, and its nonce with it.
    const auto attempt = state.empty() ? std::nullopt : mSignIns.take(state, nowUnix - kLaunchSeconds);
    if (!attempt || !attempt->provider.starts_with(kLtiProviderPrefix))
        return ltiRefused("launch_expired", "this launch has expired or was used already; launch again");
    // Another browser's launch: someone else's launch pushed into this browser (login CSRF).
    if (browserKey.size() != attempt->browserKey.size() ||
        CRYPTO_memcmp(browserKey.data(), attempt->browserKey.data(), browserKey.size()) != 0)
        return ltiRefused("wrong_browser", "the launch came to another browser than its login, or the browser "
                                           "blocks this server's cookie in the platform's frame");
    if (!platformError.empty())
        return ltiRefused("platform_refused", "the platform answered " + platformError.substr(0, 60));
    const auto platformId = std::stoll(attempt->provider.substr(std::string(kLtiProviderPrefix).size()));
    const auto platform = mPlatforms.platform(platformId);
    if (!platform) return ltiRefused("unknown_platform", "the launch's platform was removed");

    IdTokenExpectations expected;
    expected.issuer = platform->issuer;
    expected.clientId = platform->clientId;
    expected.nonce = attempt->nonce;
    expected.now = nowUnix;
    const auto verified = verifyIdToken(idToken, *keyCache(*platform), expected);
    if (const auto* refused = std::get_if<IdTokenError>(&verified)) return ltiRefused(refused->code, refused->message);
    const IdToken& token = std::get<IdToken>(verified);
    const auto read = readLtiMessage(token.claims, token.subject, platform->deploymentIds, mPublicUrl);
    if (const auto* refused = std::get_if<LtiMessageError>(&read)) return ltiRefused(refused->code, refused->message);
    const LtiMessage& message = std::get<LtiMessage>(read);

    const User user = mUsers.insertLinked("lti " + platform->issuer, token.subject, accountNameFor(message.name), kRoleUser);
    if (user.disabled) return ltiRefused("account_disabled", "the account is disabled");
    // Signed in: the app's launch page with a hand-over key, and where the app goes on to.
    const auto signedIn = [&](const std::string& next) {
        return LtiOutcome{user, mPublicUrl + "/api/v1/lti/app#/signed-in/" + handOverSignIn(mSignIns, user.id, nowUnix) + next,
                          {}, {}, {}};
    };
    if (message.contextId.empty() && message.messageType == kLtiResourceLinkRequest) return signedIn("");
    if (message.messageType == kLtiDeepLinkingRequest && message.classRole != kClassTeacher)
        return ltiRefused("not_instructor", "only the course's teachers place tlmhub's assignments in it");
    if (message.contextId.empty())
        return ltiRefused("no_course", "a deep-linking launch outside a course has no class to place from");
    LtiOutcome refusal;
    const std::int64_t classId = courseClass(*platform, message, user, refusal);
    if (classId == 0) return refusal;
    if (message.messageType == kLtiDeepLinkingRequest) {
        const LtiDeepLinkRequest request{newSignInSecrets().state, platform->id, message.deploymentId,
                                         message.deepLinkReturnUrl, message.deepLinkData, classId, user.id, nowUnix};
        mPlatforms.addDeepLink(request, nowUnix - kLaunchSeconds);
        return signedIn("/place/" + request.key);
    }
    // A link placed by deep linking names its assignment; its line item takes the scores.
    const auto assignmentId = message.custom.contains("assignment")
        ? assignmentIdOf(message.custom["assignment"].get<std::string>())
        : std::nullopt;
    const auto assignment = assignmentId ? mLabs.store().assignment(*assignmentId) : std::nullopt;
    if (!assignment || assignment->classId != classId) return signedIn("/class/" + std::to_string(classId));
    if (!message.lineItem.empty()) mPlatforms.setLineItem(platform->id, message.lineItem, assignment->id);
    return signedIn("/assignment/" + std::to_string(assignment->id));
}

std::optional<LtiDeepLinkRequest> LtiTool::deepLinkOf(const std::string& key, std::int64_t userId, std::int64_t nowUnix)
{
    auto request = key.empty() ? std::nullopt : mPlatforms.deepLink(key, nowUnix - kLaunchSeconds, false);
    if (!request || request->userId != userId) return std::nullopt;
    return request;
}

std::optional<std::string> LtiTool::placeAssignment(const LtiDeepLinkRequest& request, const AssignmentInfo& assignment,
                                                    std::int64_t nowUnix)
{
    const auto platform = mPlatforms.platform(request.platformId);
    if (!platform || !mPlatforms.deepLink(request.key, nowUnix - kLaunchSeconds, true)) return std::nullopt;
    const std::string id = std::to_string(assignment.id);
    // The platform scales scores to its line item's maximum, so 100 suits every assignment.
    const nlohmann::json link = {{"type", "ltiResourceLink"},
                                 {"title", assignment.title},
                                 {"url", launchUrl()},
                                 {"custom", {{"assignment", id}}},
                                 {"lineItem", {{"scoreMaximum", 100}, {"label", assignment.title}, {"resourceId", "assignment-" + id}}}};
    nlohmann::json claims = {{"iss", platform->clientId},
                             {"aud", platform->issuer},
                             {"iat", nowUnix},
                             {"exp", nowUnix + 300},
                             {"nonce", newSignInSecrets().nonce},
                             {"https://purl.imsglobal.org/spec/lti/claim/deployment_id", request.deploymentId},
                             {"https://purl.imsglobal.org/spec/lti/claim/message_type", "LtiDeepLinkingResponse"},
                             {"https://purl.imsglobal.org/spec/lti/claim/version", "1.3.0"},
                             {"https://purl.imsglobal.org/spec/lti-dl/claim/content_items", nlohmann::json::array({link})}};
    if (!request.data.empty()) claims["https://purl.imsglobal.org/spec/lti-dl/claim/data"] = request.data;
    return mKeys.sign(claims);
}

void LtiTool::queueScore(std::int64_t assignmentId, std::int64_t userId, double scoreGiven, double scoreMaximum,
                         const std::string& comment, std::int64_t timestampMs)
{
    if (scoreMaximum <= 0) return;   // an assignment without points: nothing a grade book can show
    const auto targets = mPlatforms.scoreTargets(assignmentId, userId);
    for (const LtiScoreTarget& target : targets) {
        LtiScore score;
        score.platformId = target.platformId;
        score.lineItemUrl = target.lineItemUrl;
        score.userSubject = target.userSubject;
        score.userId = userId;
        score.assignmentId = assignmentId;
        score.scoreGiven = scoreGiven;
        score.scoreMaximum = scoreMaximum;
        score.comment = comment;
        score.timestampMs = timestampMs;
        mPlatforms.addScore(score);
    }
    if (!targets.empty()) mDelivery.wake();
}

std::int64_t LtiTool::courseClass(const LtiPlatform& platform, const LtiMessage& message, const User& user,
                                  LtiOutcome& refusal)
{
    auto classId = mPlatforms.classOfContext(platform.id, message.contextId);
    if (!classId) {
        if (message.classRole != kClassTeacher) {
            refusal = ltiRefused("course_not_ready", "the course's teacher has not launched tlmhub from it yet");
            return 0;
        }
        const auto made = mLabs.createClass(user, className(platform, message.contextTitle));
        if (!made) {
            refusal = ltiRefused("internal", "cannot make the course's class");
            return 0;
        }
        classId = mPlatforms.linkContext(platform.id, message.contextId, *made);
        if (*classId != *made) mLabs.store().removeClass(*made);   // another first launch won
    }
    if (message.classRole.empty()) {
        refusal = ltiRefused("no_course_role", "the launch gives no role in the course this tool knows");
        return 0;
    }
    mLabs.store().setMember(*classId, user.id, message.classRole);
    return *classId;
}

std::shared_ptr<ProviderKeyCache> LtiTool::keyCache(const LtiPlatform& platform)
{
    std::lock_guard lock(mKeyCachesMutex);
    auto& [url, cache] = mKeyCaches[platform.id];
    if (!cache || url != platform.jwksUrl) {
        url = platform.jwksUrl;
        cache = std::make_shared<ProviderKeyCache>(
            [this, keysUrl = platform.jwksUrl](std::string& error) { return mHttp.getKeySet(keysUrl, error); });
    }
    return cache;
}

std::string LtiTool::frameAncestors()
{
    std::set<std::string> origins;
    for (const LtiPlatform& platform : mPlatforms.listPlatforms())
        for (const std::string* url : {&platform.issuer, &platform.authUrl})
            if (const std::string origin = httpsOriginOf(*url); !origin.empty()) origins.insert(origin);
    std::string sources = "'self'";
    for (const std::string& origin : origins) sources += " " + origin;
    return sources;
}

} // namespace tlmhub::server
