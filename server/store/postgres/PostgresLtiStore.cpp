#include "server/store/postgres/PostgresStores.h"

#include "server/store/UnixTime.h"

#include <algorithm>

namespace tlmhub::server {

namespace {

#define TLMHUB_PG_LTI_PLATFORM_COLUMNS "id, name, issuer, client_id, auth_url, token_url, jwks_url, created_at"
#define TLMHUB_PG_LTI_SCORE_COLUMNS                                                                                  \
    "id, platform_id, line_item_url, user_subject, user_id, assignment_id, score_given, score_maximum, comment,"    \
    " timestamp_ms, state, attempts, next_attempt_at, last_error, created_at, delivered_at, lease"

constexpr PgStatement kAddPlatform{
    "lti_add_platform",
    "INSERT INTO lti_platforms(name, issuer, client_id, auth_url, token_url, jwks_url, created_at)"
    " VALUES($1, $2, $3, $4, $5, $6, $7) ON CONFLICT(issuer, client_id) DO NOTHING RETURNING id"};
constexpr PgStatement kAddDeployment{"lti_add_deployment",
                                     "INSERT INTO lti_deployments(platform_id, deployment_id) VALUES($1, $2)"
                                     " ON CONFLICT DO NOTHING"};
constexpr PgStatement kClearDeployments{"lti_clear_deployments", "DELETE FROM lti_deployments WHERE platform_id = $1"};
constexpr PgStatement kDeployments{"lti_deployments",
                                   "SELECT deployment_id FROM lti_deployments WHERE platform_id = $1 ORDER BY deployment_id"};
constexpr PgStatement kPlatformById{"lti_platform_by_id",
                                    "SELECT " TLMHUB_PG_LTI_PLATFORM_COLUMNS " FROM lti_platforms WHERE id = $1"};
constexpr PgStatement kPlatformsOf{"lti_platforms_of", "SELECT " TLMHUB_PG_LTI_PLATFORM_COLUMNS
                                                       " FROM lti_platforms WHERE issuer = $1 ORDER BY id"};
constexpr PgStatement kListPlatforms{"lti_list_platforms",
                                     "SELECT " TLMHUB_PG_LTI_PLATFORM_COLUMNS " FROM lti_platforms ORDER BY id"};
// The update skips a platform whose new issuer and client id are another's (no conflict raised).
constexpr PgStatement kUpdatePlatform{
    "lti_update_platform",
    "UPDATE lti_platforms SET name = $1, issuer = $2, client_id = $3, auth_url = $4, token_url = $5, jwks_url = $6"
    " WHERE id = $7 AND NOT EXISTS (SELECT 1 FROM lti_platforms o WHERE o.issuer = $2 AND o.client_id = $3"
    " AND o.id <> $7)"};
constexpr PgStatement kRemovePlatform{"lti_remove_platform", "DELETE FROM lti_platforms WHERE id = $1"};
constexpr PgStatement kClassOfContext{"lti_class_of_context",
                                      "SELECT class_id FROM lti_contexts WHERE platform_id = $1 AND context_id = $2"};
constexpr PgStatement kLinkContext{"lti_link_context",
                                   "INSERT INTO lti_contexts(platform_id, context_id, class_id) VALUES($1, $2, $3)"
                                   " ON CONFLICT DO NOTHING"};
constexpr PgStatement kSetLineItem{"lti_set_line_item",
                                   "INSERT INTO lti_line_items(platform_id, assignment_id, url) VALUES($1, $2, $3)"
                                   " ON CONFLICT(platform_id, assignment_id) DO UPDATE SET url = excluded.url"};
constexpr PgStatement kLineItemOf{"lti_line_item_of",
                                  "SELECT url FROM lti_line_items WHERE platform_id = $1 AND assignment_id = $2"};
constexpr PgStatement kScoreTargets{"lti_score_targets",
                                    "SELECT l.platform_id, l.url, i.subject FROM lti_line_items l"
                                    " JOIN lti_platforms p ON p.id = l.platform_id"
                                    " JOIN identities i ON i.provider = 'lti ' || p.issuer AND i.user_id = $1"
                                    " WHERE l.assignment_id = $2 ORDER BY l.platform_id"};
constexpr PgStatement kPurgeDeepLinks{"lti_purge_deep_links", "DELETE FROM lti_deep_links WHERE created_at < $1"};
constexpr PgStatement kAddDeepLink{"lti_add_deep_link",
                                   "INSERT INTO lti_deep_links(key, platform_id, deployment_id, return_url, data, class_id,"
                                   " user_id, created_at) VALUES($1, $2, $3, $4, $5, $6, $7, $8)"};
constexpr PgStatement kDeepLink{"lti_deep_link", "SELECT platform_id, deployment_id, return_url, data, class_id, user_id,"
                                                 " created_at FROM lti_deep_links WHERE key = $1"};
constexpr PgStatement kTakeDeepLink{"lti_take_deep_link",
                                    "DELETE FROM lti_deep_links WHERE key = $1 RETURNING platform_id, deployment_id,"
                                    " return_url, data, class_id, user_id, created_at"};
constexpr PgStatement kSupersede{"lti_supersede",
                                 "UPDATE lti_scores SET state = 'superseded' WHERE state = 'pending'"
                                 " AND platform_id = $1 AND line_item_url = $2 AND user_subject = $3"};
constexpr PgStatement kAddScore{
    "lti_add_score",
    "INSERT INTO lti_scores(platform_id, line_item_url, user_subject, user_id, assignment_id, score_given,"
    " score_maximum, comment, timestamp_ms, state, next_attempt_at, created_at)"
    " VALUES($1, $2, $3, $4, $5, $6, $7, $8, $9, 'pending', $10, $10) RETURNING id"};
// SKIP LOCKED: nodes claiming at once take different rows instead of waiting on each other.
constexpr PgStatement kClaimScores{
    "lti_claim_scores",
    "UPDATE lti_scores SET lease = lease + 1, lease_until = $1, attempts = attempts + 1"
    " WHERE id IN (SELECT id FROM lti_scores WHERE state = 'pending' AND next_attempt_at <= $2"
    " AND lease_until <= $2 ORDER BY id LIMIT $3 FOR UPDATE SKIP LOCKED) RETURNING " TLMHUB_PG_LTI_SCORE_COLUMNS};
constexpr PgStatement kMarkDelivered{"lti_mark_delivered",
                                     "UPDATE lti_scores SET state = 'delivered', delivered_at = $1, lease_until = 0,"
                                     " last_error = '' WHERE id = $2 AND lease = $3 AND state = 'pending'"};
constexpr PgStatement kMarkFailed{"lti_mark_failed",
                                  "UPDATE lti_scores SET state = $1, last_error = $2, next_attempt_at = $3,"
                                  " lease_until = 0 WHERE id = $4 AND lease = $5 AND state = 'pending'"};
constexpr PgStatement kScoresOf{"lti_scores_of", "SELECT " TLMHUB_PG_LTI_SCORE_COLUMNS
                                                 " FROM lti_scores WHERE assignment_id = $1 ORDER BY id DESC"};

LtiPlatform pgPlatformRow(PostgresConnection& c, pqxx::transaction_base& tx, const pqxx::row& row)
{
    LtiPlatform platform;
    platform.id = row[0].as<std::int64_t>();
    platform.name = row[1].as<std::string>();
    platform.issuer = row[2].as<std::string>();
    platform.clientId = row[3].as<std::string>();
    platform.authUrl = row[4].as<std::string>();
    platform.tokenUrl = row[5].as<std::string>();
    platform.jwksUrl = row[6].as<std::string>();
    platform.createdAt = row[7].as<std::int64_t>();
    for (const auto& deployment : c.exec(tx, kDeployments, platform.id))
        platform.deploymentIds.push_back(deployment[0].as<std::string>());
    return platform;
}

std::vector<LtiPlatform> pgPlatforms(PostgresConnection& c, pqxx::transaction_base& tx, const pqxx::result& rows)
{
    std::vector<LtiPlatform> platforms;
    for (const auto& row : rows) platforms.push_back(pgPlatformRow(c, tx, row));
    return platforms;
}

LtiScore pgScoreRow(const pqxx::row& row)
{
    LtiScore score;
    score.id = row[0].as<std::int64_t>();
    score.platformId = row[1].as<std::int64_t>();
    score.lineItemUrl = row[2].as<std::string>();
    score.userSubject = row[3].as<std::string>();
    score.userId = row[4].as<std::int64_t>();
    score.assignmentId = row[5].as<std::int64_t>();
    score.scoreGiven = row[6].as<double>();
    score.scoreMaximum = row[7].as<double>();
    score.comment = row[8].as<std::string>();
    score.timestampMs = row[9].as<std::int64_t>();
    score.state = row[10].as<std::string>();
    score.attempts = row[11].as<std::int64_t>();
    score.nextAttemptAt = row[12].as<std::int64_t>();
    score.lastError = row[13].as<std::string>();
    score.createdAt = row[14].as<std::int64_t>();
    score.deliveredAt = row[15].as<std::int64_t>();
    score.lease = row[16].as<std::int64_t>();
    return score;
}

} // namespace

std::optional<std::int64_t> PostgresLtiStore::addPlatform(const LtiPlatform& platform)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) -> std::optional<std::int64_t> {
        const auto now = static_cast<std::int64_t>(unixNow());
        pqxx::work tx(c.raw());
        const auto r = c.exec(tx, kAddPlatform, platform.name, platform.issuer, platform.clientId, platform.authUrl,
                              platform.tokenUrl, platform.jwksUrl, now);
        if (r.empty()) return std::nullopt;   // its issuer and client id are registered
        const auto id = r[0][0].as<std::int64_t>();
        for (const auto& deployment : platform.deploymentIds) c.exec(tx, kAddDeployment, id, deployment);
        tx.commit();
        return id;
    });
}

std::optional<LtiPlatform> PostgresLtiStore::platform(std::int64_t id)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) -> std::optional<LtiPlatform> {
        pqxx::read_transaction tx(c.raw());
        const auto r = c.exec(tx, kPlatformById, id);
        if (r.empty()) return std::nullopt;
        return pgPlatformRow(c, tx, r[0]);
    });
}

std::vector<LtiPlatform> PostgresLtiStore::platformsOf(const std::string& issuer)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::read_transaction tx(c.raw());
        return pgPlatforms(c, tx, c.exec(tx, kPlatformsOf, issuer));
    });
}

std::vector<LtiPlatform> PostgresLtiStore::listPlatforms()
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::read_transaction tx(c.raw());
        return pgPlatforms(c, tx, c.exec(tx, kListPlatforms));
    });
}

bool PostgresLtiStore::updatePlatform(const LtiPlatform& platform)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::work tx(c.raw());
        try {
            const auto r = c.exec(tx, kUpdatePlatform, platform.name, platform.issuer, platform.clientId,
                                  platform.authUrl, platform.tokenUrl, platform.jwksUrl, platform.id);
            if (r.affected_rows() != 1) return false;
        } catch (const pqxx::unique_violation&) {
            return false;   // another platform took the issuer and client id meanwhile
        }
        c.exec(tx, kClearDeployments, platform.id);
        for (const auto& deployment : platform.deploymentIds) c.exec(tx, kAddDeployment, platform.id, deployment);
        tx.commit();
        return true;
    });
}

bool PostgresLtiStore::removePlatform(std::int64_t id)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return c.exec(tx, kRemovePlatform, id).affected_rows() == 1;
    });
}

std::optional<std::int64_t> PostgresLtiStore::classOfContext(std::int64_t platformId, const std::string& contextId)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) -> std::optional<std::int64_t> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kClassOfContext, platformId, contextId);
        if (r.empty()) return std::nullopt;
        return r[0][0].as<std::int64_t>();
    });
}

std::int64_t PostgresLtiStore::linkContext(std::int64_t platformId, const std::string& contextId, std::int64_t classId)
{
    // Repeatable: the insert does nothing the second time, and the select reads who won.
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        c.exec(tx, kLinkContext, platformId, contextId, classId);
        return c.exec(tx, kClassOfContext, platformId, contextId)[0][0].as<std::int64_t>();
    });
}

void PostgresLtiStore::setLineItem(std::int64_t platformId, const std::string& url, std::int64_t assignmentId)
{
    mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        c.exec(tx, kSetLineItem, platformId, assignmentId, url);
    });
}

std::optional<std::string> PostgresLtiStore::lineItemOf(std::int64_t platformId, std::int64_t assignmentId)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) -> std::optional<std::string> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kLineItemOf, platformId, assignmentId);
        if (r.empty()) return std::nullopt;
        return r[0][0].as<std::string>();
    });
}

std::vector<LtiScoreTarget> PostgresLtiStore::scoreTargets(std::int64_t assignmentId, std::int64_t userId)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        std::vector<LtiScoreTarget> targets;
        for (const auto& row : c.exec(tx, kScoreTargets, userId, assignmentId))
            targets.push_back({row[0].as<std::int64_t>(), row[1].as<std::string>(), row[2].as<std::string>()});
        return targets;
    });
}

void PostgresLtiStore::addDeepLink(const LtiDeepLinkRequest& request, std::int64_t purgeBeforeUnix)
{
    mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::work tx(c.raw());
        c.exec(tx, kPurgeDeepLinks, purgeBeforeUnix);
        c.exec(tx, kAddDeepLink, request.key, request.platformId, request.deploymentId, request.returnUrl, request.data,
               request.classId, request.userId, request.createdAt);
        tx.commit();
    });
}

std::optional<LtiDeepLinkRequest> PostgresLtiStore::deepLink(const std::string& key, std::int64_t notBeforeUnix, bool take)
{
    // A take is not retried: a delete that committed before the connection broke has taken it.
    return mDb.run(take ? Idempotent::No : Idempotent::Yes, [&](PostgresConnection& c) -> std::optional<LtiDeepLinkRequest> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, take ? kTakeDeepLink : kDeepLink, key);
        if (r.empty()) return std::nullopt;
        LtiDeepLinkRequest request{key,
                                   r[0][0].as<std::int64_t>(),
                                   r[0][1].as<std::string>(),
                                   r[0][2].as<std::string>(),
                                   r[0][3].as<std::string>(),
                                   r[0][4].as<std::int64_t>(),
                                   r[0][5].as<std::int64_t>(),
                                   r[0][6].as<std::int64_t>()};
        if (request.createdAt < notBeforeUnix) return std::nullopt;
        return request;
    });
}

std::int64_t PostgresLtiStore::addScore(const LtiScore& score)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        const auto now = static_cast<std::int64_t>(unixNow());
        pqxx::work tx(c.raw());
        c.exec(tx, kSupersede, score.platformId, score.lineItemUrl, score.userSubject);
        const auto id = c.exec(tx, kAddScore, score.platformId, score.lineItemUrl, score.userSubject, score.userId,
                               score.assignmentId, score.scoreGiven, score.scoreMaximum, score.comment,
                               score.timestampMs, now)[0][0]
                            .as<std::int64_t>();
        tx.commit();
        return id;
    });
}

std::vector<LtiScore> PostgresLtiStore::claimScores(std::int64_t nowUnix, std::int64_t leaseSeconds, std::size_t limit)
{
    // Not retried: a claim that committed before the connection broke holds its leases until they run out.
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::work tx(c.raw());
        const auto r = c.exec(tx, kClaimScores, nowUnix + leaseSeconds, nowUnix, static_cast<std::int64_t>(limit));
        tx.commit();
        std::vector<LtiScore> scores;
        for (const auto& row : r) scores.push_back(pgScoreRow(row));
        std::sort(scores.begin(), scores.end(), [](const LtiScore& a, const LtiScore& b) { return a.id < b.id; });
        return scores;
    });
}

bool PostgresLtiStore::markDelivered(std::int64_t id, std::int64_t lease, std::int64_t nowUnix)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return c.exec(tx, kMarkDelivered, nowUnix, id, lease).affected_rows() == 1;
    });
}

bool PostgresLtiStore::markFailed(std::int64_t id, std::int64_t lease, const std::string& error,
                                  std::int64_t nextAttemptAt, bool giveUp)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        const std::string state = giveUp ? "failed" : "pending";
        return c.exec(tx, kMarkFailed, state, error, nextAttemptAt, id, lease).affected_rows() == 1;
    });
}

std::vector<LtiScore> PostgresLtiStore::scoresOf(std::int64_t assignmentId)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        std::vector<LtiScore> scores;
        for (const auto& row : c.exec(tx, kScoresOf, assignmentId)) scores.push_back(pgScoreRow(row));
        return scores;
    });
}

} // namespace tlmhub::server
