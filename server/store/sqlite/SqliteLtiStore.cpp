#include "server/store/sqlite/SqliteStores.h"

#include "server/store/UnixTime.h"

#include <SQLiteCpp/Transaction.h>

#include <algorithm>

namespace tlmhub::server {

namespace {

#define TLMHUB_LTI_PLATFORM_COLUMNS "id, name, issuer, client_id, auth_url, token_url, jwks_url, created_at"
#define TLMHUB_LTI_SCORE_COLUMNS                                                                                     \
    "id, platform_id, line_item_url, user_subject, user_id, assignment_id, score_given, score_maximum, comment,"    \
    " timestamp_ms, state, attempts, next_attempt_at, last_error, created_at, delivered_at, lease"

LtiPlatform sqlitePlatformRow(SqliteConnection& c, SQLite::Statement& row)
{
    LtiPlatform platform;
    platform.id = row.getColumn(0).getInt64();
    platform.name = row.getColumn(1).getString();
    platform.issuer = row.getColumn(2).getString();
    platform.clientId = row.getColumn(3).getString();
    platform.authUrl = row.getColumn(4).getString();
    platform.tokenUrl = row.getColumn(5).getString();
    platform.jwksUrl = row.getColumn(6).getString();
    platform.createdAt = row.getColumn(7).getInt64();
    auto deployments = c.prepared("SELECT deployment_id FROM lti_deployments WHERE platform_id = ? ORDER BY deployment_id");
    deployments->bind(1, platform.id);
    while (deployments->executeStep()) platform.deploymentIds.push_back(deployments->getColumn(0).getString());
    return platform;
}

std::vector<LtiPlatform> sqlitePlatforms(SqliteConnection& c, SqliteConnection::Statement& query)
{
    std::vector<LtiPlatform> platforms;
    while (query->executeStep()) platforms.push_back(sqlitePlatformRow(c, *query));
    return platforms;
}

LtiScore sqliteScoreRow(SQLite::Statement& row)
{
    LtiScore score;
    score.id = row.getColumn(0).getInt64();
    score.platformId = row.getColumn(1).getInt64();
    score.lineItemUrl = row.getColumn(2).getString();
    score.userSubject = row.getColumn(3).getString();
    score.userId = row.getColumn(4).getInt64();
    score.assignmentId = row.getColumn(5).getInt64();
    score.scoreGiven = row.getColumn(6).getDouble();
    score.scoreMaximum = row.getColumn(7).getDouble();
    score.comment = row.getColumn(8).getString();
    score.timestampMs = row.getColumn(9).getInt64();
    score.state = row.getColumn(10).getString();
    score.attempts = row.getColumn(11).getInt64();
    score.nextAttemptAt = row.getColumn(12).getInt64();
    score.lastError = row.getColumn(13).getString();
    score.createdAt = row.getColumn(14).getInt64();
    score.deliveredAt = row.getColumn(15).getInt64();
    score.lease = row.getColumn(16).getInt64();
    return score;
}

void sqliteAddDeployments(SqliteConnection& c, const LtiPlatform& platform, std::int64_t id)
{
    for (const auto& deployment : platform.deploymentIds) {
        auto insert = c.prepared("INSERT INTO lti_deployments(platform_id, deployment_id) VALUES(?, ?)"
                                 " ON CONFLICT DO NOTHING");
        insert->bind(1, id);
        insert->bind(2, deployment);
        insert->exec();
    }
}

void sqliteBindPlatform(SQLite::Statement& statement, const LtiPlatform& platform)
{
    statement.bind(1, platform.name);
    statement.bind(2, platform.issuer);
    statement.bind(3, platform.clientId);
    statement.bind(4, platform.authUrl);
    statement.bind(5, platform.tokenUrl);
    statement.bind(6, platform.jwksUrl);
}

} // namespace

std::optional<std::int64_t> SqliteLtiStore::addPlatform(const LtiPlatform& platform)
{
    const auto now = static_cast<std::int64_t>(unixNow());
    return mDb.run([&](SqliteConnection& c) -> std::optional<std::int64_t> {
        SQLite::Transaction transaction(c.db(), SQLite::TransactionBehavior::IMMEDIATE);
        auto insert = c.prepared("INSERT INTO lti_platforms(name, issuer, client_id, auth_url, token_url, jwks_url,"
                                 " created_at) VALUES(?, ?, ?, ?, ?, ?, ?) ON CONFLICT(issuer, client_id) DO NOTHING");
        sqliteBindPlatform(*insert, platform);
        insert->bind(7, now);
        if (insert->exec() != 1) return std::nullopt;
        const std::int64_t id = c.db().getLastInsertRowid();
        sqliteAddDeployments(c, platform, id);
        transaction.commit();
        return id;
    });
}

std::optional<LtiPlatform> SqliteLtiStore::platform(std::int64_t id)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<LtiPlatform> {
        auto query = c.prepared("SELECT " TLMHUB_LTI_PLATFORM_COLUMNS " FROM lti_platforms WHERE id = ?");
        query->bind(1, id);
        if (!query->executeStep()) return std::nullopt;
        return sqlitePlatformRow(c, *query);
    });
}

std::vector<LtiPlatform> SqliteLtiStore::platformsOf(const std::string& issuer)
{
    return mDb.run([&](SqliteConnection& c) {
        auto query = c.prepared("SELECT " TLMHUB_LTI_PLATFORM_COLUMNS " FROM lti_platforms WHERE issuer = ? ORDER BY id");
        query->bind(1, issuer);
        return sqlitePlatforms(c, query);
    });
}

std::vector<LtiPlatform> SqliteLtiStore::listPlatforms()
{
    return mDb.run([&](SqliteConnection& c) {
        auto query = c.prepared("SELECT " TLMHUB_LTI_PLATFORM_COLUMNS " FROM lti_platforms ORDER BY id");
        return sqlitePlatforms(c, query);
    });
}

bool SqliteLtiStore::updatePlatform(const LtiPlatform& platform)
{
    return mDb.run([&](SqliteConnection& c) {
        SQLite::Transaction transaction(c.db(), SQLite::TransactionBehavior::IMMEDIATE);
        auto update = c.prepared("UPDATE OR IGNORE lti_platforms SET name = ?, issuer = ?, client_id = ?, auth_url = ?,"
                                 " token_url = ?, jwks_url = ? WHERE id = ?");
        sqliteBindPlatform(*update, platform);
        update->bind(7, platform.id);
        if (update->exec() != 1) return false;   // no such platform, or the issuer and client id are another's
        auto clear = c.prepared("DELETE FROM lti_deployments WHERE platform_id = ?");
        clear->bind(1, platform.id);
        clear->exec();
        sqliteAddDeployments(c, platform, platform.id);
        transaction.commit();
        return true;
    });
}

bool SqliteLtiStore::removePlatform(std::int64_t id)
{
    return mDb.runFreeingSpace([&](SqliteConnection& c) {
        auto remove = c.prepared("DELETE FROM lti_platforms WHERE id = ?");
        remove->bind(1, id);
        return remove->exec() == 1;
    });
}

std::optional<std::int64_t> SqliteLtiStore::classOfContext(std::int64_t platformId, const std::string& contextId)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<std::int64_t> {
        auto query = c.prepared("SELECT class_id FROM lti_contexts WHERE platform_id = ? AND context_id = ?");
        query->bind(1, platformId);
        query->bind(2, contextId);
        if (!query->executeStep()) return std::nullopt;
        return query->getColumn(0).getInt64();
    });
}

std::int64_t SqliteLtiStore::linkContext(std::int64_t platformId, const std::string& contextId, std::int64_t classId)
{
    return mDb.run([&](SqliteConnection& c) {
        SQLite::Transaction transaction(c.db(), SQLite::TransactionBehavior::IMMEDIATE);
        {
            auto insert = c.prepared("INSERT INTO lti_contexts(platform_id, context_id, class_id) VALUES(?, ?, ?)"
                                     " ON CONFLICT DO NOTHING");
            insert->bind(1, platformId);
            insert->bind(2, contextId);
            insert->bind(3, classId);
            insert->exec();
        }
        auto query = c.prepared("SELECT class_id FROM lti_contexts WHERE platform_id = ? AND context_id = ?");
        query->bind(1, platformId);
        query->bind(2, contextId);
        query->executeStep();
        const std::int64_t linked = query->getColumn(0).getInt64();
        transaction.commit();
        return linked;
    });
}

void SqliteLtiStore::setLineItem(std::int64_t platformId, const std::string& url, std::int64_t assignmentId)
{
    mDb.run([&](SqliteConnection& c) {
        auto upsert = c.prepared("INSERT INTO lti_line_items(platform_id, assignment_id, url) VALUES(?, ?, ?)"
                                 " ON CONFLICT(platform_id, assignment_id) DO UPDATE SET url = excluded.url");
        upsert->bind(1, platformId);
        upsert->bind(2, assignmentId);
        upsert->bind(3, url);
        upsert->exec();
    });
}

std::optional<std::string> SqliteLtiStore::lineItemOf(std::int64_t platformId, std::int64_t assignmentId)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<std::string> {
        auto query = c.prepared("SELECT url FROM lti_line_items WHERE platform_id = ? AND assignment_id = ?");
        query->bind(1, platformId);
        query->bind(2, assignmentId);
        if (!query->executeStep()) return std::nullopt;
        return query->getColumn(0).getString();
    });
}

std::vector<LtiScoreTarget> SqliteLtiStore::scoreTargets(std::int64_t assignmentId, std::int64_t userId)
{
    return mDb.run([&](SqliteConnection& c) {
        auto query = c.prepared("SELECT l.platform_id, l.url, i.subject FROM lti_line_items l"
                                " JOIN lti_platforms p ON p.id = l.platform_id"
                                " JOIN identities i ON i.provider = 'lti ' || p.issuer AND i.user_id = ?"
                                " WHERE l.assignment_id = ? ORDER BY l.platform_id");
        query->bind(1, userId);
        query->bind(2, assignmentId);
        std::vector<LtiScoreTarget> targets;
        while (query->executeStep())
            targets.push_back({query->getColumn(0).getInt64(), query->getColumn(1).getString(), query->getColumn(2).getString()});
        return targets;
    });
}

void SqliteLtiStore::addDeepLink(const LtiDeepLinkRequest& request, std::int64_t purgeBeforeUnix)
{
    mDb.run([&](SqliteConnection& c) {
        SQLite::Transaction transaction(c.db(), SQLite::TransactionBehavior::IMMEDIATE);
        {
            auto purge = c.prepared("DELETE FROM lti_deep_links WHERE created_at < ?");
            purge->bind(1, purgeBeforeUnix);
            purge->exec();
        }
        auto insert = c.prepared("INSERT INTO lti_deep_links(key, platform_id, deployment_id, return_url, data, class_id,"
                                 " user_id, created_at) VALUES(?, ?, ?, ?, ?, ?, ?, ?)");
        insert->bind(1, request.key);
        insert->bind(2, request.platformId);
        insert->bind(3, request.deploymentId);
        insert->bind(4, request.returnUrl);
        insert->bind(5, request.data);
        insert->bind(6, request.classId);
        insert->bind(7, request.userId);
        insert->bind(8, request.createdAt);
        insert->exec();
        transaction.commit();
    });
}

std::optional<LtiDeepLinkRequest> SqliteLtiStore::deepLink(const std::string& key, std::int64_t notBeforeUnix, bool take)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<LtiDeepLinkRequest> {
        auto query = take ? c.prepared("DELETE FROM lti_deep_links WHERE key = ? RETURNING platform_id, deployment_id,"
                                       " return_url, data, class_id, user_id, created_at")
                          : c.prepared("SELECT platform_id, deployment_id, return_url, data, class_id, user_id, created_at"
                                       " FROM lti_deep_links WHERE key = ?");
        query->bind(1, key);
        if (!query->executeStep()) return std::nullopt;
        LtiDeepLinkRequest request{key,
                                   query->getColumn(0).getInt64(),
                                   query->getColumn(1).getString(),
                                   query->getColumn(2).getString(),
                                   query->getColumn(3).getString(),
                                   query->getColumn(4).getInt64(),
                                   query->getColumn(5).getInt64(),
                                   query->getColumn(6).getInt64()};
        while (query->executeStep()) {}   // the statement runs to its end: a delete is done
        if (request.createdAt < notBeforeUnix) return std::nullopt;
        return request;
    });
}

std::int64_t SqliteLtiStore::addScore(const LtiScore& score)
{
    const auto now = static_cast<std::int64_t>(unixNow());
    return mDb.run([&](SqliteConnection& c) {
        SQLite::Transaction transaction(c.db(), SQLite::TransactionBehavior::IMMEDIATE);
        {
            auto supersede = c.prepared("UPDATE lti_scores SET state = 'superseded' WHERE state = 'pending'"
                                        " AND platform_id = ? AND line_item_url = ? AND user_subject = ?");
            supersede->bind(1, score.platformId);
            supersede->bind(2, score.lineItemUrl);
            supersede->bind(3, score.userSubject);
            supersede->exec();
        }
        auto insert = c.prepared("INSERT INTO lti_scores(platform_id, line_item_url, user_subject, user_id, assignment_id,"
                                 " score_given, score_maximum, comment, timestamp_ms, state, next_attempt_at, created_at)"
                                 " VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?, 'pending', ?, ?)");
        insert->bind(1, score.platformId);
        insert->bind(2, score.lineItemUrl);
        insert->bind(3, score.userSubject);
        insert->bind(4, score.userId);
        insert->bind(5, score.assignmentId);
        insert->bind(6, score.scoreGiven);
        insert->bind(7, score.scoreMaximum);
        insert->bind(8, score.comment);
        insert->bind(9, score.timestampMs);
        insert->bind(10, now);
        insert->bind(11, now);
        insert->exec();
        const std::int64_t id = c.db().getLastInsertRowid();
        transaction.commit();
        return id;
    });
}

std::vector<LtiScore> SqliteLtiStore::claimScores(std::int64_t nowUnix, std::int64_t leaseSeconds, std::size_t limit)
{
    return mDb.run([&](SqliteConnection& c) {
        auto claim = c.prepared("UPDATE lti_scores SET lease = lease + 1, lease_until = ?, attempts = attempts + 1"
                                " WHERE id IN (SELECT id FROM lti_scores WHERE state = 'pending' AND next_attempt_at <= ?"
                                " AND lease_until <= ? ORDER BY id LIMIT ?) RETURNING " TLMHUB_LTI_SCORE_COLUMNS);
        claim->bind(1, nowUnix + leaseSeconds);
        claim->bind(2, nowUnix);
        claim->bind(3, nowUnix);
        claim->bind(4, static_cast<std::int64_t>(limit));
        std::vector<LtiScore> scores;
        while (claim->executeStep()) scores.push_back(sqliteScoreRow(*claim));
        std::sort(scores.begin(), scores.end(), [](const LtiScore& a, const LtiScore& b) { return a.id < b.id; });
        return scores;
    });
}

bool SqliteLtiStore::markDelivered(std::int64_t id, std::int64_t lease, std::int64_t nowUnix)
{
    return mDb.run([&](SqliteConnection& c) {
        auto update = c.prepared("UPDATE lti_scores SET state = 'delivered', delivered_at = ?, lease_until = 0,"
                                 " last_error = '' WHERE id = ? AND lease = ? AND state = 'pending'");
        update->bind(1, nowUnix);
        update->bind(2, id);
        update->bind(3, lease);
        return update->exec() == 1;
    });
}

bool SqliteLtiStore::markFailed(std::int64_t id, std::int64_t lease, const std::string& error,
                                std::int64_t nextAttemptAt, bool giveUp)
{
    return mDb.run([&](SqliteConnection& c) {
        auto update = c.prepared("UPDATE lti_scores SET state = ?, last_error = ?, next_attempt_at = ?, lease_until = 0"
                                 " WHERE id = ? AND lease = ? AND state = 'pending'");
        update->bind(1, giveUp ? "failed" : "pending");
        update->bind(2, error);
        update->bind(3, nextAttemptAt);
        update->bind(4, id);
        update->bind(5, lease);
        return update->exec() == 1;
    });
}

std::vector<LtiScore> SqliteLtiStore::scoresOf(std::int64_t assignmentId)
{
    return mDb.run([&](SqliteConnection& c) {
        auto query = c.prepared("SELECT " TLMHUB_LTI_SCORE_COLUMNS " FROM lti_scores WHERE assignment_id = ?"
                                " ORDER BY id DESC");
        query->bind(1, assignmentId);
        std::vector<LtiScore> scores;
        while (query->executeStep()) scores.push_back(sqliteScoreRow(*query));
        return scores;
    });
}

} // namespace tlmhub::server
