#pragma once
// The learning platforms tlmhub is an LTI 1.3 tool of, as stored: the platforms an
// administrator registered with their deployments, the platform courses (contexts) mapped to
// classes, the platform line items (grade columns) of assignments, and the outbox of scores on
// their way to a platform. The outbox is worked by any node: a row is leased, delivered or
// given back with its error and next attempt, and a lease that ran out goes to another node;
// each lease of a row has the next number, so a node whose lease was taken over cannot mark it.
// Secrets (the tool's private keys) are never here: they are read from files.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tlmhub::server {

struct LtiPlatform {
    std::int64_t id = 0;
    std::string name;                        // shown to administrators and on the login page
    std::string issuer, clientId;            // unique together: the platform's `iss` and our `aud`
    std::string authUrl;                     // its OIDC authorization endpoint (the launch)
    std::string tokenUrl;                    // its OAuth 2 token endpoint (grade services)
    std::string jwksUrl;                     // its public keys
    std::vector<std::string> deploymentIds;  // launches from other deployments are refused
    std::int64_t createdAt = 0;              // unix s
};

// A teacher's deep-linking launch, waiting for the assignment to place in the platform's course.
struct LtiDeepLinkRequest {
    std::string key;                         // random: in the app's address
    std::int64_t platformId = 0;
    std::string deploymentId;
    std::string returnUrl, data;             // where the answer goes, what it must echo
    std::int64_t classId = 0, userId = 0;    // the course's class and the teacher
    std::int64_t createdAt = 0;              // unix s
};

// Where a person's score for an assignment goes: a platform's line item and who they are there.
struct LtiScoreTarget {
    std::int64_t platformId = 0;
    std::string lineItemUrl, userSubject;
};

// A score on its way to a platform's line item.
struct LtiScore {
    std::int64_t id = 0;
    std::int64_t platformId = 0;
    std::string lineItemUrl;
    std::string userSubject;                 // the person's `sub` at the platform
    std::int64_t userId = 0;                 // the person's account here
    std::int64_t assignmentId = 0;           // what the score is for (the teacher's view)
    double scoreGiven = 0, scoreMaximum = 0;
    std::string comment;
    std::int64_t timestampMs = 0;            // when the score was given: the platform keeps the newest
    std::string state = "pending";           // pending, delivered, superseded, failed (gave up)
    std::int64_t attempts = 0;
    std::int64_t nextAttemptAt = 0;          // unix s
    std::string lastError;
    std::int64_t createdAt = 0, deliveredAt = 0;
    std::int64_t lease = 0;                  // the number of the latest lease of the row
};

class LtiStore {
public:
    virtual ~LtiStore() = default;

    // ---- platforms
    // Stores a new platform with its deployments; nullopt when its issuer and client id are
    // registered already.
    virtual std::optional<std::int64_t> addPlatform(const LtiPlatform& platform) = 0;
    virtual std::optional<LtiPlatform> platform(std::int64_t id) = 0;
    // The platforms with `issuer` (one per client id), by id.
    virtual std::vector<LtiPlatform> platformsOf(const std::string& issuer) = 0;
    virtual std::vector<LtiPlatform> listPlatforms() = 0;    // by id
    // Replaces name, issuer, client id, the endpoints and the deployments of `platform.id`.
    // False when there is no such platform or the issuer and client id belong to another.
    virtual bool updatePlatform(const LtiPlatform& platform) = 0;
    // Removes the platform with its deployments, course links, line items and outbox; the
    // classes stay.
    virtual bool removePlatform(std::int64_t id) = 0;

    // ---- courses
    // The class a platform course is mapped to.
    virtual std::optional<std::int64_t> classOfContext(std::int64_t platformId, const std::string& contextId) = 0;
    // Maps the course to `classId` unless it is mapped already, and returns the class it is
    // mapped to: of two first launches racing on any nodes, one class wins.
    virtual std::int64_t linkContext(std::int64_t platformId, const std::string& contextId, std::int64_t classId) = 0;

    // ---- line items
    // Records that scores for `assignmentId` go to the line item `url` at the platform.
    virtual void setLineItem(std::int64_t platformId, const std::string& url, std::int64_t assignmentId) = 0;
    // The line item of the assignment at the platform.
    virtual std::optional<std::string> lineItemOf(std::int64_t platformId, std::int64_t assignmentId) = 0;

    // People launched from a platform are linked to it as identities "lti <issuer>"
    // (UserStore): the line items of the assignment at the platforms `userId` is linked to.
    virtual std::vector<LtiScoreTarget> scoreTargets(std::int64_t assignmentId, std::int64_t userId) = 0;

    // ---- deep linking
    // Stores a request; those made before `purgeBeforeUnix` (never answered) go.
    virtual void addDeepLink(const LtiDeepLinkRequest& request, std::int64_t purgeBeforeUnix) = 0;
    // The request with `key`, made at or after `notBeforeUnix`; `take` removes it in the same
    // step (of two racing, one gets it).
    virtual std::optional<LtiDeepLinkRequest> deepLink(const std::string& key, std::int64_t notBeforeUnix, bool take) = 0;

    // ---- outbox
    // Stores a pending score, due now; older pending scores of the same person and line item
    // become superseded (the platform keeps only the newest anyway). Returns its id.
    virtual std::int64_t addScore(const LtiScore& score) = 0;
    // Leases up to `limit` pending scores that are due at `nowUnix` and not leased, until
    // `nowUnix + leaseSeconds`, each with its next lease number; oldest first.
    virtual std::vector<LtiScore> claimScores(std::int64_t nowUnix, std::int64_t leaseSeconds, std::size_t limit) = 0;
    // Ends a lease: delivered, or failed with the error and the next attempt (`giveUp`: the
    // score is failed for good). False when the lease is no longer the caller's.
    virtual bool markDelivered(std::int64_t id, std::int64_t lease, std::int64_t nowUnix) = 0;
    virtual bool markFailed(std::int64_t id, std::int64_t lease, const std::string& error,
                            std::int64_t nextAttemptAt, bool giveUp) = 0;
    // The scores sent or to be sent for an assignment, newest first (the teacher's view).
    virtual std::vector<LtiScore> scoresOf(std::int64_t assignmentId) = 0;
};

} // namespace tlmhub::server
