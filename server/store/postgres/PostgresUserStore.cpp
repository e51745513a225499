#include "server/store/UnixTime.h"
#include "server/store/postgres/PostgresStores.h"


namespace tlmhub::server {

namespace {

constexpr PgStatement kInsert{
    "users_insert",
    // A name taken regardless of case, also by a concurrent insert, yields no row here (the
    // unique index on lower(username)) instead of an error.
    "INSERT INTO users(username, password_hash, role, created_at) VALUES($1, $2, $3, $4)"
    " ON CONFLICT ((lower(username))) DO NOTHING RETURNING id"};
constexpr PgStatement kCredentialsByName{
    "users_credentials_by_name",
    // The exact name first, then any other names equal regardless of case.
    "SELECT id, password_hash, username = $1 FROM users WHERE lower(username) = lower($1)"
    " ORDER BY username = $1 DESC, id LIMIT 2"};
constexpr PgStatement kCredentialsById{"users_credentials_by_id",
                                       "SELECT id, password_hash FROM users WHERE id = $1"};
constexpr PgStatement kSetPasswordHash{"users_set_password_hash",
                                       "UPDATE users SET password_hash = $1 WHERE id = $2"};
constexpr PgStatement kPreferences{"users_preferences", "SELECT preferences FROM users WHERE id = $1"};
constexpr PgStatement kSetPreferences{"users_set_preferences", "UPDATE users SET preferences = $1 WHERE id = $2"};
constexpr PgStatement kFind{"users_find", "SELECT id, username, role, disabled FROM users WHERE id = $1"};
constexpr PgStatement kFindByName{"users_find_by_name",
                                  "SELECT id, username, role, disabled FROM users"
                                  " WHERE lower(username) = lower($1) AND username = $1"};
constexpr PgStatement kList{"users_list", "SELECT id, username, role, disabled FROM users ORDER BY id"};
constexpr PgStatement kCount{"users_count", "SELECT COUNT(*) FROM users"};
constexpr PgStatement kLockAll{
    "users_lock_all",
    // Every account, locked against another change until this transaction ends (in id order,
    // so two changes cannot deadlock). NO KEY: logins inserting sessions (foreign keys to
    // these rows) are not held up.
    "SELECT id, username, role, disabled FROM users ORDER BY id FOR NO KEY UPDATE"};
constexpr PgStatement kWrite{"users_write", "UPDATE users SET role = $1, disabled = $2 WHERE id = $3"};
constexpr PgStatement kNamesDifferingOnlyInCase{
    "users_names_differing_only_in_case",
    "SELECT string_agg(username, ', ' ORDER BY id) FROM users GROUP BY lower(username)"
    " HAVING COUNT(*) > 1 ORDER BY MIN(id)"};

constexpr PgStatement kFindByIdentity{
    "users_find_by_identity",
    "SELECT u.id, u.username, u.role, u.disabled FROM identities i JOIN users u ON u.id = i.user_id"
    " WHERE i.provider = $1 AND i.subject = $2"};
// First sign-ins take turns ("tlmhub\0\3"; migrations use "tlmhub\0\1"): rare, and two of one
// person must make one account.
constexpr long long kFirstSignInLock = 0x746c6d6875620003;
constexpr PgStatement kFirstSignInLockStatement{"users_first_sign_in_lock", "SELECT pg_advisory_xact_lock($1)"};
constexpr PgStatement kInsertWithoutPassword{
    "users_insert_without_password",
    "INSERT INTO users(username, password_hash, role, created_at) VALUES($1, NULL, $2, $3)"
    " ON CONFLICT ((lower(username))) DO NOTHING RETURNING id"};
constexpr PgStatement kLink{"identities_link",
                            "INSERT INTO identities(provider, subject, user_id, created_at) VALUES($1, $2, $3, $4)"};

User readUser(const pqxx::row& row)
{
    return User{row[0].as<std::int64_t>(), row[1].as<std::string>(), row[2].as<std::string>(std::string()),
                row[3].as<bool>()};
}

Credentials readCredentials(const pqxx::row& row)
{
    return Credentials{row[0].as<std::int64_t>(), nullable<std::string>(row[1])};
}

} // namespace

std::optional<User> PostgresUserStore::insert(const std::string& username, const std::string& passwordHash,
                                              const std::string& role)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) -> std::optional<User> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kInsert, username, passwordHash, role, static_cast<std::int64_t>(unixNow()));
        if (r.empty()) return std::nullopt;
        return User{r[0][0].as<std::int64_t>(), username, role, false};
    });
}

std::optional<Credentials> PostgresUserStore::credentials(const std::string& username)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) -> std::optional<Credentials> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kCredentialsByName, username);
        if (r.empty()) return std::nullopt;
        const bool exact = r[0][2].as<bool>();
        if (!exact && r.size() > 1) return std::nullopt;   // two old accounts differ only in case
        return readCredentials(r[0]);
    });
}

std::optional<Credentials> PostgresUserStore::credentials(std::int64_t id)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) -> std::optional<Credentials> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kCredentialsById, id);
        if (r.empty()) return std::nullopt;
        return readCredentials(r[0]);
    });
}

bool PostgresUserStore::setPasswordHash(std::int64_t id, const std::string& passwordHash)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return c.exec(tx, kSetPasswordHash, passwordHash, id).affected_rows() > 0;
    });
}

std::optional<std::string> PostgresUserStore::preferences(std::int64_t id)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) -> std::optional<std::string> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kPreferences, id);
        if (r.empty()) return std::nullopt;
        return r[0][0].as<std::string>();
    });
}

bool PostgresUserStore::setPreferences(std::int64_t id, const std::string& json)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return c.exec(tx, kSetPreferences, json, id).affected_rows() > 0;
    });
}

std::optional<User> PostgresUserStore::find(std::int64_t id)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) -> std::optional<User> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kFind, id);
        if (r.empty()) return std::nullopt;
        return readUser(r[0]);
    });
}

std::optional<User> PostgresUserStore::findByName(const std::string& username)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) -> std::optional<User> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kFindByName, username);
        if (r.empty()) return std::nullopt;
        return readUser(r[0]);
    });
}

std::vector<User> PostgresUserStore::list()
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        std::vector<User> users;
        for (const auto& row : c.exec(tx, kList)) users.push_back(readUser(row));
        return users;
    });
}

std::size_t PostgresUserStore::count()
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return c.exec(tx, kCount)[0][0].as<std::size_t>();
    });
}

UserChangeOutcome PostgresUserStore::change(std::int64_t id, const UserChange& change, User& updated)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::work tx(c.raw());
        std::vector<User> all;
        for (const auto& row : c.exec(tx, kLockAll)) all.push_back(readUser(row));
        User changed;
        const UserChangeOutcome outcome = applyUserChange(all, id, change, changed);
        if (outcome != UserChangeOutcome::Changed) return outcome;
        c.exec(tx, kWrite, changed.role, changed.disabled, id);
        tx.commit();
        updated = changed;
        return outcome;
    });
}

std::vector<std::string> PostgresUserStore::namesDifferingOnlyInCase()
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        std::vector<std::string> groups;
        for (const auto& row : c.exec(tx, kNamesDifferingOnlyInCase)) groups.push_back(row[0].as<std::string>());
        return groups;
    });
}

std::optional<User> PostgresUserStore::findByIdentity(const std::string& provider, const std::string& subject)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) -> std::optional<User> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kFindByIdentity, provider, subject);
        if (r.empty()) return std::nullopt;
        return readUser(r[0]);
    });
}

User PostgresUserStore::insertLinked(const std::string& provider, const std::string& subject,
                                     const std::string& username, const std::string& role)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::work tx(c.raw());
        c.exec(tx, kFirstSignInLockStatement, kFirstSignInLock);
        if (const auto r = c.exec(tx, kFindByIdentity, provider, subject); !r.empty()) return readUser(r[0]);
        const auto now = static_cast<std::int64_t>(unixNow());
        std::string name = username;
        for (int n = 2;; ++n) {
            const auto inserted = c.exec(tx, kInsertWithoutPassword, name, role, now);
            if (!inserted.empty()) {
                const auto id = inserted[0][0].as<std::int64_t>();
                c.exec(tx, kLink, provider, subject, id, now);
                tx.commit();
                return User{id, name, role, false};
            }
            name = suffixedUsername(username, n);
        }
    });
}

} // namespace tlmhub::server
