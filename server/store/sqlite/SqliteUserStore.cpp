#include "server/store/UnixTime.h"
#include "server/store/sqlite/SqliteStores.h"

#include <SQLiteCpp/Transaction.h>


namespace tlmhub::server {

namespace {

constexpr const char* kSelectById = "SELECT id, username, role, disabled FROM users WHERE id = ?";

User readUser(SQLite::Statement& q)
{
    return User{q.getColumn(0).getInt64(), q.getColumn(1).getString(), q.getColumn(2).getString(),
                q.getColumn(3).getInt() != 0};
}

Credentials readCredentials(SQLite::Statement& q)
{
    Credentials c{q.getColumn(0).getInt64(), std::nullopt};
    if (!q.getColumn(1).isNull()) c.passwordHash = q.getColumn(1).getString();
    return c;
}

constexpr const char* kSelectByIdentity =
    "SELECT u.id, u.username, u.role, u.disabled FROM identities i JOIN users u ON u.id = i.user_id"
    " WHERE i.provider = ? AND i.subject = ?";

std::optional<User> linkedUser(SqliteConnection& c, const std::string& provider, const std::string& subject)
{
    auto q = c.prepared(kSelectByIdentity);
    q->bind(1, provider);
    q->bind(2, subject);
    if (!q->executeStep()) return std::nullopt;
    return readUser(*q);
}

} // namespace

std::optional<User> SqliteUserStore::insert(const std::string& username, const std::string& passwordHash,
                                            const std::string& role)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<User> {
        // IMMEDIATE: the check and the insert see no other writer in between.
        SQLite::Transaction transaction(c.db(), SQLite::TransactionBehavior::IMMEDIATE);
        {
            auto taken = c.prepared("SELECT 1 FROM users WHERE username = ? COLLATE NOCASE");
            taken->bind(1, username);
            if (taken->executeStep()) return std::nullopt;
        }
        auto insert = c.prepared("INSERT INTO users(username, password_hash, role, created_at)"
                                 " VALUES(?, ?, ?, ?)");
        insert->bind(1, username);
        insert->bind(2, passwordHash);
        insert->bind(3, role);
        insert->bind(4, static_cast<std::int64_t>(unixNow()));
        insert->exec();
        const std::int64_t id = c.db().getLastInsertRowid();
        transaction.commit();
        return User{id, username, role, false};
    });
}

std::optional<Credentials> SqliteUserStore::credentials(const std::string& username)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<Credentials> {
        {
            auto exact = c.prepared("SELECT id, password_hash FROM users WHERE username = ?");
            exact->bind(1, username);
            if (exact->executeStep()) return readCredentials(*exact);
        }
        auto anyCase = c.prepared("SELECT id, password_hash FROM users WHERE username = ? COLLATE NOCASE LIMIT 2");
        anyCase->bind(1, username);
        if (!anyCase->executeStep()) return std::nullopt;
        Credentials found = readCredentials(*anyCase);
        if (anyCase->executeStep()) return std::nullopt;   // two old accounts differ only in case
        return found;
    });
}

std::optional<Credentials> SqliteUserStore::credentials(std::int64_t id)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<Credentials> {
        auto q = c.prepared("SELECT id, password_hash FROM users WHERE id = ?");
        q->bind(1, id);
        if (!q->executeStep()) return std::nullopt;
        return readCredentials(*q);
    });
}

bool SqliteUserStore::setPasswordHash(std::int64_t id, const std::string& passwordHash)
{
    return mDb.run([&](SqliteConnection& c) {
        auto update = c.prepared("UPDATE users SET password_hash = ? WHERE id = ?");
        update->bind(1, passwordHash);
        update->bind(2, id);
        return update->exec() > 0;
    });
}

std::optional<std::string> SqliteUserStore::preferences(std::int64_t id)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<std::string> {
        auto q = c.prepared("SELECT preferences FROM users WHERE id = ?");
        q->bind(1, id);
        if (!q->executeStep()) return std::nullopt;
        return q->getColumn(0).getString();
    });
}

bool SqliteUserStore::setPreferences(std::int64_t id, const std::string& json)
{
    return mDb.run([&](SqliteConnection& c) {
        auto update = c.prepared("UPDATE users SET preferences = ? WHERE id = ?");
        update->bind(1, json);
        update->bind(2, id);
        return update->exec() > 0;
    });
}

std::optional<User> SqliteUserStore::find(std::int64_t id)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<User> {
        auto q = c.prepared(kSelectById);
        q->bind(1, id);
        if (!q->executeStep()) return std::nullopt;
        return readUser(*q);
    });
}

std::optional<User> SqliteUserStore::findByName(const std::string& username)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<User> {
        auto q = c.prepared("SELECT id, username, role, disabled FROM users WHERE username = ?");
        q->bind(1, username);
        if (!q->executeStep()) return std::nullopt;
        return readUser(*q);
    });
}

std::vector<User> SqliteUserStore::list()
{
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared("SELECT id, username, role, disabled FROM users ORDER BY id");
        std::vector<User> users;
        while (q->executeStep()) users.push_back(readUser(*q));
        return users;
    });
}

std::size_t SqliteUserStore::count()
{
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared("SELECT COUNT(*) FROM users");
        q->executeStep();
        return static_cast<std::size_t>(q->getColumn(0).getInt64());
    });
}

UserChangeOutcome SqliteUserStore::change(std::int64_t id, const UserChange& change, User& updated)
{
    return mDb.run([&](SqliteConnection& c) {
        // IMMEDIATE: no other writer between reading who administers and writing the change.
        SQLite::Transaction transaction(c.db(), SQLite::TransactionBehavior::IMMEDIATE);
        std::vector<User> all;
        {
            auto q = c.prepared("SELECT id, username, role, disabled FROM users");
            while (q->executeStep()) all.push_back(readUser(*q));
        }
        User changed;
        const UserChangeOutcome outcome = applyUserChange(all, id, change, changed);
        if (outcome != UserChangeOutcome::Changed) return outcome;
        auto write = c.prepared("UPDATE users SET role = ?, disabled = ? WHERE id = ?");
        write->bind(1, changed.role);
        write->bind(2, changed.disabled ? 1 : 0);
        write->bind(3, id);
        write->exec();
        transaction.commit();
        updated = changed;
        return outcome;
    });
}

std::vector<std::string> SqliteUserStore::namesDifferingOnlyInCase()
{
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared("SELECT group_concat(username, ', ') FROM (SELECT username FROM users ORDER BY id)"
                            " GROUP BY lower(username) HAVING COUNT(*) > 1");
        std::vector<std::string> groups;
        while (q->executeStep()) groups.push_back(q->getColumn(0).getString());
        return groups;
    });
}

std::optional<User> SqliteUserStore::findByIdentity(const std::string& provider, const std::string& subject)
{
    return mDb.run([&](SqliteConnection& c) { return linkedUser(c, provider, subject); });
}

User SqliteUserStore::insertLinked(const std::string& provider, const std::string& subject, const std::string& username,
                                   const std::string& role)
{
    return mDb.run([&](SqliteConnection& c) {
        // IMMEDIATE: a second first sign-in of the same person waits, then finds the link.
        SQLite::Transaction transaction(c.db(), SQLite::TransactionBehavior::IMMEDIATE);
        if (auto linked = linkedUser(c, provider, subject)) return *linked;
        auto taken = c.prepared("SELECT 1 FROM users WHERE username = ? COLLATE NOCASE");
        std::string name = username;
        for (int n = 2;; ++n) {
            taken->reset();
            taken->bind(1, name);
            if (!taken->executeStep()) break;
            name = suffixedUsername(username, n);
        }
        auto user = c.prepared("INSERT INTO users(username, password_hash, role, created_at) VALUES(?, NULL, ?, ?)");
        user->bind(1, name);
        user->bind(2, role);
        user->bind(3, static_cast<std::int64_t>(unixNow()));
        user->exec();
        const std::int64_t id = c.db().getLastInsertRowid();
        auto link = c.prepared("INSERT INTO identities(provider, subject, user_id, created_at) VALUES(?, ?, ?, ?)");
        link->bind(1, provider);
        link->bind(2, subject);
        link->bind(3, id);
        link->bind(4, static_cast<std::int64_t>(unixNow()));
        link->exec();
        transaction.commit();
        return User{id, name, role, false};
    });
}

} // namespace tlmhub::server
