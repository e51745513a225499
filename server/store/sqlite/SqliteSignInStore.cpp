#include "server/store/sqlite/SqliteStores.h"

namespace tlmhub::server {

void SqliteSignInStore::add(const SignInAttempt& attempt)
{
    mDb.run([&](SqliteConnection& c) {
        auto insert = c.prepared("INSERT INTO sign_in_attempts(state, provider, nonce, code_verifier, browser_key, created_at,"
                                 " user_id) VALUES(?, ?, ?, ?, ?, ?, ?)");
        insert->bind(1, attempt.state);
        insert->bind(2, attempt.provider);
        insert->bind(3, attempt.nonce);
        insert->bind(4, attempt.codeVerifier);
        insert->bind(5, attempt.browserKey);
        insert->bind(6, attempt.createdAt);
        insert->bind(7, attempt.userId);
        insert->exec();
    });
}

std::optional<SignInAttempt> SqliteSignInStore::take(const std::string& state, std::int64_t notBeforeUnix)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<SignInAttempt> {
        auto remove = c.prepared("DELETE FROM sign_in_attempts WHERE state = ?"
                                 " RETURNING provider, nonce, code_verifier, browser_key, created_at, user_id");
        remove->bind(1, state);
        if (!remove->executeStep()) return std::nullopt;
        SignInAttempt attempt{state,
                              remove->getColumn(0).getString(),
                              remove->getColumn(1).getString(),
                              remove->getColumn(2).getString(),
                              remove->getColumn(3).getString(),
                              remove->getColumn(4).getInt64(),
                              remove->getColumn(5).getInt64()};
        while (remove->executeStep()) {}   // the statement runs to its end: the delete is done
        if (attempt.createdAt < notBeforeUnix) return std::nullopt;
        return attempt;
    });
}

std::size_t SqliteSignInStore::purge(std::int64_t notBeforeUnix)
{
    return mDb.runFreeingSpace([&](SqliteConnection& c) {
        auto remove = c.prepared("DELETE FROM sign_in_attempts WHERE created_at < ?");
        remove->bind(1, notBeforeUnix);
        remove->exec();
        auto count = c.prepared("SELECT COUNT(*) FROM sign_in_attempts");
        count->executeStep();
        return static_cast<std::size_t>(count->getColumn(0).getInt64());
    });
}

} // namespace tlmhub::server
