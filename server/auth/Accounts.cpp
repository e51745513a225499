#include "server/store/UserStore.h"

#include "server/auth/AccessPolicy.h"
#include "server/auth/PasswordHasher.h"

#include <SQLiteCpp/Statement.h>
#include <SQLiteCpp/Transaction.h>

#include <algorithm>

namespace tlmhub::server {

namespace {

User readUser(SQLite::Statement& q)
{
    User u;
    u.id = q.getColumn(0).getInt64();
    u.username = q.getColumn(1).getString();
    u.role = q.getColumn(2).getString();
    u.disabled = q.getColumn(3).getInt() != 0;
    return u;
}

bool isUsernameChar(char c)
{
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
           c == '_' || c == '.' || c == '-';
}

// Verified against when the user does not exist, so a miss costs as much as a wrong password.
const std::string& decoyHash()
{
    static const std::string hash = hashPassword("tlmhub decoy password");
    return hash;
}

} // namespace

bool isValidUsername(const std::string& username)
{
    if (username.empty() || username.size() > 64) return false;
    for (char c : username)
        if (!isUsernameChar(c)) return false;
    return true;
}

UserStore::UserStore(Database& db) : mDb(db)
{
    std::lock_guard lock(mDb.mutex());
    mDb.sql().exec(
        "CREATE TABLE IF NOT EXISTS users ("
        " id INTEGER PRIMARY KEY,"
        " username TEXT UNIQUE NOT NULL,"
        " password_hash TEXT,"
        " role TEXT CHECK(role IN ('admin','teacher','user')),"
        " created_at INTEGER)");
    // Added after the first release: older databases get the column on first start.
    bool hasDisabled = false;
    SQLite::Statement columns(mDb.sql(), "PRAGMA table_info(users)");
    while (columns.executeStep()) hasDisabled = hasDisabled || columns.getColumn(1).getString() == "disabled";
    if (!hasDisabled) mDb.sql().exec("ALTER TABLE users ADD COLUMN disabled INTEGER NOT NULL DEFAULT 0");
}

std::optional<User> UserStore::create(const std::string& username, const std::string& password,
                                      const std::string& role, std::string& error)
{
    if (!isValidUsername(username)) { error = kBadUsername; return std::nullopt; }
    if (!isValidRole(role)) { error = kBadRole; return std::nullopt; }
    if (password.size() < kMinPasswordLength) { error = kShortPassword; return std::nullopt; }
    {
        std::lock_guard lock(mDb.mutex());
        SQLite::Statement taken(mDb.sql(), "SELECT 1 FROM users WHERE username = ? COLLATE NOCASE");
        taken.bind(1, username);
        if (taken.executeStep()) { error = kUsernameTaken; return std::nullopt; }
    }

    const std::string hash = hashPassword(password);
    std::lock_guard lock(mDb.mutex());
    // INSERT OR IGNORE: a concurrent create of the same name loses here, not with an exception.
    SQLite::Statement insert(mDb.sql(),
                             "INSERT OR IGNORE INTO users(username, password_hash, role, created_at)"
                             " VALUES(?, ?, ?, ?)");
    insert.bind(1, username);
    insert.bind(2, hash);
    insert.bind(3, role);
    insert.bind(4, static_cast<std::int64_t>(unixNow()));
    if (insert.exec() == 0) { error = kUsernameTaken; return std::nullopt; }
    return User{mDb.sql().getLastInsertRowid(), username, role, false};
}

std::optional<std::string> UserStore::passwordHash(const std::string& username, std::int64_t& id)
{
    std::lock_guard lock(mDb.mutex());
    SQLite::Statement exact(mDb.sql(), "SELECT id, password_hash FROM users WHERE username = ?");
    exact.bind(1, username);
    if (exact.executeStep()) {
        if (exact.getColumn(1).isNull()) return std::nullopt;
        id = exact.getColumn(0).getInt64();
        return exact.getColumn(1).getString();
    }
    SQLite::Statement anyCase(mDb.sql(),
                              "SELECT id, password_hash FROM users WHERE username = ? COLLATE NOCASE LIMIT 2");
    anyCase.bind(1, username);
    if (!anyCase.executeStep() || anyCase.getColumn(1).isNull()) return std::nullopt;
    id = anyCase.getColumn(0).getInt64();
    std::string hash = anyCase.getColumn(1).getString();
    if (anyCase.executeStep()) return std::nullopt;   // two old accounts differ only in case
    return hash;
}

std::optional<User> UserStore::authenticate(const std::string& username,
                                            const std::string& password)
{
    std::int64_t id = 0;
    const std::optional<std::string> hash = passwordHash(username, id);
    if (!hash) {
        verifyPassword(decoyHash(), password);
        return std::nullopt;
    }
    if (!verifyPassword(*hash, password)) return std::nullopt;
    return find(id);
}

std::optional<User> UserStore::find(std::int64_t id)
{
    std::lock_guard lock(mDb.mutex());
    SQLite::Statement q(mDb.sql(), "SELECT id, username, role, disabled FROM users WHERE id = ?");
    q.bind(1, id);
    if (!q.executeStep()) return std::nullopt;
    return readUser(q);
}

std::optional<User> UserStore::findByName(const std::string& username)
{
    std::lock_guard lock(mDb.mutex());
    SQLite::Statement q(mDb.sql(), "SELECT id, username, role, disabled FROM users WHERE username = ?");
    q.bind(1, username);
    if (!q.executeStep()) return std::nullopt;
    return readUser(q);
}

std::vector<User> UserStore::list()
{
    std::lock_guard lock(mDb.mutex());
    SQLite::Statement q(mDb.sql(), "SELECT id, username, role, disabled FROM users ORDER BY id");
    std::vector<User> users;
    while (q.executeStep()) users.push_back(readUser(q));
    return users;
}

std::size_t UserStore::count()
{
    std::lock_guard lock(mDb.mutex());
    SQLite::Statement q(mDb.sql(), "SELECT COUNT(*) FROM users");
    q.executeStep();
    return static_cast<std::size_t>(q.getColumn(0).getInt64());
}

bool UserStore::changePassword(std::int64_t id, const std::string& oldPw,
                               const std::string& newPw, std::string& error)
{
    std::optional<std::string> oldHash;
    {
        std::lock_guard lock(mDb.mutex());
        SQLite::Statement q(mDb.sql(), "SELECT password_hash FROM users WHERE id = ?");
        q.bind(1, id);
        if (!q.executeStep()) { error = kNoSuchUser; return false; }
        if (!q.getColumn(0).isNull()) oldHash = q.getColumn(0).getString();
    }
    if (!oldHash || !verifyPassword(*oldHash, oldPw)) { error = kWrongPassword; return false; }
    if (newPw.size() < kMinPasswordLength) { error = kShortPassword; return false; }

    const std::string newHash = hashPassword(newPw);
    std::lock_guard lock(mDb.mutex());
    SQLite::Statement update(mDb.sql(), "UPDATE users SET password_hash = ? WHERE id = ?");
    update.bind(1, newHash);
    update.bind(2, id);
    if (update.exec() == 0) { error = kNoSuchUser; return false; }
    return true;
}

std::vector<User> UserStore::usersOtherThan(std::int64_t id)
{
    SQLite::Statement q(mDb.sql(), "SELECT id, username, role, disabled FROM users WHERE id != ?");
    q.bind(1, id);
    std::vector<User> users;
    while (q.executeStep()) users.push_back(readUser(q));
    return users;
}

std::optional<User> UserStore::update(std::int64_t id, const std::optional<std::string>& role,
                                      std::optional<bool> disabled, std::string& error)
{
    if (role && !isValidRole(*role)) { error = kBadRole; return std::nullopt; }
    std::lock_guard lock(mDb.mutex());
    SQLite::Transaction transaction(mDb.sql());
    SQLite::Statement q(mDb.sql(), "SELECT id, username, role, disabled FROM users WHERE id = ?");
    q.bind(1, id);
    if (!q.executeStep()) { error = kNoSuchUser; return std::nullopt; }
    User user = readUser(q);
    q.reset();
    const bool administeredBefore = administersServer(user);
    if (role) user.role = *role;
    if (disabled) user.disabled = *disabled;
    // Someone must be left who can administer the server; AccessPolicy says who can.
    if (administeredBefore && !administersServer(user) &&
        std::ranges::none_of(usersOtherThan(id), administersServer)) {
        error = kLastAdmin;
        return std::nullopt;
    }
    SQLite::Statement write(mDb.sql(), "UPDATE users SET role = ?, disabled = ? WHERE id = ?");
    write.bind(1, user.role);
    write.bind(2, user.disabled ? 1 : 0);
    write.bind(3, id);
    write.exec();
    transaction.commit();
    return user;
}

std::vector<std::string> UserStore::namesDifferingOnlyInCase()
{
    std::lock_guard lock(mDb.mutex());
    SQLite::Statement q(mDb.sql(),
                        "SELECT group_concat(username, ', ') FROM (SELECT username FROM users ORDER BY id)"
                        " GROUP BY lower(username) HAVING COUNT(*) > 1");
    std::vector<std::string> groups;
    while (q.executeStep()) groups.push_back(q.getColumn(0).getString());
    return groups;
}

} // namespace tlmhub::server
