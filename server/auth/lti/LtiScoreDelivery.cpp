#include "server/auth/lti/LtiScoreDelivery.h"

#include "server/auth/oidc/AuthorizationRequest.h"
#include "server/auth/oidc/JsonMembers.h"

#include <algorithm>
#include <ctime>
#include <iostream>

namespace tlmhub::server {

namespace {

constexpr const char* kScoreScope = "https://purl.imsglobal.org/spec/lti-ags/scope/score";

// 2026-12-07T19:53:35.123Z
std::string isoTimestamp(std::int64_t unixMs)
{
    const std::time_t seconds = static_cast<std::time_t>(unixMs / 1000);
    std::tm utc{};
    gmtime_r(&seconds, &utc);
    char date[32];
    std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%S", &utc);
    const int millis = static_cast<int>(unixMs % 1000);
    std::string text = date;
    text += {'.', static_cast<char>('0' + millis / 100), static_cast<char>('0' + millis / 10 % 10),
             static_cast<char>('0' + millis % 10), 'Z'};
    return text;
}

// A line item's scores address: "/scores" after its path, before its query (AGS §3.4).
std::string scoresUrl(const std::string& lineItem)
{
    const std::size_t query = lineItem.find('?');
    return query == std::string::npos ? lineItem + "/scores" : lineItem.substr(0, query) + "/scores" + lineItem.substr(query);
}

// What a platform's status means for a score: worth another attempt, or final.
bool worthRetrying(int status)
{
    return status == 0 || status == 401 || status == 408 || status == 429 || status >= 500;
}

} // namespace

LtiScoreDelivery::LtiScoreDelivery(LtiStore& outbox, const ToolKeys& keys, const ProviderHttp& http)
    : mOutbox(outbox), mKeys(keys), mHttp(http)
{
}

LtiScoreDelivery::~LtiScoreDelivery()
{
    stop();
}

void LtiScoreDelivery::start()
{
    mThread = std::thread([this] { run(); });
}

void LtiScoreDelivery::stop()
{
    {
        std::lock_guard lock(mMutex);
        mStopping = true;
    }
    mWake.notify_all();
    if (mThread.joinable()) mThread.join();
}

void LtiScoreDelivery::wake()
{
    {
        std::lock_guard lock(mMutex);
        mWoken = true;
    }
    mWake.notify_all();
}

std::int64_t LtiScoreDelivery::retryDelaySeconds(std::int64_t attempts)
{
    return std::min<std::int64_t>(3600, std::int64_t{10} << std::clamp<std::int64_t>(attempts - 1, 0, 12));
}

void LtiScoreDelivery::run()
{
    for (;;) {
        {
            std::unique_lock lock(mMutex);
            mWake.wait_for(lock, kPoll, [&] { return mWoken || mStopping; });
            if (mStopping) return;
            mWoken = false;
        }
        try {
            deliverDue(std::time(nullptr));
        } catch (const std::exception& e) {
            // The database away for a moment: the next poll tries again.
            std::cerr << "LTI score delivery: " << e.what() << std::endl;
        }
    }
}

int LtiScoreDelivery::deliverDue(std::int64_t nowUnix)
{
    int delivered = 0;
    for (;;) {
        const auto scores = mOutbox.claimScores(nowUnix, kLeaseSeconds, kClaimed);
        if (scores.empty()) return delivered;
        for (const LtiScore& score : scores) {
            std::string error;
            bool retry = false;
            if (send(score, error, retry)) {
                mOutbox.markDelivered(score.id, score.lease, std::time(nullptr));
                ++delivered;
            } else {
                const bool giveUp = !retry || score.attempts >= kMaxAttempts;
                mOutbox.markFailed(score.id, score.lease, error.substr(0, 500),
                                   std::time(nullptr) + retryDelaySeconds(score.attempts), giveUp);
            }
        }
    }
}

std::string LtiScoreDelivery::accessToken(const LtiPlatform& platform, std::string& error, bool& retry)
{
    {
        std::lock_guard lock(mTokensMutex);
        const auto it = mTokens.find(platform.id);
        if (it != mTokens.end() && std::chrono::steady_clock::now() < it->second.expiresAt) return it->second.value;
    }
    const std::int64_t now = std::time(nullptr);
    const nlohmann::json assertion = {{"iss", platform.clientId}, {"sub", platform.clientId}, {"aud", platform.tokenUrl},
                                      {"iat", now},               {"exp", now + 300},         {"jti", newSignInSecrets().state}};
    const std::string form = formEncode({{"grant_type", "client_credentials"},
                                         {"client_assertion_type", "urn:ietf:params:oauth:client-assertion-type:jwt-bearer"},
                                         {"client_assertion", mKeys.sign(assertion)},
                                         {"scope", kScoreScope}});
    const auto reply = mHttp.postForm(platform.tokenUrl, form, {}, error);
    if (!reply || reply->status != 200) {
        if (reply) error = "the platform's token endpoint answered " + std::to_string(reply->status) + " " +
                           stringMember(reply->body, "error");
        retry = !reply || worthRetrying(reply->status);
        return {};
    }
    const std::string token = stringMember(reply->body, "access_token");
    if (token.empty()) {
        error = "the platform's token endpoint gave no access token";
        return {};
    }
    const auto lifetime = reply->body.contains("expires_in") && reply->body["expires_in"].is_number_integer()
        ? reply->body["expires_in"].get<std::int64_t>()
        : 3600;
    std::lock_guard lock(mTokensMutex);
    // Renewed a minute early, so a token never runs out between its check and its use.
    mTokens[platform.id] = {token, std::chrono::steady_clock::now() + std::chrono::seconds(std::max<std::int64_t>(0, lifetime - 60))};
    return token;
}

bool LtiScoreDelivery::send(const LtiScore& score, std::string& error, bool& retry)
{
    const auto platform = mOutbox.platform(score.platformId);
    if (!platform) {
        error = "the platform was removed";
        return false;
    }
    const std::string token = accessToken(*platform, error, retry);
    if (token.empty()) return false;
    nlohmann::json body = {{"userId", score.userSubject},      {"scoreGiven", score.scoreGiven},
                           {"scoreMaximum", score.scoreMaximum}, {"activityProgress", "Completed"},
                           {"gradingProgress", "FullyGraded"}, {"timestamp", isoTimestamp(score.timestampMs)}};
    if (!score.comment.empty()) body["comment"] = score.comment;
    const auto reply = mHttp.post(scoresUrl(score.lineItemUrl), "application/vnd.ims.lis.v1.score+json", body.dump(),
                                  {{"Authorization", "Bearer " + token}}, error);
    if (reply && reply->status >= 200 && reply->status < 300) return true;
    if (reply) {
        error = "the platform answered " + std::to_string(reply->status);
        if (reply->status == 409) error += ": it holds a newer score";
        if (reply->status == 401) {   // the token was revoked or ran out early: a new one next time
            std::lock_guard lock(mTokensMutex);
            mTokens.erase(platform->id);
        }
    }
    retry = !reply || worthRetrying(reply->status);
    return false;
}

} // namespace tlmhub::server
